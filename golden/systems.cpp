#include "golden/systems.hpp"

#include <algorithm>

namespace gm::golden {

const std::vector<SystemInfo>& systems() {
  static const std::vector<SystemInfo> list = {
      {SystemId::FreeRigidBody,
       "free_rigid_body",
       "the free rigid body",
       "dPi/dt = Pi x Omega, Omega = I^-1 Pi, I = diag(I1, I2, I3)  (3.7), (3.8)",
       {{"I", "principal moments of inertia I1 I2 I3 (positive, each at most the sum of the others)"}},
       {{"Pi", "body angular momentum Pi1 Pi2 Pi3"}},
       {"euler_3_8"}},
      {SystemId::RigidBodyAttitude,
       "rigid_body_attitude",
       "the free rigid body with its attitude",
       "dPi/dt = Pi x Omega, dO/dt = O hat(Omega), Omega = I^-1 Pi  (2.20), (2.10), (3.8)",
       {{"I", "principal moments of inertia I1 I2 I3"}},
       {{"Pi", "body angular momentum"}, {"O", "attitude in SO(3), row-major O11 O12 ... O33 (default: identity)"}},
       {"euler_3_8", "omega_3_5", "reconstruction_2_10"}},
      {SystemId::Clebsch,
       "clebsch",
       "the Clebsch form of the rigid body",
       "dQ/dt = -Omega x Q, dP/dt = -Omega x P, Omega = I^-1 Pi, Pi = P x Q  (3.21)",
       {{"I", "principal moments of inertia I1 I2 I3"}},
       {{"Q", "Clebsch variable Q"}, {"P", "Clebsch variable P"}},
       {"clebsch_3_21"}},
      {SystemId::Manakov,
       "manakov",
       "Manakov's rigid body on SO(n) with its attitude",
       "dM/dt = [M, Omega], dO/dt = O Omega, M = A Omega + Omega A, A = diag(a)  (2.34), sec. 2.4",
       {{"a", "diagonal of A: n positive numbers, 2 <= n <= 9"}},
       {{"M", "body momentum in so(n), n x n row-major, skew"},
        {"O", "attitude in SO(n), n x n row-major (default: identity)"}},
       {"manakov_2_34", "manakov_Omega"}},
      {SystemId::Nambu316,
       "nambu_3_16",
       "the system (3.16)",
       "dx1/dt = -a1 a3 x2 x3, dx2/dt = -a2 a3 x3 x1, dx3/dt = a1 a2 x1 x2  (3.16)",
       {{"a", "nonzero constants a1 a2 a3 (a rigid body when 1/a1 + 1/a2 = 1/a3)"}},
       {{"x", "x1 x2 x3"}},
       {"nambu_3_16"}},
  };
  return list;
}

const SystemInfo* find_system(std::string_view name) {
  for (const auto& s : systems())
    if (s.name == name) return &s;
  return nullptr;
}

std::string system_names() {
  std::string out;
  for (const auto& s : systems()) out += (out.empty() ? "" : ", ") + s.name;
  return out;
}

namespace {

InputError error_at(const NamedValues& nv, const std::string& message) {
  return InputError(nv.where, nv.line, message);
}

Rational abs_q(const Rational& x) { return x < 0 ? Rational(-x) : x; }

std::string block_list(const std::vector<BlockInfo>& b) {
  std::string s;
  for (const auto& x : b) s += (s.empty() ? "" : ", ") + x.name;
  return s;
}

// Sorts the given blocks into the order of `spec`, rejecting unknown and duplicate names;
// a missing block is returned with an empty name.
std::vector<NamedValues> arrange(const SystemInfo& sys, const char* kind, const std::vector<BlockInfo>& spec,
                                 std::vector<NamedValues> given) {
  std::vector<NamedValues> out(spec.size());
  for (auto& g : given) {
    auto it = std::find_if(spec.begin(), spec.end(), [&](const BlockInfo& b) { return b.name == g.name; });
    if (it == spec.end())
      throw error_at(g, std::string("unknown ") + kind + " '" + g.name + "' for system " + sys.name + " (its " + kind +
                            "s: " + block_list(spec) + ")");
    auto& slot = out[static_cast<std::size_t>(it - spec.begin())];
    if (!slot.name.empty()) throw error_at(g, std::string(kind) + " '" + g.name + "' is given twice");
    slot = std::move(g);
  }
  return out;
}

void require_size(const NamedValues& nv, std::size_t n, const std::string& what) {
  if (nv.values.size() != n)
    throw error_at(nv, nv.name + " has " + std::to_string(nv.values.size()) + " value" +
                           (nv.values.size() == 1 ? "" : "s") + ", expected " + std::to_string(n) + " (" + what + ")");
}

void require_magnitudes(const NamedValues& nv) {
  const Rational limit(static_cast<long long>(kMaxInputMagnitude));
  for (std::size_t i = 0; i < nv.values.size(); ++i)
    if (abs_q(nv.values[i]) > limit)
      throw error_at(nv, nv.name + ", value " + std::to_string(i + 1) + ": absurd magnitude " +
                             format_exact(nv.values[i]) + " (|value| > 1e6)");
}

void require_parameter_range(const NamedValues& nv, bool positive) {
  const Rational lo = Rational(1) / Rational(static_cast<long long>(1 / kMinParameterMagnitude + 0.5));
  for (std::size_t i = 0; i < nv.values.size(); ++i) {
    const Rational& v = nv.values[i];
    const std::string which = nv.name + std::to_string(i + 1);
    if (positive && v <= 0) throw error_at(nv, "degenerate: " + which + " = " + format_exact(v) + " must be positive");
    if (!positive && v == 0) throw error_at(nv, "degenerate: " + which + " = 0 must be nonzero");
    if (abs_q(v) < lo) throw error_at(nv, which + " = " + format_exact(v) + ": absurd magnitude (below 1e-6)");
  }
  require_magnitudes(nv);
}

// Positive moments (zero or negative ones are degenerate: Omega = I^-1 Pi is undefined or the
// energy indefinite). The triangle inequality is not required: the notes' own examples violate
// it (I = diag(1, 1/2, 1/3) in section 3.4; the benchmark body (2, 1, 2/3)), and Euler's
// equations are well posed for any positive I; see nonphysical_inertia().
void require_inertia(const NamedValues& nv) {
  require_size(nv, 3, "I1 I2 I3");
  require_parameter_range(nv, true);
}

// The determinant of an n x n matrix (row-major) by elimination in Rational.
Rational determinant(std::vector<Rational> a, int n) {
  Rational det(1);
  for (int c = 0; c < n; ++c) {
    int piv = -1;
    for (int r = c; r < n; ++r)
      if (a[r * n + c] != 0) {
        piv = r;
        break;
      }
    if (piv < 0) return Rational(0);
    if (piv != c) {
      for (int k = 0; k < n; ++k) std::swap(a[c * n + k], a[piv * n + k]);
      det = -det;
    }
    det *= a[c * n + c];
    for (int r = c + 1; r < n; ++r) {
      const Rational f = a[r * n + c] / a[c * n + c];
      if (f == 0) continue;
      for (int k = c; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
    }
  }
  return det;
}

// O in SO(n): |O^T O - Id|_max <= 1e-40 (exact rotations, or rotations written with >= 45
// digits) and det O > 0.
void require_rotation(const NamedValues& nv, int n) {
  const auto& O = nv.values;
  const Rational tol = pow10(-40);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) {
      Rational s(0);
      for (int k = 0; k < n; ++k) s += O[k * n + i] * O[k * n + j];
      if (i == j) s -= 1;
      if (abs_q(s) > tol)
        throw error_at(nv, "O is not a rotation: (O^T O - Id)_" + std::to_string(i + 1) + std::to_string(j + 1) +
                               " = " + format_significant(s, 3) + " (allowed: |.| <= 1e-40)");
    }
  if (determinant(O, n) <= 0) throw error_at(nv, "O is not a rotation: det O < 0 (a reflection)");
}

NamedValues identity_block(const std::string& name, int n, const std::string& where) {
  NamedValues nv;
  nv.name = name;
  nv.where = where;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) nv.values.push_back(Rational(i == j ? 1 : 0));
  return nv;
}

std::vector<std::string> matrix_columns(const std::string& m, int n) {
  std::vector<std::string> c;
  for (int i = 1; i <= n; ++i)
    for (int j = 1; j <= n; ++j) c.push_back(m + std::to_string(i) + std::to_string(j));
  return c;
}

}  // namespace

