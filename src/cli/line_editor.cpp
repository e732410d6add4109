#include "cli/line_editor.hpp"

#include <editline/readline.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>

namespace wobble::cli {

check::ReadLine terminal_lines() {
  return [](const std::string& prompt, std::string& line) {
    // libedit writes the prompt through C stdio: what the worksheet printed must come first.
    std::cout << std::flush;
    std::fflush(stdout);
    const std::unique_ptr<char, decltype(&std::free)> text(readline(prompt.c_str()), &std::free);
    if (!text) return false;
    line = text.get();
    if (!line.empty()) add_history(text.get());
    return true;
  };
}

}  // namespace wobble::cli
