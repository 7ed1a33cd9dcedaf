#include "properties/support/step_guard.hpp"

namespace gm {

std::optional<StepRaise>& current_step_raise() {
  thread_local std::optional<StepRaise> raise;
  return raise;
}

bool& discard_step_raises() {
  thread_local bool discard = false;
  return discard;
}

StepDomain& current_step_domain() {
  thread_local StepDomain domain;
  return domain;
}

}  // namespace gm
