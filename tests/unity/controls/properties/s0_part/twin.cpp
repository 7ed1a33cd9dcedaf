// Control for tests/unity/hygiene.py: a file in a part folder of properties/ keeps the namespace
// properties_<file>; its twin of the same name in another part folder would share it.
namespace gm {
namespace properties_twin {
inline int twin() { return 1; }
}  // namespace properties_twin
}  // namespace gm
