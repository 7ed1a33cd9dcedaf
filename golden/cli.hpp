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

#include "golden/fixture.hpp"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace gm::golden {

void add_commands(CLI::App& app);

// Parsing of the command line's values (also used by the tests).
// "NAME=v1,v2,..." (commas or spaces between exact numbers) -> a block whose `where` is the
// argument as typed, e.g. "--param I=2,1,2/3".
NamedValues parse_block_argument(const std::string& option, const std::string& text);
// "t1,t2,..." or "start:step:stop" (stop included) -> exact times.
std::vector<Rational> parse_times_argument(const std::string& text);

}  // namespace gm::golden
