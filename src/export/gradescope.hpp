#pragma once
/// @file
/// A Gradescope autograder (a zip for "Configure Autograder", Ubuntu or Debian base image):
///   setup.sh        installs wobble from its Debian package, carried in the zip
///   run_autograder  grades /autograder/submission/*.txt with `wobble check --answers` and writes
///                   /autograder/results/results.json (AUTOGRADER_ROOT relocates /autograder
///                   and WOBBLE names the program, for a test on a machine that is no Gradescope)
///   ID.toml         the problem, as wobble read it
/// and the results of a submission as Gradescope's results.json: one test per answer (1 point),
/// wobble's verdict and feedback as its output.
#include <filesystem>
#include <string>
#include <vector>

#include "check/submission.hpp"
#include "export/output_file.hpp"
#include "problem/problem.hpp"

namespace wobble::exports {

/// The autograder's files; `deb` is the wobble package to carry, `check_options` what
/// run_autograder passes to `wobble check` besides the answers ("--tolerance 0.02", or "").
/// @throws InputError if `deb` is not a readable Debian package.
std::vector<OutputFile> gradescope_autograder(const Problem& problem,
                                              const std::filesystem::path& deb,
                                              const std::string& check_options);

/// Gradescope's results.json for a judged submission.
std::string gradescope_results(const check::SubmissionResult& result);

}  // namespace wobble::exports
