// Generating a golden trajectory: integrate at 70 digits with the Taylor oracle, reproduce it
// with independent methods, measure the disagreement and the condition, and write the fixture.
//
//   generator  Taylor series (oracle/taylor.hpp) on oracle/fields.hpp, Real70, tolerance 1e-62
//   check      Gragg-Bulirsch-Stoer extrapolation (golden/extrapolation.hpp) on the fields as
//              written in golden/fields_geometric.hpp, Real70, 14 columns, tolerance 1e-60
//   check      closed form, for a free rigid body with two equal moments (symmetric top)
//   check      the exact elliptic solution for the free rigid body (golden/elliptic_check.cpp)
//
// A fixture is written only if every check agrees with the generator to within
// min(1e-40, 10^-(digits+2) max(1, |x|_max)): the printed digits are then all verified.
#pragma once

#include "golden/arguments.hpp"
#include "golden/fixture.hpp"
#include "golden/systems.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace gm::golden {

inline constexpr int kWorkingDigits = 70;  // Real70
inline constexpr int kDefaultDigits = 50;

struct Request {
  std::string name;   // identifier (also the file name of a fixture)
  std::string title;  // one line; empty: the system's own title
  Problem problem;
  std::vector<Rational> times;  // finite decimals, 0 <= t_0 < t_1 < ... <= kMaxRequestTime
  int digits = kDefaultDigits;
  // Prove the printed digits with a validated enclosure in ball arithmetic
  // (golden/certify.hpp) and write each row's certified radius; refused (VerificationError,
  // naming the first time) where fewer than `certified_digits` digits can be proved.
  bool certify = false;
  int certified_digits = 45;
};

struct MethodTiming {
  std::string method;
  double seconds = 0;
};

struct GenerationReport {
  std::vector<MethodTiming> timings;  // generator, checks, condition
  double seconds = 0;                 // total
  std::string max_abs_diff;           // largest disagreement of any check, 2 digits
  std::string allowed;                // what it had to be below
};

// The independent methods disagree by more than the fixture's digits allow.
class VerificationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Generates, verifies and formats the fixture (InputError for a bad request, VerificationError
// when the checks disagree).
Fixture generate(const Request& request, GenerationReport* report = nullptr);

// validate_times, kMaxRequestTime: golden/arguments.hpp

}  // namespace gm::golden
