// Included by `geomech check` after geomech/student.hpp (which may come precompiled), with
// GEOMECH_STUDENT_ONLY set to the scalar of this compile: 0 double, 1 mp50, 2 exact. Not for
// students' own builds, which register all three scalars.
#undef GEOMECH_STUDENT_SCALARS
#define GEOMECH_STUDENT_SCALARS GEOMECH_STUDENT_ONLY
