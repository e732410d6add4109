#include <string>
#include <utility>

#include "cli/commands.hpp"
#include "core/input_error.hpp"

namespace wobble::cli {

namespace {
// The command as typed so far ("wobble export moodle"), for the help to point at.
std::string command_path(const CLI::App& app) {
  std::string path = app.get_name();
  for (const CLI::App* sub = &app; !sub->get_subcommands().empty();) {
    sub = sub->get_subcommands().front();
    path += " " + sub->get_name();
  }
  return path;
}

// The first option given the empty value, with the command it belongs to ("wobble export
// moodle"); nullptr for none.
std::pair<const CLI::Option*, std::string> option_with_empty_value(const CLI::App& app,
                                                                   const std::string& path) {
  for (const CLI::Option* option : app.get_options()) {
    // A positional's empty value reaches its command, which names what it wanted ("unknown
    // problem ''"); a flag takes no value.
    if (!option->nonpositional() || option->get_type_size_max() == 0 || option->count() == 0)
      continue;
    for (const std::string& value : option->results())
      if (value.empty()) return {option, path};
  }
  for (const CLI::App* sub : app.get_subcommands()) {
    auto found = option_with_empty_value(*sub, path + " " + sub->get_name());
    if (found.first) return found;
  }
  return {nullptr, ""};
}
}  // namespace

void refuse_empty_values(const CLI::App& app) {
  const auto [option, path] = option_with_empty_value(app, app.get_name());
  if (option)
    throw InputError(option->get_name() + ": the value '' is empty; give one (see " + path +
                     " --help)");
}

std::string missing_value_message(const std::string& what, const CLI::App& app) {
  // CLI11 says "--part: 1 required TEXT missing" for "--part" last on the line or "--part=".
  const auto colon = what.find(": 1 required ");
  const bool missing = what.size() > 8 && what.compare(what.size() - 8, 8, " missing") == 0;
  if (colon == std::string::npos || !missing || what.rfind("-", 0) != 0) return "";
  return what.substr(0, colon) + ": no value given; give one (see " + command_path(app) +
         " --help)";
}

}  // namespace wobble::cli