Problem make_problem(std::string_view system, const std::string& where, int line, std::vector<NamedValues> parameters,
                     std::vector<NamedValues> initial, bool fill_defaults) {
  const SystemInfo* sys = find_system(system);
  if (!sys)
    throw InputError(where, line, "unknown system '" + std::string(system) + "' (known: " + system_names() + ")");
  Problem pr;
  pr.info = sys;
  auto params = arrange(*sys, "parameter", sys->parameters, std::move(parameters));
  auto init = arrange(*sys, "initial block", sys->initial, std::move(initial));
  for (std::size_t i = 0; i < params.size(); ++i)
    if (params[i].name.empty())
      throw InputError(where, line,
                       "system " + sys->name + ": missing parameter '" + sys->parameters[i].name + "' (" +
                           sys->parameters[i].meaning + ")");
  const NamedValues& p = params[0];
  switch (sys->id) {
    case SystemId::FreeRigidBody:
    case SystemId::RigidBodyAttitude:
    case SystemId::Clebsch:
      require_inertia(p);
      pr.n = 3;
      break;
    case SystemId::Manakov:
      if (p.values.size() < 2 || p.values.size() > 9)
        throw error_at(p, "a has " + std::to_string(p.values.size()) + " values; Manakov's SO(n) needs 2 <= n <= 9");
      require_parameter_range(p, true);
      pr.n = static_cast<int>(p.values.size());
      break;
    case SystemId::Nambu316:
      require_size(p, 3, "a1 a2 a3");
      require_parameter_range(p, false);
      pr.n = 3;
      break;
  }
  pr.p = p.values;
  const int n = pr.n;
  for (std::size_t i = 0; i < init.size(); ++i) {
    if (!init[i].name.empty()) continue;
    const bool attitude = sys->initial[i].name == "O";
    if (attitude && fill_defaults) {
      init[i] = identity_block("O", n, where);
      continue;
    }
    throw InputError(where, line,
                     "system " + sys->name + ": missing initial block '" + sys->initial[i].name + "' (" +
                         sys->initial[i].meaning + ")");
  }
  for (auto& b : init) require_magnitudes(b);
  auto zero = [](const std::vector<Rational>& v) {
    return std::all_of(v.begin(), v.end(), [](const Rational& x) { return x == 0; });
  };
  switch (sys->id) {
    case SystemId::FreeRigidBody:
      require_size(init[0], 3, "Pi1 Pi2 Pi3");
      if (zero(init[0].values))
        throw error_at(init[0], "zero angular momentum Pi = 0: the body is at rest, nothing moves");
      pr.columns = {"Pi1", "Pi2", "Pi3"};
      break;
    case SystemId::RigidBodyAttitude:
      require_size(init[0], 3, "Pi1 Pi2 Pi3");
      require_size(init[1], 9, "O11 ... O33, row-major");
      if (zero(init[0].values))
        throw error_at(init[0], "zero angular momentum Pi = 0: the body is at rest, nothing moves");
      require_rotation(init[1], 3);
      pr.columns = {"Pi1", "Pi2", "Pi3"};
      for (auto& c : matrix_columns("O", 3)) pr.columns.push_back(c);
      break;
    case SystemId::Clebsch: {
      require_size(init[0], 3, "Q1 Q2 Q3");
      require_size(init[1], 3, "P1 P2 P3");
      const auto& Q = init[0].values;
      const auto& P = init[1].values;
      const std::vector<Rational> Pi = {P[1] * Q[2] - P[2] * Q[1], P[2] * Q[0] - P[0] * Q[2],
                                        P[0] * Q[1] - P[1] * Q[0]};
      if (zero(Pi)) throw error_at(init[1], "zero angular momentum Pi = P x Q = 0: Omega = 0 and nothing moves");
      pr.columns = {"Q1", "Q2", "Q3", "P1", "P2", "P3"};
      break;
    }
    case SystemId::Manakov: {
      require_size(init[0], static_cast<std::size_t>(n * n), "n x n row-major, n = size of a");
      require_size(init[1], static_cast<std::size_t>(n * n), "n x n row-major, n = size of a");
      const auto& M = init[0].values;
      for (int i = 0; i < n; ++i)
        for (int j = i; j < n; ++j)
          if (M[i * n + j] != -M[j * n + i])
            throw error_at(init[0], "M is not skew: M" + std::to_string(i + 1) + std::to_string(j + 1) + " = " +
                                        format_exact(M[i * n + j]) + " but M" + std::to_string(j + 1) +
                                        std::to_string(i + 1) + " = " + format_exact(M[j * n + i]) +
                                        " (M must be in so(n) exactly)");
      if (zero(M)) throw error_at(init[0], "zero angular momentum M = 0: the body is at rest, nothing moves");
      require_rotation(init[1], n);
      pr.columns = matrix_columns("M", n);
      for (auto& c : matrix_columns("O", n)) pr.columns.push_back(c);
      break;
    }
    case SystemId::Nambu316:
      require_size(init[0], 3, "x1 x2 x3");
      if (zero(init[0].values)) throw error_at(init[0], "x = 0 is an equilibrium: nothing moves");
      pr.columns = {"x1", "x2", "x3"};
      break;
  }
  for (const auto& b : init)
    for (const auto& v : b.values) pr.x0.push_back(v);
  pr.parameters = std::move(params);
  pr.initial = std::move(init);
  return pr;
}

std::string nonphysical_inertia(const Problem& pr) {
  if (pr.info->id != SystemId::FreeRigidBody && pr.info->id != SystemId::RigidBodyAttitude &&
      pr.info->id != SystemId::Clebsch)
    return {};
  const auto& I = pr.p;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (I[i] > I[j] + I[k])
      return "I" + std::to_string(i + 1) + " = " + format_exact(I[i]) + " > I" + std::to_string(j + 1) + " + I" +
             std::to_string(k + 1) + " = " + format_exact(I[j] + I[k]) +
             ": these moments violate the triangle inequality, so no mass distribution has them (the notes' "
             "examples are of this kind too); Euler's equations are well posed for them all the same";
  }
  return {};
}

Problem validate_fixture(const Fixture& f) {
  Problem pr = make_problem(f.system, f.source, f.system_line, f.parameters, f.initial, false);
  if (pr.columns != f.columns) {
    std::string expected;
    for (const auto& c : pr.columns) expected += " " + c;
    throw InputError(f.source, f.columns_line,
                     "the columns do not match system " + f.system + ": expected t" + expected);
  }
  return pr;
}

}  // namespace gm::golden
