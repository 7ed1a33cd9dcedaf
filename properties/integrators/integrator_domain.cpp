// Where an integrator's step works. An integrator of (3.8) and (2.10) (or of Manakov's
// (2.36)) must return a finite state for every state and step in its domain: the whole space when
// it declares none, or the declared one (largest |Omega| or state, smallest h; StepDomain in
// core/subject.hpp). The step is probed at a generic state scaled by 2^j (j = -64..64, the time
// with it: the same motion in other units), with steps h = 2^-k / |Omega| down to 2^-50 (2^-120
// in 50 digits) and one of h |Omega| = 1, everywhere inside the domain; the finding says what was
// probed, never "everywhere".
//
// This is the one finding for a step that raises (support/step_guard.hpp): "your step raises on
// every call: ...", "raises for |Omega| >= 2.6e6: ...", "raises for h <= ...", with the advice to
// declare a domain when it raises only beyond some size; the other checks of the integrator then
// say only that they could not run (claimed: FAIL, NOT VERIFIED; not claimed: NOT CHARACTERISED).
// It asserts something of every integrator, claimed or not, and judges no claim.
//
// Spec entries: the flows of (3.8) with (2.10) and of (2.36) are defined for every state
// (s3.euler-flow, s2.manakov-flow).
#include "properties/integrators/support/step_kind.hpp"
#include "properties/registry.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/named_inputs.hpp"
#include "properties/support/regimes.hpp"
#include "properties/support/scalar_text.hpp"
#include "properties/support/step_guard.hpp"
#include "properties/support/step_precision.hpp"
#include "properties/support/tolerance.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace gm {
namespace properties_integrator_domain {
namespace {

struct Probe {
  int j = 0;        // the state scaled by 2^j (0: as drawn)
  int k = 4;        // h |Omega| = 2^-k
  double rate = 0;  // |Omega| there
  double size = 0;  // |state| there
  double h = 0;
  bool raised = false;
  bool finite = true;
  std::string message;
};

// What the probes say, in one sentence, and whether the step works everywhere they went.
inline std::string verdict_of(const std::vector<Probe>& probes, const StepDomain& declared, bool* works) {
  std::vector<const Probe*> bad;
  for (const auto& p : probes)
    if (p.raised || !p.finite) bad.push_back(&p);
  *works = bad.empty();
  auto range = [&](auto get) {
    double lo = 0, hi = 0;
    bool first = true;
    for (const auto& p : probes) {
      const double v = get(p);
      if (first || v < lo) lo = v;
      if (first || v > hi) hi = v;
      first = false;
    }
    return fmt("%.3g to %.3g", lo, hi);
  };
  const std::string where = "|Omega| from " + range([](const Probe& p) { return p.rate; }) + ", h |Omega| from " +
                            range([](const Probe& p) { return p.rate * p.h; }) + " (" + std::to_string(probes.size()) +
                            " probes" + (declared.declared() ? ", inside the declared domain" : "") + ")";
  // One step from each probe: what a long run does from there (a growth to overflow) is the other
  // checks' finding, and this sentence says no more than was measured.
  if (bad.empty()) return "one step returns a finite state from every state probed: " + where;
  const Probe& b = *bad.front();
  const std::string what = b.raised ? "raises" : "returns a state that is not finite";
  const std::string first_message = b.raised ? ": " + b.message : "";
  if (bad.size() == probes.size()) return "your step " + what + " on every call" + first_message + " (" + where + ")";
  // A threshold on |Omega|: it fails at every probe at least as fast as the slowest failing one,
  // and at none slower.
  double fail_rate = 1e308, ok_rate = 0;
  bool by_rate = true;
  for (const auto& p : probes)
    if (p.k == 4) {
      if (p.raised || !p.finite)
        fail_rate = std::min(fail_rate, p.rate);
      else
        ok_rate = std::max(ok_rate, p.rate);
    }
  for (const auto& p : probes)
    if (p.k == 4 && p.rate >= fail_rate && !(p.raised || !p.finite)) by_rate = false;
  for (const auto& p : probes)
    if (p.k != 4 && (p.raised || !p.finite)) by_rate = false;
  const std::string advice =
      declared.declared()
          ? " inside its declared domain"
          : "; if it is meant to work only below that, declare its domain (C++: static constexpr gm::student::Domain "
            "domain{.max_omega = ...}; Python: domain = {\"max_omega\": ...}; Octave: the field domain = "
            "struct('max_omega', ...)), and nothing outside it is drawn";
  if (by_rate && fail_rate < 1e308)
    return "your step " + what + " for max |Omega_i| >= " + fmt("%.3g", fail_rate) + " (it works up to " +
           fmt("%.3g", ok_rate) + ")" + first_message + advice;
  // A threshold on h.
  double fail_h = 0, ok_h = 1e308;
  bool by_h = true;
  for (const auto& p : probes)
    if (p.j == 0) {
      if (p.raised || !p.finite)
        fail_h = std::max(fail_h, p.h);
      else
        ok_h = std::min(ok_h, p.h);
    }
  for (const auto& p : probes)
    if (p.j == 0 && p.h <= fail_h && !(p.raised || !p.finite)) by_h = false;
  for (const auto& p : probes)
    if (p.j != 0 && (p.raised || !p.finite)) by_h = false;
  if (by_h && fail_h > 0)
    return "your step " + what + " for h <= " + fmt("%.3g", fail_h) + " (it works down to h = " + fmt("%.3g", ok_h) +
           ")" + first_message +
           (declared.declared() ? std::string(" inside its declared domain")
                                : "; if it is meant to work only above that, declare its domain (min_h)");
  return "your step " + what + " at " + std::to_string(bad.size()) + " of " + std::to_string(probes.size()) +
         " probes, first at |Omega| = " + fmt("%.3g", b.rate) + ", h = " + fmt("%.3g", b.h) + first_message +
         (declared.declared() ? " inside its declared domain" : "");
}

// One probe: the step at x with h, its raise caught (and cleared: this check reports it itself).
template <class P, class X, class T, class Step>
Probe probe(int j, int k, const P& param, const X& x, const T& h, Step&& step) {
  Probe p;
  p.j = j, p.k = k;
  p.rate = stepguard::rate_of(param, x);
  p.size = stepguard::size_of(x);
  p.h = to_double(h);
  try {
    p.finite = step(x, h);
  } catch (const StepRaised& e) {
    p.raised = true;
    p.message = e.raise().message.substr(0, e.raise().message.find('\n'));  // its first line: the sentence
    current_step_raise().reset();
  }
  return p;
}

// The scales between the fastest that works and the slowest that fails, one power of two apart at
// the end, so that a threshold is said to a factor of 2 (the coarse probes are 2^4 apart).
template <class Call>
void refine(std::vector<Probe>& probes, Call&& at_scale) {
  int ok = -1000, bad = 1000;
  for (const auto& p : probes)
    if (p.k == 4) {
      if (p.raised || !p.finite)
        bad = std::min(bad, p.j);
      else
        ok = std::max(ok, p.j);
    }
  while (ok > -1000 && bad < 1000 && bad - ok > 1) {
    const int mid = (ok + bad) / 2;
    const Probe p = at_scale(mid);
    probes.push_back(p);
    (p.raised || !p.finite ? bad : ok) = mid;
  }
}

// The probes of one state: scaled (j) with h |Omega| = 1/16, and as drawn with smaller steps.
template <class T, class Scaled, class Call>
std::vector<Probe> probes_of(double rate0, double size0, Scaled&& scaled, Call&& call) {
  std::vector<Probe> out;
  const StepDomain& d = current_step_domain();
  const int last_k = std::is_same_v<T, double> ? 50 : 120;
  auto at_scale = [&](int j) {
    const double l = std::ldexp(1.0, j);
    return call(j, 4, scaled(pow2<T>(j)), T(pow2<T>(-4) / T(l * rate0)));
  };
  auto inside = [&](int j) {
    const double l = std::ldexp(1.0, j);
    return !((d.max_omega > 0 && l * rate0 > d.max_omega) || (d.max_pi > 0 && l * size0 > d.max_pi) ||
             (d.min_h > 0 && std::ldexp(1.0, -4) / (l * rate0) < d.min_h));
  };
  // Scales from 2^-64 to 2^64 (|Omega| up to ~1e19: a reset of a fast body shows there), each at
  // h |Omega| = 1/16; for a step judged at a precision whose range is smaller (float: |Pi|^2
  // overflows near 2^128), within 2^-60 to 2^60, where the squares of the state stay finite there.
  const int reach = current_step_precision().eps >= kFloatEps ? 60 : 64;
  for (int j = -reach; j <= reach; j += 4)
    if (inside(j)) out.push_back(at_scale(j));
  refine(out, at_scale);
  // A step of h |Omega| = 1, past the pi/4 at which engines limit the turn of a step, as drawn.
  if (inside(0) && !(d.min_h > 0 && 1.0 / rate0 < d.min_h)) out.push_back(call(0, 0, scaled(T(1)), T(T(1) / T(rate0))));
  for (int k = 6; k <= last_k; k += 4) {
    const T h = pow2<T>(-k) / T(rate0);
    if (d.min_h > 0 && to_double(h) < d.min_h) continue;
    if ((d.max_omega > 0 && rate0 > d.max_omega) || (d.max_pi > 0 && size0 > d.max_pi)) continue;
    out.push_back(call(0, k, scaled(T(1)), h));
  }
  return out;
}

template <class T>
bool finite(const RigidBodyState<T>& y) {
  return is_finite(max_abs(y.Pi)) && is_finite(max_abs(y.O));
}
template <class T>
bool finite(const ManakovState<T>& y) {
  return is_finite(max_abs(y.M)) && is_finite(max_abs(y.O));
}

// The case probed, by kind: the rigid body's generic case; Manakov's with n from gen::uniform(3, 5)
// (this check's own generator for n, kept so that its draws do not move).
template <class T>
stepkind::RigidBodyCase<T> draw_domain_case(stepkind::RigidBodyKind) {
  return stepkind::RigidBodyKind::draw_case<T>();
}

// The same draw as the local order's (support/step_kind.hpp).
template <class T>
stepkind::ManakovCase<T> draw_domain_case(stepkind::ManakovKind) {
  return stepkind::ManakovKind::draw_local_case<T>();
}

// The state with its momentum scaled by l (the probes' scales).
template <class T>
RigidBodyState<T> scaled_state(const RigidBodyState<T>& x0, const T& l) {
  return RigidBodyState<T>{Vec3<T>(x0.Pi * l), x0.O};
}

template <class T>
ManakovState<T> scaled_state(const ManakovState<T>& x0, const T& l) {
  return ManakovState<T>{MatX<T>(x0.M * l), x0.O};
}

template <class T>
std::string domain_inputs(const stepkind::RigidBodyCase<T>& m) {
  return named("I", m.I) + named("Pi (before scaling)", m.x0.Pi) + named("O", m.x0.O);
}

template <class T>
std::string domain_inputs(const stepkind::ManakovCase<T>& m) {
  return named("A", m.A) + named("M (before scaling)", m.x0.M) + named("O", m.x0.O);
}

template <class Kind, class T>
void domain_claim(const Integrator<T>& in, const IntegratorClaims& c) {
  using State = typename Kind::template State<T>;
  const auto m = draw_domain_case<T>(Kind{});
  const State& x0 = m.x0;
  const double rate0 = stepguard::rate_of(Kind::body(m), x0), size0 = stepguard::size_of(x0);
  const auto probes = probes_of<T>(
      rate0, size0, [&](const T& l) { return scaled_state(x0, l); },
      [&](int j, int k, const State& x, const T& h) {
        return probe(j, k, Kind::body(m), x, h,
                     [&](const State& s, const T& dt) { return finite(Kind::step(in, m, s, dt)); });
      });
  bool works = false;
  const std::string words = verdict_of(probes, c.domain, &works);
  if (works) record_note(in.name + ": " + words + judged_tag<T>());
  showing_inputs([&] { return domain_inputs(m); }, [&] { require(in.name + ": " + words, works, "\n"); });
}

template <class T>
void integrator_domain(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  domain_claim<stepkind::RigidBodyKind>(in, c);
}

template <class T>
void manakov_integrator_domain(const Subject<T>&, const Integrator<T>& in, const IntegratorClaims& c) {
  domain_claim<stepkind::ManakovKind>(in, c);
}

}  // namespace

GM_PROPERTY(integrator_domain, integrator_scalars,
            {.spec = "s3.euler-flow",
             .title = "rigid-body integrator: the step returns a finite state at every state and step probed in its "
                      "domain (scales 2^-64 to 2^64, h |Omega| from 2^-50 to 1)",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"midpoint_raises_when_fast"},
             .cases = {.d = 3, .mp = 1, .q = 0},
             .step = StepKind::RigidBody});

GM_PROPERTY(manakov_integrator_domain, integrator_scalars,
            {.spec = "s2.manakov-flow",
             .title = "Manakov integrator: the step returns a finite state at every state and step probed in its "
                      "domain (scales 2^-64 to 2^64, h |Omega| from 2^-50 to 1)",
             .tolerance = ToleranceClass::Truncation,
             .needs = {},
             .negative_controls = {"midpoint_raises_when_fast"},
             .cases = {.d = 3, .mp = 1, .q = 0},
             .step = StepKind::Manakov});

}  // namespace properties_integrator_domain
}  // namespace gm
