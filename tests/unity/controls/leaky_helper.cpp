// Control for tests/unity/hygiene.py: helpers straight in gm's anonymous namespace, visible to the
// next file of a unity batch (must be reported). Not compiled.
namespace gm {
namespace {

int twice(int x) { return 2 * x; }

}  // namespace
}  // namespace gm
