// The systems a golden trajectory can be made for: their names, parameters, initial data and
// state layout, and the validation of a given instance (exact, in Rational). Shared by the
// fixture reader (what a file says about its system must make sense), the generator and the
// command line (`geomech golden trajectory`).
#pragma once

#include "golden/fixture.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace gm::golden {

enum class SystemId { FreeRigidBody, RigidBodyAttitude, Clebsch, Manakov, Nambu316 };

struct BlockInfo {
  std::string name;
  std::string meaning;
};

struct SystemInfo {
  SystemId id;
  std::string name;       // as written in files and on the command line
  std::string title;      // a default one-line description
  std::string equations;  // the equations line of a fixture
  std::vector<BlockInfo> parameters;
  std::vector<BlockInfo> initial;
  std::vector<std::string> slots;  // the subject slots the regression integrates
};

const std::vector<SystemInfo>& systems();
const SystemInfo* find_system(std::string_view name);
std::string system_names();  // "free_rigid_body, rigid_body_attitude, ..."

// A validated instance of a system: exact parameters, state layout and exact initial state.
struct Problem {
  const SystemInfo* info = nullptr;
  int n = 3;                            // Manakov: the matrices are n x n
  std::vector<Rational> p;              // the parameter values (I, or a), flattened
  std::vector<std::string> columns;     // state column names
  std::vector<Rational> x0;             // the initial state, in column order
  std::vector<NamedValues> parameters;  // in the system's order, as written to a file
  std::vector<NamedValues> initial;
  int dim() const { return static_cast<int>(x0.size()); }
};

// Largest magnitude of a parameter or an initial value, and smallest nonzero parameter magnitude.
inline constexpr double kMaxInputMagnitude = 1e6;
inline constexpr double kMinParameterMagnitude = 1e-6;

// Validates names, sizes and values and builds the problem. `where`/`line` locate the system
// name (a file line or an argument); each block carries its own place. With `fill_defaults`, an
// omitted attitude O is the identity (the command line); a file must list every block.
// Throws InputError.
Problem make_problem(std::string_view system, const std::string& where, int line, std::vector<NamedValues> parameters,
                     std::vector<NamedValues> initial, bool fill_defaults);

// For a rigid body whose moments violate the triangle inequality (not a physical body, but a
// well-posed system; the notes use such bodies): a note saying so; empty otherwise.
std::string nonphysical_inertia(const Problem& pr);

// The problem a fixture describes, checked against its columns (InputError on mismatch).
Problem validate_fixture(const Fixture& f);

}  // namespace gm::golden
