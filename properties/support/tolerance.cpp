#include "properties/support/tolerance.hpp"

#include "properties/support/figures.hpp"

#include <cstdio>

namespace gm {

std::vector<Series>& recorded_series() {
  thread_local std::vector<Series> series;
  return series;
}

std::vector<std::string>& recorded_notes() {
  thread_local std::vector<std::string> notes;
  return notes;
}

ResidualLog& residual_log() {
  thread_local ResidualLog log;
  return log;
}

namespace detail {

std::string describe_failure(std::string_view what, std::string_view kind, const std::string& lhs,
                             const std::string& rhs, const std::string& diff, const std::string& residual,
                             double units, const std::string& allowed) {
  std::ostringstream os;
  os << what << " does not hold (" << kind << " tolerance)\n"
     << "  lhs      = " << lhs << "\n"
     << "  rhs      = " << rhs << "\n"
     << "  lhs-rhs  = " << diff << "\n"
     << "  residual = " << residual;
  if (kind != "exact") {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", units);
    os << " (" << buf << " eps * scale)";
  }
  os << "\n  allowed  = " << allowed;
  return os.str();
}

GM_REQUIRE_CLOSE_FOR(, double)
GM_REQUIRE_CLOSE_FOR(, Real50)
GM_REQUIRE_CLOSE_FOR(, Rational)

}  // namespace detail
}  // namespace gm
