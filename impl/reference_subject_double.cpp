// The reference subject instantiated for double (one scalar per translation unit).
#include "impl/reference_subject_impl.hpp"

namespace gm {
template Subject<double> make_reference_subject<double>();
}  // namespace gm
