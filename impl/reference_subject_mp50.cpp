// The reference subject instantiated for Real50 (one scalar per translation unit).
#include "impl/reference_subject_impl.hpp"

namespace gm {
template Subject<Real50> make_reference_subject<Real50>();
}  // namespace gm
