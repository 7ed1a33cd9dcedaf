// regress<double>: one scalar per translation unit.
#include "golden/regression_impl.hpp"

namespace gm::golden {
template RegressionResult regress<double>(const Fixture&, const Problem&, const Subject<double>&);
}  // namespace gm::golden
