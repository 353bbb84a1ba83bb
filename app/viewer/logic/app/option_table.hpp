// convexloc-viewer (internal) — the viewer's options as a table, one row an option: what
// options.cpp declares on CLI11 and the lecture files' keys are checked against.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "logic/app/options.hpp"

namespace convexloc::viewer {

using Values = std::vector<std::string>;

// One option: CLI11's names, the value's name in --help (empty for a flag) and how many
// values it takes, its --help group and line, what it needs (the error says "--NAME needs
// ..."), whether it sets the window or the run (then no lecture slide may set it), and how
// its values go into Options: false for values it does not take, with `why` set where the
// problem is not what it needs.
struct OptionSpec {
  const char* names;
  const char* value;
  int count;
  const char* group;
  const char* help;
  const char* needs;
  bool run;
  bool (*apply)(const Values& v, Options& o, std::string& why);
};

// every option, in --help's order
std::span<const OptionSpec> optionTable();

// every argument into `o`, in order (an option given again overrides); the first problem, or
// an empty string. --figure parses its own options into the same `o` with it.
std::string parseInto(std::span<const std::string_view> args, Options& o);

}  // namespace convexloc::viewer
