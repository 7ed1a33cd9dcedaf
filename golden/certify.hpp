// Certified golden trajectories: a rigorous enclosure of the exact solution of a
// fixture's initial-value problem at every sample time, by a validated Taylor method in ball
// arithmetic (golden/ball.hpp, Arb), and the certificate it gives each printed row: a radius r
// such that every printed value of the row lies within r of the true solution.
//
// The method, for the polynomial fields of oracle/fields.hpp instantiated with Ball constants
// (the exact rational parameters enter as balls that contain them):
//   1. The field is recorded on a tape (oracle/taylor.hpp) and its Taylor coefficients
//      c_0 .. c_N of the solution through the current enclosure X are computed in balls:
//      c_{k+1} = [f(x)]_k / (k + 1), every Cauchy product in ball arithmetic; the polynomial
//      sum_k c_k h^k then encloses the Taylor polynomial of every solution starting in X.
//   2. An a-priori enclosure B of every solution over [0, h] (Picard-Lindelof): a candidate
//      B is accepted when X + [0, h] f(B) lies inside B; then x(t) stays in B for t in [0, h].
//      The candidate starts from X + [0, h] f(X), widened, and is enlarged a few times; failing
//      that the step is halved.
//   3. The Lagrange remainder: x(h) - sum_{k <= N} c_k(x_0) h^k = c_{N+1}(x(xi)) h^{N+1} for some
//      xi in [0, h], and x(xi) lies in B, so the remainder lies in c_{N+1}(B) h^{N+1}, computed by
//      the same recurrence on B. The new enclosure is the polynomial plus that ball.
//   Steps end exactly on the sample times (exact rationals). The step size and the order follow
//   the Jorba-Zou rule of the oracle, with a tolerance far below the printed digits.
// The wrapping effect (the radii grow with the absolute values of the Jacobian, not with the
// true sensitivity) is absorbed by the working precision: the midpoints carry 320 bits (96
// digits) and a fixture needs 45 certified digits, so a growth of the radii by up to about 10^45
// over the trajectory is affordable; the growth is measured and reported, and an enclosure whose
// radius grows past what is asked is refused, saying at which time.
#pragma once

#include "golden/ball.hpp"
#include "golden/fixture.hpp"
#include "golden/systems.hpp"

#include <string>
#include <vector>

namespace gm::golden {

struct EnclosureOptions {
  long precision_bits = 320;  // of the midpoints
  // Local truncation target, relative to max(1, |x|_inf). The remainders, not the rounding, set
  // the final radii (the wrapping effect multiplies them by up to 10^20 over t = 20 for the
  // Clebsch fixture: 1e-66 left 6e-46, 1e-72 left 1.5e-51, 1e-80 leaves < 1e-52; 320 or 400
  // bits give the same radii, measured).
  double tolerance = 1e-80;
  int order = 0;  // 0: from the tolerance, as the oracle
};

// The enclosures of the solution at each sample time.
struct Enclosure {
  std::vector<std::vector<Ball>> values;  // values[i][j]: state column j at times[i]
  long steps = 0;
  int order = 0;
  long precision_bits = 0;
  double largest_radius = 0;  // the widest enclosure at any sample, absolute
  std::string failure;        // empty when every sample time was reached with finite balls
};

// Encloses the solution of `system` from its exact initial state x0 (Rational) at `times`.
Enclosure enclose_problem(const Problem& problem, const std::vector<Rational>& times, const EnclosureOptions& o = {});

// The certificate of printed rows: for each row, an upper bound of the distance between every
// printed value and the exact solution (rounded up to one significant digit, as written), and
// the certified digits: min over rows of -log10(radius / max(1, |row|_inf)).
struct Certificate {
  MethodRecord record;                  // "#: certificate arb ..." line
  std::vector<std::string> row_radius;  // per row, as written ("4e-51")
  double certified_digits = 0;
  Enclosure enclosure;
};

// Certifies rows printed for `times` (each row: the decimal strings of the state columns).
// Throws VerificationError-like std::runtime_error (message naming the time) when the enclosure
// cannot reach a sample time.
Certificate certify_rows(const Problem& problem, const std::vector<Rational>& times,
                         const std::vector<std::vector<std::string>>& rows, const EnclosureOptions& o = {});

// Checks a fixture's certificate against a fresh enclosure: every printed value must lie within
// its row's stated radius of the certified ball. Returns the problems found, each naming the
// fixture, the time, the column and the numbers (empty: certified).
std::vector<std::string> verify_certificate(const Fixture& f, const Enclosure& e);

// The enclosure computed with any field of oracle/fields.hpp instantiated on Ball (a test uses
// it with a wrong field: its certificate must fail).
template <class Field>
Enclosure enclose_field(const Field& field, int dim, const std::vector<Rational>& x0,
                        const std::vector<Rational>& times, const EnclosureOptions& o);

}  // namespace gm::golden

#include "golden/certify_impl.hpp"
