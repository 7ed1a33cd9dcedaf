// libFuzzer target: the values of the command-line arguments that carry numbers (golden
// trajectory's --system/--param/--initial/--times, golden/arguments.hpp, and the validation of
// the problem they describe, golden/systems.hpp). The input is split into lines: the system name,
// then arguments "--param NAME=..." / "--initial NAME=..." / "--times ...". Every rejection must be
// an InputError naming the argument; nothing else may escape.
#include "golden/arguments.hpp"
#include "golden/systems.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::string system;
  std::getline(in, system);
  std::vector<gm::golden::NamedValues> params, initial;
  try {
    for (std::string line; std::getline(in, line);) {
      const auto space = line.find(' ');
      const std::string option = line.substr(0, space),
                        value = space == std::string::npos ? "" : line.substr(space + 1);
      if (option == "--param") {
        params.push_back(gm::golden::parse_block_argument(option, value));
      } else if (option == "--initial") {
        initial.push_back(gm::golden::parse_block_argument(option, value));
      } else if (option == "--times") {
        const auto times = gm::golden::parse_times_argument(value);
        if (times.empty()) std::abort();  // validated: never empty
      }
    }
    const auto problem = gm::golden::make_problem(system, "--system " + system, 0, params, initial, true);
    (void)gm::golden::nonphysical_inertia(problem);
  } catch (const gm::golden::InputError& e) {
    if (e.where().empty()) {
      std::fprintf(stderr, "an argument error that names no argument: %s\n", e.what());
      std::abort();
    }
  }
  return 0;
}
