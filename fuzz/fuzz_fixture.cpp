// libFuzzer target: the golden-fixture reader and the validation of what a fixture says about
// its system. Any input must either parse or raise golden::InputError; nothing else may escape,
// and ASan/UBSan must stay silent.
#include "golden/fixture.hpp"
#include "golden/systems.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto f = gm::golden::parse_fixture(text, "fuzz-input");
    (void)gm::golden::validate_fixture(f);
    // A fixture that parses must survive conversion to every scalar and a round trip.
    (void)f.values_as<double>();
    (void)f.times_as<gm::Rational>();
    const auto again = gm::golden::parse_fixture(gm::golden::write_fixture(f), "fuzz-rewritten");
    if (again.rows != f.rows) {
      std::fprintf(stderr, "write_fixture/parse_fixture round trip changed the rows\n");
      std::abort();
    }
  } catch (const gm::golden::InputError&) {}
  return 0;
}
