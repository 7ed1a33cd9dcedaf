#include "impl/reference_subject.hpp"

#include <memory>

namespace gm {

template <class T>
void add_reference_integrators(Subject<T>&) {}
template void add_reference_integrators<double>(Subject<double>&);
template void add_reference_integrators<Real50>(Subject<Real50>&);

const SubjectSet& reference_subject() {
  static const SubjectSet set = [] {
    SubjectSet s;
    s.name = "reference";
    s.description = "the bundled reference implementation (impl/), written to read like the notes";
    s.d = std::make_shared<const Subject<double>>(make_reference_subject<double>());
    s.mp = std::make_shared<const Subject<Real50>>(make_reference_subject<Real50>());
    s.q = std::make_shared<const Subject<Rational>>(make_reference_subject<Rational>());
    return s;
  }();
  return set;
}

}  // namespace gm
