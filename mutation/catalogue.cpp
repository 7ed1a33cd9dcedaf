// Generates the mutant list: one translation unit instantiating every operator on every slot in
// double, Real50 and Rational (mutant schemata: one build, the choice made at run time).
#include "mutation/catalogue.hpp"

#include "mutation/operators.hpp"
#include "tests/mutants/mutants.hpp"

#include <memory>

namespace gm::mutation {

const char* class_name(Class c) {
  switch (c) {
    case Class::ResultSign:
      return "result_sign";
    case Class::Factor:
      return "factor";
    case Class::Transpose:
      return "transpose";
    case Class::SwapArgs:
      return "swap_args";
    case Class::IndexSlip:
      return "index_slip";
    case Class::Constant:
      return "constant";
    case Class::SpecialCase:
      return "special_case";
    case Class::Precision:
      return "precision";
    case Class::Integrator:
      return "integrator";
    case Class::Handwritten:
      return "handwritten";
  }
  return "?";
}

namespace {

enum class OpKind {
  Negate,
  Times2,
  Half,
  Transpose,
  PermuteResult,
  Perturb,
  TinyGuard,
  PrecisionLowered,
  SwapArgs,
  PermuteArg,
  AxisBranch
};

struct OpSpec {
  OpKind kind;
  int i = -1, j = -1;
  std::string name;
  std::string description;
  Class cls;
};

template <std::size_t N, class F>
void for_index(F&& f) {
  [&]<std::size_t... K>(std::index_sequence<K...>) { (f(std::integral_constant<std::size_t, K>{}), ...); }
  (std::make_index_sequence<N>{});
}

template <class T, class R, class... A>
std::vector<OpSpec> applicable(const Slot<R(A...)>&) {
  using O = Ops<T, R(A...)>;
  constexpr std::size_t N = sizeof...(A);
  std::vector<OpSpec> out;
  if constexpr (is_numeric_v<T, R>) {
    out.push_back({OpKind::Negate, -1, -1, "negate_result", "result negated (a sign error)", Class::ResultSign});
    out.push_back({OpKind::Times2, -1, -1, "double_result", "result times 2 (a factor 1/2 lost)", Class::Factor});
    out.push_back({OpKind::Half, -1, -1, "halve_result", "result times 1/2 (a factor 1/2 added)", Class::Factor});
    out.push_back({OpKind::Perturb, -1, -1, "perturb_result", "result times (1 + 2^-30) (a constant slightly wrong)",
                   Class::Constant});
  }
  if constexpr (is_square_matrix<R>::value)
    out.push_back({OpKind::Transpose, -1, -1, "transpose_result", "matrix result transposed", Class::Transpose});
  if constexpr (is_vec3<R>::value)
    out.push_back({OpKind::PermuteResult, -1, -1, "permute_result",
                   "components of the Vec3 result cycled (x,y,z) -> (y,z,x) (an index slip)", Class::IndexSlip});
  std::vector<OpSpec> swaps;
  for_index<N>([&](auto I_) {
    constexpr std::size_t I = decltype(I_)::value;
    for_index<N>([&](auto J_) {
      constexpr std::size_t J = decltype(J_)::value;
      if constexpr (I < J && std::is_same_v<typename O::template Arg<I>, typename O::template Arg<J>>)
        swaps.push_back({OpKind::SwapArgs, int(I), int(J), "swap_args_" + std::to_string(I) + "_" + std::to_string(J),
                         "arguments " + std::to_string(I) + " and " + std::to_string(J) + " swapped", Class::SwapArgs});
    });
  });
  if (swaps.size() == 1) swaps[0].name = "swap_args";
  out.insert(out.end(), swaps.begin(), swaps.end());
  for_index<N>([&](auto I_) {
    constexpr std::size_t I = decltype(I_)::value;
    if constexpr (is_vec3<typename O::template Arg<I>>::value) {
      out.push_back({OpKind::PermuteArg, int(I), -1, "permute_arg_" + std::to_string(I),
                     "components of Vec3 argument " + std::to_string(I) + " cycled (x,y,z) -> (y,z,x) (an index slip)",
                     Class::IndexSlip});
      if constexpr (is_numeric_v<T, R>)
        out.push_back({OpKind::AxisBranch, int(I), -1, "axis_branch_arg_" + std::to_string(I),
                       "a wrong 'principal axis fast path': result negated when Vec3 argument " + std::to_string(I) +
                           " lies on a coordinate axis",
                       Class::SpecialCase});
    }
  });
  if constexpr (is_numeric_v<T, R> && (is_vector<std::decay_t<A>>::value || ...))
    out.push_back({OpKind::TinyGuard, -1, -1, "tiny_guard",
                   "a special-case guard: result zero when a vector argument is tiny (|x|_inf < 2^-20)",
                   Class::SpecialCase});
  out.push_back({OpKind::PrecisionLowered, -1, -1, "precision_lowered",
                 "in 50 digits, arguments and result rounded through double (a cast to double)", Class::Precision});
  return out;
}

template <class T, class R, class... A>
void apply(Slot<R(A...)>& slot, const OpSpec& op) {
  using O = Ops<T, R(A...)>;
  constexpr std::size_t N = sizeof...(A);
  const Slot<R(A...)> orig = slot;
  switch (op.kind) {
    case OpKind::Negate:
      if constexpr (is_numeric_v<T, R>) slot = O::negate(orig);
      break;
    case OpKind::Times2:
      if constexpr (is_numeric_v<T, R>) slot = O::times(orig, T(2));
      break;
    case OpKind::Half:
      if constexpr (is_numeric_v<T, R>) slot = O::times(orig, T(1) / T(2));
      break;
    case OpKind::Perturb:
      if constexpr (is_numeric_v<T, R>) slot = O::times(orig, T(1) + T(1) / T(1 << 30));
      break;
    case OpKind::Transpose:
      if constexpr (is_square_matrix<R>::value) slot = O::transpose(orig);
      break;
    case OpKind::PermuteResult:
      if constexpr (is_vec3<R>::value) slot = O::permute_result(orig);
      break;
    case OpKind::TinyGuard:
      if constexpr (is_numeric_v<T, R>) slot = O::tiny_guard(orig);
      break;
    case OpKind::PrecisionLowered:
      slot = O::precision_lowered(orig);
      break;
    case OpKind::SwapArgs:
      for_index<N>([&](auto I_) {
        constexpr std::size_t I = decltype(I_)::value;
        for_index<N>([&](auto J_) {
          constexpr std::size_t J = decltype(J_)::value;
          if constexpr (I < J && std::is_same_v<typename O::template Arg<I>, typename O::template Arg<J>>)
            if (op.i == int(I) && op.j == int(J)) slot = O::template swap_args<I, J>(orig);
        });
      });
      break;
    case OpKind::PermuteArg:
      for_index<N>([&](auto I_) {
        constexpr std::size_t I = decltype(I_)::value;
        if constexpr (is_vec3<typename O::template Arg<I>>::value)
          if (op.i == int(I)) slot = O::template permute_arg<I>(orig);
      });
      break;
    case OpKind::AxisBranch:
      for_index<N>([&](auto I_) {
        constexpr std::size_t I = decltype(I_)::value;
        if constexpr (is_vec3<typename O::template Arg<I>>::value && is_numeric_v<T, R>)
          if (op.i == int(I)) slot = O::template axis_branch<I>(orig);
      });
      break;
  }
}

// Calls fn(dst.<name>, src.<name>) for the slot called `name`.
template <class T, class Fn>
void with_slot(Subject<T>& dst, const Subject<T>& src, std::string_view name, Fn&& fn) {
#define GM_WITH_SLOT(n, sig, place, meaning) \
  if (name == #n) return fn(dst.n, src.n);
  GM_SUBJECT_SLOTS(GM_WITH_SLOT)
#undef GM_WITH_SLOT
}

template <class T>
std::shared_ptr<const Subject<T>> alone_subject(const std::shared_ptr<const Subject<T>>& base, const std::string& slot,
                                                const OpSpec& op) {
  if (!base) return nullptr;
  auto s = std::make_shared<Subject<T>>();
  with_slot(*s, *base, slot, [&](auto& dst, const auto& src) {
    dst = src;
    apply<T>(dst, op);
  });
  return s;
}

// ---- integrator steps ----------------------------------------------------------------------
enum class StepOp { PrecisionLowered, HPerturbed, AxisFastPath, DropAttitude, AtRestGuard, DiagonalAOnly };

template <class T>
Mat3<T> axis_rotation(int k, const T& angle) {  // exp(angle * hat(e_k))
  using std::cos;
  using std::sin;
  const T c = cos(angle), s = sin(angle);
  Mat3<T> r = Mat3<T>::Identity();
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  r(a, a) = c;
  r(b, b) = c;
  r(a, b) = -s;
  r(b, a) = s;
  return r;
}

template <class T>
void apply_step(Integrator<T>& in, bool rigid, StepOp op) {
  if constexpr (!std::is_same_v<T, Rational>) {
    if (rigid) {
      const auto orig = in.rigid_body_step;
      using St = RigidBodyState<T>;
      switch (op) {
        case StepOp::PrecisionLowered:
          if constexpr (std::is_same_v<T, Real50>)
            in.rigid_body_step = [orig](const Vec3<T>& I, const St& x, const T& h) {
              return round_through_double<T>(
                  orig(round_through_double<T>(I), round_through_double<T>(x), round_through_double<T>(h)));
            };
          break;
        case StepOp::HPerturbed:
          in.rigid_body_step = [orig](const Vec3<T>& I, const St& x, const T& h) {
            return orig(I, x, T(h * (T(1) + T(1) / T(1 << 20))));
          };
          break;
        case StepOp::AxisFastPath:
          in.rigid_body_step = [orig](const Vec3<T>& I, const St& x, const T& h) {
            if (!on_axis(x.Pi)) return orig(I, x, h);
            int k = x.Pi(0) != 0 ? 0 : (x.Pi(1) != 0 ? 1 : 2);
            const T omega = x.Pi(k) / I(k);
            return St{x.Pi, Mat3<T>(x.O * axis_rotation<T>(k, T(-h * omega)))};
          };
          break;
        case StepOp::DropAttitude:
          in.rigid_body_step = [orig](const Vec3<T>& I, const St& x, const T& h) {
            St y = orig(I, x, h);
            y.O = x.O;
            return y;
          };
          break;
        case StepOp::AtRestGuard:
          in.rigid_body_step = [orig](const Vec3<T>& I, const St& x, const T& h) {
            if (x.Pi.cwiseAbs().maxCoeff() < T(1) / T(1 << 30)) return x;
            return orig(I, x, h);
          };
          break;
        case StepOp::DiagonalAOnly:
          break;
      }
    } else {
      const auto orig = in.manakov_step;
      using St = ManakovState<T>;
      switch (op) {
        case StepOp::PrecisionLowered:
          if constexpr (std::is_same_v<T, Real50>)
            in.manakov_step = [orig](const MatX<T>& A, const St& x, const T& h) {
              return round_through_double<T>(
                  orig(round_through_double<T>(A), round_through_double<T>(x), round_through_double<T>(h)));
            };
          break;
        case StepOp::HPerturbed:
          in.manakov_step = [orig](const MatX<T>& A, const St& x, const T& h) {
            return orig(A, x, T(h * (T(1) + T(1) / T(1 << 20))));
          };
          break;
        case StepOp::AxisFastPath:
          break;
        case StepOp::AtRestGuard:
          in.manakov_step = [orig](const MatX<T>& A, const St& x, const T& h) {
            if (x.M.cwiseAbs().maxCoeff() < T(1) / T(1 << 30)) return x;
            return orig(A, x, h);
          };
          break;
        case StepOp::DiagonalAOnly:
          in.manakov_step = [orig](const MatX<T>& A, const St& x, const T& h) {
            return orig(MatX<T>(A.diagonal().asDiagonal()), x, h);
          };
          break;
        case StepOp::DropAttitude:
          in.manakov_step = [orig](const MatX<T>& A, const St& x, const T& h) {
            St y = orig(A, x, h);
            y.O = x.O;
            return y;
          };
          break;
      }
    }
  }
}

template <class T>
std::shared_ptr<const Subject<T>> step_subject(const std::shared_ptr<const Subject<T>>& base, std::size_t index,
                                               bool rigid, StepOp op, bool alone) {
  if (!base) return nullptr;
  auto s = alone ? std::make_shared<Subject<T>>() : std::make_shared<Subject<T>>(*base);
  if (index < base->integrators.size()) {
    Integrator<T> in = base->integrators[index];
    if (alone) {
      // Only the mutated step: the other step of this integrator is left out too.
      if (rigid)
        in.manakov_step = std::function<ManakovState<T>(const MatX<T>&, const ManakovState<T>&, const T&)>{};
      else
        in.rigid_body_step = std::function<RigidBodyState<T>(const Vec3<T>&, const RigidBodyState<T>&, const T&)>{};
    }
    apply_step(in, rigid, op);
    if (alone)
      s->integrators = {in};
    else
      s->integrators[index] = in;
  }
  return s;
}

}  // namespace

std::vector<MutantDef> all_mutants(const SubjectSet& base) {
  std::vector<MutantDef> out;
  const Subject<double>& d = *base.d;
  // Slots.
  Subject<double> scratch;
  for (const auto& info : subject_slots()) {
    const std::string slot = info.name;
    std::vector<OpSpec> ops;
    with_slot(scratch, d, slot, [&](auto&, const auto& src) { ops = applicable<double>(src); });
    for (const OpSpec& op : ops) {
      MutantDef m;
      m.name = slot + ":" + op.name;
      m.slot = slot;
      m.op = op.name;
      m.op_class = class_name(op.cls);
      m.description = slot + ": " + op.description;
      m.full = [slot, op, name = m.name, desc = m.description](const SubjectSet& b) {
        return mutate(b, name, desc, [&](auto& s) {
          using T = typename std::decay_t<decltype(s)>::Scalar;
          const Subject<T> src = s;
          with_slot(s, src, slot, [&](auto& dst, const auto&) { apply<T>(dst, op); });
        });
      };
      m.alone = [slot, op, name = m.name, desc = m.description](const SubjectSet& b) {
        SubjectSet s;
        s.name = name + " (alone)";
        s.description = desc;
        s.claims = b.claims;
        s.d = alone_subject(b.d, slot, op);
        s.mp = alone_subject(b.mp, slot, op);
        s.q = alone_subject(b.q, slot, op);
        return s;
      };
      out.push_back(std::move(m));
    }
  }
  // Integrator steps.
  struct StepOpInfo {
    StepOp op;
    const char* name;
    const char* description;
  };
  const StepOpInfo step_ops[] = {
      {StepOp::PrecisionLowered, "precision_lowered", "in 50 digits, the step computed in double (a cast to double)"},
      {StepOp::HPerturbed, "h_perturbed", "the step taken with h * (1 + 2^-20) instead of h"},
      {StepOp::AxisFastPath, "axis_fast_path",
       "a wrong 'principal axis fast path': Pi on a coordinate axis returns (Pi, O R(-h Omega))"},
      {StepOp::DropAttitude, "drop_attitude", "the attitude update dropped: O returned unchanged"},
      {StepOp::AtRestGuard, "at_rest_guard",
       "a 'body at rest' guard: the state returned unchanged when |Pi|_inf (or |M|_inf) < 2^-30"},
      {StepOp::DiagonalAOnly, "diagonal_A_only", "the step given only the diagonal of A (right for a diagonal A only)"},
  };
  for (std::size_t k = 0; k < d.integrators.size(); ++k) {
    const Integrator<double>& in = d.integrators[k];
    for (bool rigid : {true, false}) {
      if (rigid ? !in.rigid_body_step : !in.manakov_step) continue;
      const std::string step = rigid ? "rigid_body_step" : "manakov_step";
      for (const auto& so : step_ops) {
        if (!rigid && so.op == StepOp::AxisFastPath) continue;
        if (rigid && so.op == StepOp::DiagonalAOnly) continue;
        MutantDef m;
        m.name = in.name + ":" + step + ":" + so.name;
        m.slot = step;
        m.op = so.name;
        m.op_class = class_name(Class::Integrator);
        m.integrator = in.name;
        m.step = rigid ? StepKind::RigidBody : StepKind::Manakov;
        m.description = in.name + " " + step + ": " + so.description;
        auto make = [k, rigid, op = so.op, name = m.name, desc = m.description](const SubjectSet& b, bool alone) {
          SubjectSet s = b;
          s.name = alone ? name + " (alone)" : name;
          s.description = desc;
          s.d = step_subject(b.d, k, rigid, op, alone);
          s.mp = step_subject(b.mp, k, rigid, op, alone);
          s.q = step_subject(b.q, k, rigid, op, alone);
          return s;
        };
        m.full = [make](const SubjectSet& b) { return make(b, false); };
        m.alone = [make](const SubjectSet& b) { return make(b, true); };
        out.push_back(std::move(m));
      }
    }
  }
  // Hand-written negative controls.
  for (const Mutant& h : mutants()) {
    MutantDef m;
    m.name = h.name;
    m.op = "handwritten";
    m.op_class = class_name(Class::Handwritten);
    m.description = h.description;
    m.full = h.make;
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace gm::mutation
