// Control for tests/unity/hygiene.py: a macro left defined for the next file of a unity batch
// (must be reported). Not compiled.
namespace gm {
namespace controls_leaky_macro {

#define GM_CONTROL_TOLERANCE 64
int tolerance() { return GM_CONTROL_TOLERANCE; }

}  // namespace controls_leaky_macro
}  // namespace gm
