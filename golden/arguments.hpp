// The values of the golden tool's command-line arguments: exact numbers, blocks and sample
// times, parsed with errors naming the argument as typed (InputError with line 0). Small and
// dependency-free (the fixture format only), so that it is fuzzed on its own (fuzz/).
#pragma once

#include "golden/fixture.hpp"

#include <string>
#include <vector>

namespace gm::golden {

inline constexpr long kMaxRequestTime = 1000;  // the latest sample time a request may ask for

// "NAME=v1,v2,..." (commas or spaces between exact numbers) -> a block whose `where` is the
// argument as typed, e.g. "--param I=2,1,2/3".
NamedValues parse_block_argument(const std::string& option, const std::string& text);

// "t1,t2,..." or "start:step:stop" (stop included) -> exact times, validated.
std::vector<Rational> parse_times_argument(const std::string& text);

// Checks that times are usable for a request: finite decimals, increasing, in [0, 1000].
// `where` names the argument or file for the message.
void validate_times(const std::vector<Rational>& times, const std::string& where);

}  // namespace gm::golden
