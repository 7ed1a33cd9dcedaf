// Included by `geomech check` after geomech/student.hpp (which may come precompiled): what this
// compile of the student's file registers (see gm::student::detail::WholeFile), from macros on its
// command line that the precompiled header never tests:
//   GEOMECH_STUDENT_ONLY=k          the scalar: 0 double, 1 mp50, 2 exact
//   GEOMECH_SLOTS_PIECES=n, GEOMECH_SLOTS_PIECE=p
//                                   no slots (n = 0), or piece p of the two (n = 2, slot_piece_of)
//   GEOMECH_SKIP_INTEGRATORS        no integrators
//   GEOMECH_SKIP_SLOTS="a b"        slots left out: they do not compile for this scalar
// Not for students' own builds, which register the whole file in all three scalars.
#pragma once

#include <string_view>

// In an unnamed namespace: each piece's registration templates (register_all<ThisCompile, ...>)
// are its own, not merged by the linker with another piece's of the same name.
namespace gm::student::detail {
namespace {
struct ThisCompile {
  static constexpr int scalar = GEOMECH_STUDENT_ONLY;
#ifdef GEOMECH_SLOTS_PIECES
  static constexpr int slot_piece = GEOMECH_SLOTS_PIECE;
  static constexpr int slot_pieces = GEOMECH_SLOTS_PIECES;
#else
  static constexpr int slot_piece = 0;
  static constexpr int slot_pieces = 1;
#endif
#ifdef GEOMECH_SKIP_INTEGRATORS
  static constexpr bool integrators = false;
#else
  static constexpr bool integrators = true;
#endif
#ifdef GEOMECH_SKIP_SLOTS
  static constexpr std::string_view skip_slots = GEOMECH_SKIP_SLOTS;
#else
  static constexpr std::string_view skip_slots = "";
#endif
};
}  // namespace
}  // namespace gm::student::detail
#undef GEOMECH_STUDENT_SELECTION
#define GEOMECH_STUDENT_SELECTION ::gm::student::detail::ThisCompile
