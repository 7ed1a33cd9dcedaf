#include "properties/support/step_precision.hpp"

namespace gm {

StepPrecision& current_step_precision() {
  thread_local StepPrecision precision;
  return precision;
}

std::optional<StepPrecision> stated_precision(std::string_view name, std::string_view reason) {
  StepPrecision p;
  if (name == "float" || name == "single") {
    p.eps = kFloatEps;
    p.name = "float";
  } else if (name == "double") {
    p.eps = kDoubleEps;
    p.name = "double";
  } else {
    return std::nullopt;
  }
  p.how = reason.empty() ? std::string("stated") : "stated: " + std::string(reason);
  return p;
}

}  // namespace gm
