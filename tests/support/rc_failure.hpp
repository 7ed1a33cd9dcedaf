// Outside a RapidCheck property, a failing check throws rc::detail::CaseResult; tests of the
// machinery catch it to read the message.
#pragma once

#include <rapidcheck.h>

#include <string>

namespace gm::testing_support {

// The failure message of f(), or "" when f() passes.
template <class F>
std::string failure_of(F&& f) {
  try {
    f();
  } catch (const rc::detail::CaseResult& r) {
    return r.description.empty() ? "(failed)" : r.description;
  }
  return {};
}

}  // namespace gm::testing_support
