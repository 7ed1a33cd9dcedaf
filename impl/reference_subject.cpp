#include "impl/reference_subject.hpp"

#include <memory>

namespace gm {

const SubjectSet& reference_subject() {
  static const SubjectSet set = [] {
    SubjectSet s;
    s.name = "reference";
    s.description = "the bundled reference implementation (impl/), written to read like the notes";
    s.d = std::make_shared<const Subject<double>>(make_reference_subject<double>());
    s.mp = std::make_shared<const Subject<Real50>>(make_reference_subject<Real50>());
    s.q = std::make_shared<const Subject<Rational>>(make_reference_subject<Rational>());
    s.claims = reference_integrator_claims();
    return s;
  }();
  return set;
}

}  // namespace gm
