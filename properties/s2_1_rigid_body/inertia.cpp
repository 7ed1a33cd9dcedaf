// The moment of inertia of a body of point masses (2.3): the bilinear form
// (a, b) = sum_k m_k (a x X_k) . (b x X_k) equals I a . b with I = sum_k m_k (|X_k|^2 Id - X_k X_k^T);
// I is symmetric, positive semidefinite, and positive definite exactly when the masses do not all
// lie on one line through the origin (the fixed point); its principal moments satisfy the
// triangle inequalities I_i <= I_j + I_k, with equality exactly for a planar body (perpendicular
// axis theorem).
//
// The notes state "positive definite" for a continuous body with a density; for point masses that
// holds only for non-collinear masses, so the property states both cases.
//
// Definiteness is decided without eigenvalues (which need square roots): by principal minors
// (Sylvester), exact in Rational. The triangle inequalities for the eigenvalues lambda of I are
// tr(I)/2 - lambda_k = (lambda_i + lambda_j - lambda_k)/2 >= 0, i.e. K = tr(I)/2 Id - I is positive
// semidefinite (K = sum m X X^T, the second moment of the masses); strict iff det K > 0.
#include "properties/registry.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

#include <array>

namespace gm {
namespace properties_inertia {
namespace {

enum class BodyShape { generic, planar, collinear };

template <class T>
struct Body {
  VecX<T> m;  // masses
  MatX<T> X;  // 3 x N positions
  BodyShape shape = BodyShape::generic;
};

// 1 to 4 masses 1..4; positions on the grid 1/2: generic bodies in [-2, 2]^3, bodies in a random
// plane through the origin (X_k = s_k u + t_k v) and on a random line through the origin
// (X_k = s_k u), s, t integers in [-2, 2], u, v in [-1, 1]^3 (so |X|_inf <= 4). The coarse grid
// keeps every entry of I (and of tr(I)/2 - I) a multiple of 1/4 (1/8), so a minor that is positive
// in exact arithmetic is at least 8^-3 = 1/512, while the float tolerance k eps scale stays below
// 1e-4 in double (entries <= 2 * 16 * 3 * 16 = 1536, a determinant's scale 6 * 1536^3 ~ 2e10, k < 20):
// floats judge strict positivity on the same side as Rational.
template <class T>
rc::Gen<Body<T>> body() {
  return rc::gen::mapcat(rc::gen::pair(rc::gen::inRange(1, 5), rc::gen::inRange(0, 3)), [](std::pair<int, int> nk) {
    const int N = nk.first;
    const auto shape = static_cast<BodyShape>(nk.second);
    return rc::gen::map(
        rc::gen::tuple(rc::gen::container<std::vector<int>>(static_cast<std::size_t>(N), rc::gen::inRange(1, 5)),
                       gen::mat<T>(3, N, 4, 1), gen::vec3<T>(2, 1), gen::vec3<T>(2, 1), gen::mat<T>(2, N, 2, 0)),
        [N, shape](const std::tuple<std::vector<int>, MatX<T>, Vec3<T>, Vec3<T>, MatX<T>>& t) {
          const auto& [ms, Xg, u, v, st] = t;
          Body<T> b;
          b.shape = shape;
          b.m = VecX<T>(N);
          for (int k = 0; k < N; ++k) b.m(k) = T(ms[static_cast<std::size_t>(k)]);
          if (shape == BodyShape::generic) {
            b.X = Xg;
          } else {
            b.X = MatX<T>(3, N);
            for (int k = 0; k < N; ++k)
              b.X.col(k) = st(0, k) * u + (shape == BodyShape::planar ? Vec3<T>(st(1, k) * v) : Vec3<T>::Zero());
          }
          return b;
        });
  });
}

template <class T>
void showValue(const Body<T>& b, std::ostream& os) {
  os << "masses " << show_value(b.m) << ", positions (columns) " << show_value(b.X);
}

// Whether the masses span a line (rank <= 1) or a plane (rank <= 2) through the origin, decided
// exactly in Rational from the (exactly representable) positions.
inline int position_rank(const MatX<Rational>& X) {
  const auto N = X.cols();
  bool any = false;
  for (Eigen::Index k = 0; k < N; ++k) any = any || !X.col(k).isZero();
  if (!any) return 0;
  for (Eigen::Index i = 0; i < N; ++i)
    for (Eigen::Index j = 0; j < N; ++j)
      for (Eigen::Index l = 0; l < N; ++l) {
        const Vec3<Rational> a = X.col(i), b = X.col(j), c = X.col(l);
        if (a.dot(truth::cross(b, c)) != 0) return 3;
      }
  for (Eigen::Index i = 0; i < N; ++i)
    for (Eigen::Index j = 0; j < N; ++j) {
      const Vec3<Rational> a = X.col(i), b = X.col(j);
      if (!truth::cross(a, b).isZero()) return 2;
    }
  return 1;
}

// The seven principal minors of a symmetric 3 x 3 matrix (three 1 x 1, three 2 x 2, the determinant).
template <class T>
std::array<T, 7> principal_minors(const Mat3<T>& A) {
  auto m2 = [&](int i, int j) { return T(A(i, i) * A(j, j) - A(i, j) * A(j, i)); };
  const T det = A(0, 0) * (A(1, 1) * A(2, 2) - A(1, 2) * A(2, 1)) - A(0, 1) * (A(1, 0) * A(2, 2) - A(1, 2) * A(2, 0)) +
                A(0, 2) * (A(1, 0) * A(2, 1) - A(1, 1) * A(2, 0));
  return {A(0, 0), A(1, 1), A(2, 2), m2(0, 1), m2(0, 2), m2(1, 2), det};
}

// Minor sizes for the tolerance: a j x j minor is a sum of j! products of j entries.
template <class T>
std::array<T, 7> minor_scales(const T& a) {
  return {a, a, a, T(2 * a * a), T(2 * a * a), T(2 * a * a), T(6 * a * a * a)};
}

// (2.3): (a, b) = sum m (a x X).(b x X) = I a . b, with the slots' bilinear form and tensor.
// Sizes: each term m |a x X| |b x X| <= m (2 |a| |X|)(2 |b| |X|), summed over N masses.
template <class T>
void inertia_bilinear_form_2_3(const Subject<T>& s) {
  const Body<T> B = *body<T>().as("the body");
  const Vec3<T> a = *gen::vec3<T>(8, 1).as("a");
  const Vec3<T> b = *gen::vec3<T>(8, 1).as("b");
  T expected(0);
  for (Eigen::Index k = 0; k < B.m.size(); ++k) {
    const Vec3<T> Xk = B.X.col(k);
    expected += B.m(k) * truth::cross(a, Xk).dot(truth::cross(b, Xk));
  }
  const T scale = T(12) * T(B.m.sum()) * norm_inf(B.X) * norm_inf(B.X) * norm_inf(a) * norm_inf(b);
  require_close("(2.3): (a, b) = sum m (a x X).(b x X)", s.inertia_bilinear_2_3(B.m, B.X, a, b), expected, scale, 12);
  const Mat3<T> I = s.inertia_tensor_2_3(B.m, B.X);
  require_close("(2.3): (a, b) = I a . b", T((I * a).dot(b)), expected, T(T(3) * scale), 16);
}

// I is symmetric and positive semidefinite; positive definite iff the masses are not all on one
// line through the origin (otherwise det I = 0: the line is an axis of zero moment).
template <class T>
void inertia_positive_definite(const Subject<T>& s) {
  const Body<T> B = *body<T>().as("the body");
  const Mat3<T> I = s.inertia_tensor_2_3(B.m, B.X);
  const T size = T(2) * T(B.m.sum()) * T(3) * norm_inf(B.X) * norm_inf(B.X);  // bounds every entry of I
  require_close("I is symmetric", I, Mat3<T>(I.transpose()), size, 8);
  const int rank = position_rank(convert_matrix<Rational>(B.X));
  const auto minors = principal_minors(I);
  const auto scales = minor_scales(size);
  const int k = 16;  // the entries' own rounding (~8) plus the minor's products and sums
  for (std::size_t i = 0; i < minors.size(); ++i) {
    const T allowed = is_exact_v<T> ? T(0) : T(T(k) * eps<T>() * scales[i]);
    require("principal minor " + std::to_string(i) + " of I is >= 0 (I positive semidefinite)", minors[i] >= -allowed,
            "minor = " + to_string_full(minors[i]));
  }
  const T det = minors[6];
  if (rank >= 2) {
    for (std::size_t i : {0u, 3u, 6u})
      require("leading principal minor " + std::to_string(i) + " > 0: I positive definite (masses not collinear)",
              minors[i] > (is_exact_v<T> ? T(0) : T(T(k) * eps<T>() * scales[i])),
              "minor = " + to_string_full(minors[i]));
  } else {
    require_close("det I = 0 when the masses lie on one line through the origin", det, T(0), scales[6], k);
  }
}

// The principal moments satisfy the triangle inequalities: K = tr(I)/2 Id - I is positive
// semidefinite; strictly (det K > 0) unless the masses lie in one plane through the origin, where
// det K = 0 (a principal moment equals the sum of the other two).
template <class T>
void inertia_triangle_inequalities(const Subject<T>& s) {
  const Body<T> B = *body<T>().as("the body");
  const Mat3<T> I = s.inertia_tensor_2_3(B.m, B.X);
  const Mat3<T> K = (I.trace() / T(2) * Mat3<T>::Identity() - I).eval();
  const T size = T(4) * T(B.m.sum()) * T(3) * norm_inf(B.X) * norm_inf(B.X);
  const int rank = position_rank(convert_matrix<Rational>(B.X));
  const auto minors = principal_minors(K);
  const auto scales = minor_scales(size);
  const int k = 18;
  for (std::size_t i = 0; i < minors.size(); ++i) {
    const T allowed = is_exact_v<T> ? T(0) : T(T(k) * eps<T>() * scales[i]);
    require("principal minor " + std::to_string(i) + " of tr(I)/2 - I is >= 0 (triangle inequalities)",
            minors[i] >= -allowed, "minor = " + to_string_full(minors[i]));
  }
  if (rank == 3)
    require("det(tr(I)/2 - I) > 0: strict triangle inequalities for a body that is not planar",
            minors[6] > (is_exact_v<T> ? T(0) : T(T(k) * eps<T>() * scales[6])), "det = " + to_string_full(minors[6]));
  else
    require_close("det(tr(I)/2 - I) = 0 for a planar body: some I_k = I_i + I_j", minors[6], T(0), scales[6], k);
}

}  // namespace

GM_PROPERTY(inertia_bilinear_form_2_3, all_scalars,
            {.spec = "s2.inertia",
             .title = "(2.3): sum m (a x X).(b x X) = I a . b for bodies of point masses",
             .tolerance = ToleranceClass::Exact,
             .needs = {"inertia_bilinear_2_3", "inertia_tensor_2_3"},
             .negative_controls = {"inertia_bilinear_dot_for_cross", "inertia_tensor_missing_identity"}});

GM_PROPERTY(
    inertia_positive_definite, all_scalars,
    {.spec = "s2.inertia",
     .title = "(2.3): I symmetric, positive semidefinite; definite iff the masses are not on one line through 0",
     .tolerance = ToleranceClass::Exact,
     .needs = {"inertia_tensor_2_3"},
     .negative_controls = {"inertia_tensor_missing_identity"}});

GM_PROPERTY(inertia_triangle_inequalities, all_scalars,
            {.spec = "s2.inertia",
             .title = "(2.3): principal moments satisfy I_i <= I_j + I_k (tr(I)/2 - I >= 0), equality iff planar",
             .tolerance = ToleranceClass::Exact,
             .needs = {"inertia_tensor_2_3"},
             .negative_controls = {"inertia_tensor_missing_identity"}});

}  // namespace properties_inertia
}  // namespace gm
