#pragma once
/// @file
/// An answer the problem asks for that does not exist at these values (the heavy top's steady
/// precession, which a top spinning below the least rate has none of): the key leaves it out of
/// its part and a step says why (solvers/key.hpp PartKey::absent). "None" is then the answer,
/// and a student may write it so.
///
/// What says "none": one of "none", "DNE", "n/a", "∅", "nothing", "does not exist", "do not
/// exist", "doesn't exist", "there is none", "there are none", "no solution", "no real root",
/// "no steady precession", "impossible", "undefined" (with "it"/"they" before a verb, any case,
/// a final '.'), alone or followed by a reason after a ',', ';', ':', '(' or a dash ("none: the
/// spin is below 688 rad/s"), "at these values" between them as a key prints it ("none at these
/// values (step 2 says why)"). A bare "no" is not: it answers no question asked here.
#include <optional>
#include <string>

#include "check/judge.hpp"

namespace wobble::check {

/// Whether `typed` says there is no such value, as above.
bool says_none(const std::string& typed);

/// The verdict on `typed` where part `part_id` and answer `name` (either may be empty; a part's
/// id may be an absent answer's name, as a line "phidot_slow = none" gives it; names spelt as
/// name_in_key reads them) point at answers that do not exist at these values: right where it
/// says none ("correct: phidot_slow does not exist at these values"), wrong otherwise
/// ("incorrect: phidot_slow does not exist at these values"), the key's reason after
/// either where `with_reason` (a graded surface withholds it: a slow top's gives ω3, part (c)'s
/// answer). nullopt where they point at no absent answer (the usual lookup then finds the answer
/// or says why not); a part with answers and absent ones, named by its id alone, is not one.
std::optional<Verdict> judge_absent(const Key& key, const std::string& part_id,
                                    const std::string& name, const std::string& typed,
                                    bool with_reason);

}  // namespace wobble::check
