// Control for tests/unity/hygiene.py: a function outside namespace gm, shared with every file of
// a unity batch (must be reported). Not compiled.
static int twice(int x) { return 2 * x; }

namespace gm {
namespace controls_code_outside {

int four() { return twice(2); }

}  // namespace controls_code_outside
}  // namespace gm
