// Included after the precompiled header by tests/unity/compiles_alone.py: the registrations of
// property and mutant files become empty declarations, so that parsing a file alone instantiates
// no property body for a scalar (the expensive part of a compile) while every name the file
// uses is still looked up where it is written. Not part of any build.
#undef GM_PROPERTY
#define GM_PROPERTY(fn, scalars, ...) static_assert(true)
// tests/mutants/mutants.hpp defines these only if they are not defined yet.
#define GM_MUTANT(name, description, ...) static_assert(true)
#define GM_MUTANT_SET(name, description, ...) static_assert(true)
#define GM_MUTANT_WRONG_ONLY_IN(name, ...) static_assert(true)
