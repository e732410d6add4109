#pragma once
/// @file
/// The page as one self-contained HTML file (`wobble page`): the same page the server sends,
/// with every asset it links inlined (scripts and styles as text, KaTeX's fonts as data: URLs)
/// and the problem's data in a script, so that it opens from disk, an LMS page or a lecture
/// slide with no server and no network. The page then shows the statement, the values, the 3-D
/// view and the questions; the answers only if the key is given.
#include <string>

namespace wobble::web {

/// `view_json` from student_view_json; `motion_json` from problem_motion_json, or empty for a
/// problem without motion; `key_json` the JSON key (render_json), or empty for none.
std::string self_contained_page(const std::string& view_json, const std::string& motion_json,
                                const std::string& key_json);

}  // namespace wobble::web
