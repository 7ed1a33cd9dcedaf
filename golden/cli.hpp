// The `golden` subcommands of the geomech tool (golden/README.md):
//   geomech golden regenerate [--check] [--only NAME]... [--dir DIR] [--quiet]
//   geomech golden trajectory --system S --param NAME=v,... --initial NAME=v,... --times T
//                             [--digits D] [--name N] [--title TEXT] [--output FILE]
//   geomech golden validate FILE...
//   geomech golden list
// Each runs from its CLI11 callback; a non-zero exit status leaves through CLI::RuntimeError,
// which the tool's CLI11_PARSE turns into the process exit status without printing anything
// more (every message has been printed by then). Status: 0 success, 1 a check failed, 2 bad
// input (the message names the argument, or the file and line).
#pragma once

#include "golden/arguments.hpp"
#include "golden/fixture.hpp"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace gm::golden {

void add_commands(CLI::App& app);

// The values of its arguments are parsed by golden/arguments.hpp.

}  // namespace gm::golden
