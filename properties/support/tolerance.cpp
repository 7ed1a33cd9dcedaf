#include "properties/support/tolerance.hpp"

#include <algorithm>

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

SideNames& side_names() {
  static SideNames names;
  return names;
}

std::string describe_failure(std::string_view what, std::string_view kind, const std::string& lhs,
                             const std::string& rhs, const std::string& diff, const std::string& residual, double units,
                             const std::string& allowed) {
  const SideNames& sides = side_names();
  const bool named = sides.lhs != "lhs";
  const std::string diff_name = named ? "difference" : "lhs-rhs";
  const std::size_t width = std::max({sides.lhs.size(), sides.rhs.size(), diff_name.size(), std::size_t(8)});
  auto label = [&](const std::string& l) { return "  " + l + std::string(width - l.size() + 1, ' ') + "= "; };
  std::ostringstream os;
  os << what << " does not hold (" << kind << " tolerance)\n"
     << label(sides.lhs) << lhs << "\n"
     << label(sides.rhs) << rhs << "\n"
     << label(diff_name) << diff << "\n"
     << label("residual") << residual;
  if (kind != "exact") {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", units);
    os << " (" << buf << " eps * scale)";
  }
  os << "\n" << label("allowed") << allowed;
  return os.str();
}

std::string double_precision_hint(const char* scalar, double relative) {
  if (!(relative >= 1e-19 && relative <= 1e-11)) return {};
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2g", relative);
  return std::string("\n  hint: the residual is ") + buf + " of the inputs' size in a " + scalar +
         " run: that is double-precision round-off (about 1e-16), so part of this computation seems to be done in "
         "double (a cast or conversion to double, a double constant such as 0.1, std::sqrt or std::sin called on a "
         "double, or a hard-coded tolerance like 1e-12)";
}

GM_REQUIRE_CLOSE_FOR(, double)
GM_REQUIRE_CLOSE_FOR(, Real50)
GM_REQUIRE_CLOSE_FOR(, Rational)

}  // namespace detail
}  // namespace gm
