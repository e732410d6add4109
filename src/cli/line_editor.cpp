#include "cli/line_editor.hpp"

#include <editline/readline.h>

#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>

namespace wobble::cli {

check::ReadLine terminal_lines() {
  // libedit reads multibyte characters (°, ·, ², Greek) only in a multibyte locale; without
  // this it drops them silently. Only the character type: numbers keep the C locale.
  static const bool locale_set = std::setlocale(LC_CTYPE, "") != nullptr;
  (void)locale_set;
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
