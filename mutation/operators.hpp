// Generic mutation operators (mutant schemata): every mutant of every slot is compiled once and
// chosen at run time. An operator wraps a slot's function; which operators apply to a slot is
// decided from the slot's signature Slot<R(A...)> alone, so a new slot in GM_SUBJECT_SLOTS gets
// its mutants with no edit here. The list of mutants is in mutation/catalogue.hpp.
#pragma once

#include "core/subject.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace gm::mutation {

// ---- type traits over slot signatures -------------------------------------------------------
template <class X>
struct is_eigen : std::false_type {};
template <class S, int R, int C, int O, int MR, int MC>
struct is_eigen<Eigen::Matrix<S, R, C, O, MR, MC>> : std::true_type {};
template <class X>
struct is_vec3 : std::false_type {};
template <class S>
struct is_vec3<Eigen::Matrix<S, 3, 1>> : std::true_type {};
template <class X>
struct is_vector : std::false_type {};  // Vec3, Vec6, VecX
template <class S, int R, int O, int MR, int MC>
struct is_vector<Eigen::Matrix<S, R, 1, O, MR, MC>> : std::true_type {};
template <class X>
struct is_square_matrix : std::false_type {};  // Mat3, MatX
template <class S, int O, int MR, int MC>
struct is_square_matrix<Eigen::Matrix<S, 3, 3, O, MR, MC>> : std::true_type {};
template <class S, int O, int MR, int MC>
struct is_square_matrix<Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic, O, MR, MC>> : std::true_type {};
template <class X>
struct is_pair : std::false_type {};
template <class X, class Y>
struct is_pair<std::pair<X, Y>> : std::true_type {};

template <class T, class X>
constexpr bool is_numeric_v = std::is_same_v<X, T> || is_eigen<X>::value || is_pair<X>::value;

// ---- value operations (generic over T, Eigen matrices and pairs) ----------------------------
template <class X, class T>
X scale(const X& x, const T& f) {
  if constexpr (is_pair<X>::value)
    return X{scale(x.first, f), scale(x.second, f)};
  else if constexpr (is_eigen<X>::value)
    return X(x * f);
  else
    return X(x * f);
}
template <class X>
X permute_vec3(const X& v) {  // (x, y, z) -> (y, z, x): an index slip
  return X(v(1), v(2), v(0));
}
template <class T, class X>
X round_through_double(const X& x) {
  if constexpr (is_pair<X>::value)
    return X{round_through_double<T>(x.first), round_through_double<T>(x.second)};
  else if constexpr (is_eigen<X>::value)
    return x.unaryExpr([](const T& v) { return T(static_cast<double>(v)); }).eval();
  else if constexpr (std::is_same_v<X, T>)
    return T(static_cast<double>(x));
  else if constexpr (std::is_same_v<X, RigidBodyState<T>>)
    return X{round_through_double<T>(x.Pi), round_through_double<T>(x.O)};
  else if constexpr (std::is_same_v<X, ManakovState<T>>)
    return X{round_through_double<T>(x.M), round_through_double<T>(x.O)};
  else
    return x;  // int, LieAlgebraId
}
template <class T, class X>
bool is_tiny(const X& x) {  // |x|_inf < 2^-20 (and not empty)
  if constexpr (is_vector<X>::value) {
    if (x.size() == 0) return false;
    const T limit = T(1) / T(1 << 20);
    for (Eigen::Index i = 0; i < x.size(); ++i)
      if (x(i) >= limit || -x(i) >= limit) return false;
    return true;
  } else {
    return false;
  }
}
template <class X>
bool on_axis(const X& v) {  // exactly two zero components
  int zeros = (v(0) == 0) + (v(1) == 0) + (v(2) == 0);
  return zeros == 2;
}

// ---- the operators ----------------------------------------------------------------------------
// Each is a struct with `name`, `description` and a static `applies<T, R, A...>` and `wrap`.
// wrap(orig) returns the mutated std::function<R(A...)>; `orig` is a copy of the slot.

enum class Class {
  ResultSign,
  Factor,
  Transpose,
  SwapArgs,
  IndexSlip,
  Constant,
  SpecialCase,
  Precision,
  Integrator,
  Handwritten
};
const char* class_name(Class c);

template <class T, class Sig>
struct Ops;

template <class T, class R, class... A>
struct Ops<T, R(A...)> {
  using F = std::function<R(A...)>;
  using SlotT = Slot<R(A...)>;
  static constexpr std::size_t N = sizeof...(A);
  template <std::size_t I>
  using Arg = std::decay_t<std::tuple_element_t<I, std::tuple<A...>>>;

  static F negate(SlotT o) {
    return [o](A... a) -> R { return scale(R(o(a...)), T(-1)); };
  }
  static F times(SlotT o, T f) {
    return [o, f](A... a) -> R { return scale(R(o(a...)), f); };
  }
  static F transpose(SlotT o) {
    return [o](A... a) -> R { return R(o(a...).transpose()); };
  }
  static F permute_result(SlotT o) {
    return [o](A... a) -> R { return permute_vec3(R(o(a...))); };
  }
  static F tiny_guard(SlotT o) {
    return [o](A... a) -> R {
      R r = o(a...);
      if ((is_tiny<T>(a) || ...)) return scale(r, T(0));
      return r;
    };
  }
  static F precision_lowered(SlotT o) {
    if constexpr (!std::is_same_v<T, Real50>) {
      return [o](A... a) -> R { return o(a...); };
    } else {
      return [o](A... a) -> R { return round_through_double<T>(R(o(round_through_double<T>(std::decay_t<A>(a))...))); };
    }
  }
  // Argument I and J swapped (same type).
  template <std::size_t I, std::size_t J>
  static F swap_args(SlotT o) {
    return [o](A... a) -> R {
      auto t = std::forward_as_tuple(a...);
      return call_swapped<I, J>(o, t, std::make_index_sequence<N>{});
    };
  }
  template <std::size_t I, std::size_t J, class Tup, std::size_t... K>
  static R call_swapped(const SlotT& o, Tup& t, std::index_sequence<K...>) {
    return o(std::get<(K == I ? J : (K == J ? I : K))>(t)...);
  }
  // Vec3 argument I permuted.
  template <std::size_t I>
  static F permute_arg(SlotT o) {
    return [o](A... a) -> R {
      auto t = std::forward_as_tuple(a...);
      const Arg<I> p = permute_vec3(Arg<I>(std::get<I>(t)));
      return call_replaced<I>(o, t, p, std::make_index_sequence<N>{});
    };
  }
  template <std::size_t I, class Tup, class V, std::size_t... K>
  static R call_replaced(const SlotT& o, Tup& t, const V& v, std::index_sequence<K...>) {
    return o(pick<K == I>(std::get<K>(t), v)...);
  }
  template <bool Take, class X, class V>
  static decltype(auto) pick(X& x, const V& v) {
    if constexpr (Take)
      return (v);
    else
      return (x);
  }
  // Vec3 argument I on a coordinate axis: the result negated (a wrong "principal axis fast path").
  template <std::size_t I>
  static F axis_branch(SlotT o) {
    return [o](A... a) -> R {
      auto t = std::forward_as_tuple(a...);
      R r = o(a...);
      if (on_axis(std::get<I>(t))) return scale(r, T(-1));
      return r;
    };
  }
};

}  // namespace gm::mutation
