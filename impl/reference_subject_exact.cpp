// The reference subject instantiated for Rational (one scalar per translation unit).
#include "impl/reference_subject_impl.hpp"

namespace gm {
template Subject<Rational> make_reference_subject<Rational>();
}  // namespace gm
