// Control for tests/unity/hygiene.py: a file as a unity batch needs it (must pass). Not compiled.
#include <string>

namespace gm {
namespace controls_clean {
namespace {

#define GM_CONTROL_TWICE(x) ((x) + (x))
int twice(int x) { return GM_CONTROL_TWICE(x); }
#undef GM_CONTROL_TWICE

}  // namespace
}  // namespace controls_clean
}  // namespace gm
