// The value encoding of the slot protocol (docs/PROTOCOL.md): every argument and result of a slot
// to and from JSON, exactly.
//
//   scalar  double: the shortest decimal string that reads back as the same double (exact);
//           mp50:   a decimal string with 60 significant digits (the 168-bit Real50 round-trips);
//           exact:  "p/q" (or "p");
//           replies may also use JSON numbers: integers in every scalar, floats in double only.
//   int                   a JSON integer
//   LieAlgebraId          "so3", "so4", "sl2"
//   vector                an array of scalars
//   matrix                an array of rows (each an array of scalars)
//   pair                  a 2-array
//   RigidBodyState        {"Pi": vector, "O": matrix}
//   ManakovState          {"M": matrix, "O": matrix}
//   EngineState           a state in its declared form (core/state_form.hpp): {"q": [4 scalars], "omega":
//                         vector}, {"O": matrix, "Pi": vector}, ... (encode/decode_engine_state)
//
// Decoding validates shapes (a Vec3 has 3 entries, a Mat3 3 rows of 3, matrices are rectangular)
// and values (numeric, finite); a bad value throws ProtocolValueError naming what was wrong. The
// state an integrator's step returns is decoded with Values::any: a NaN or an infinity there ("nan",
// "inf", Octave's "NaN", mpmath's "+inf") is what the step computed, a measurement the checks name
// ("H is not finite within 2503 steps"), not a reply the protocol refuses.
#pragma once

#include "core/subject.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace gm::protocol {

using nlohmann::json;

class ProtocolValueError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The protocol's name for each scalar.
template <class T>
constexpr const char* scalar_word() {
  if constexpr (std::is_same_v<T, double>)
    return "double";
  else if constexpr (std::is_same_v<T, Real50>)
    return "mp50";
  else
    return "exact";
}

std::string encode_scalar(double x);
std::string encode_scalar(const Real50& x);
std::string encode_scalar(const Rational& x);

// Which values a reply may hold: finite numbers only (a slot's result), or also NaN and the
// infinities (the state an integrator's step returns; an exact scalar is never non-finite).
enum class Values { finite, any };

// Throws ProtocolValueError (with `what` naming the place, e.g. "result[1][2]").
template <class T>
T decode_scalar(const json& j, const std::string& what, Values values = Values::finite);
template <>
double decode_scalar<double>(const json& j, const std::string& what, Values values);
template <>
Real50 decode_scalar<Real50>(const json& j, const std::string& what, Values values);
template <>
Rational decode_scalar<Rational>(const json& j, const std::string& what, Values values);

// The common case of a double, decoded without building the text that names its place: a JSON
// number, or a decimal string read whole and finite. False for anything else (a fraction, a
// non-finite or malformed value), which decode_scalar then decodes or rejects with its message.
bool decode_plain_double(const json& j, double& out);

// An entry of a vector or matrix: `place()` (its name, e.g. "result[1][2]") is built only when
// it is needed, for a message or for a scalar other than double.
template <class T, class Place>
T decode_entry(const json& j, Place&& place, Values values = Values::finite) {
  if constexpr (std::is_same_v<T, double>) {
    double x;
    if (decode_plain_double(j, x)) return x;
  }
  return decode_scalar<T>(j, place(), values);
}

const char* lie_algebra_word(LieAlgebraId g);

template <class X>
struct is_eigen_matrix : std::false_type {};
template <class S, int R, int C, int O, int MR, int MC>
struct is_eigen_matrix<Eigen::Matrix<S, R, C, O, MR, MC>> : std::true_type {};

template <class X>
struct is_pair : std::false_type {};
template <class A, class B>
struct is_pair<std::pair<A, B>> : std::true_type {};

template <class T, class X>
json encode(const X& x) {
  if constexpr (std::is_same_v<X, T>) {
    return encode_scalar(x);
  } else if constexpr (std::is_same_v<X, int>) {
    return x;
  } else if constexpr (std::is_same_v<X, LieAlgebraId>) {
    return lie_algebra_word(x);
  } else if constexpr (is_eigen_matrix<X>::value) {
    if constexpr (X::ColsAtCompileTime == 1) {
      json a = json::array();
      for (Eigen::Index i = 0; i < x.size(); ++i) a.push_back(encode_scalar(x(i)));
      return a;
    } else {
      json rows = json::array();
      for (Eigen::Index i = 0; i < x.rows(); ++i) {
        json row = json::array();
        for (Eigen::Index k = 0; k < x.cols(); ++k) row.push_back(encode_scalar(x(i, k)));
        rows.push_back(std::move(row));
      }
      return rows;
    }
  } else if constexpr (is_pair<X>::value) {
    return json::array({encode<T>(x.first), encode<T>(x.second)});
  } else if constexpr (std::is_same_v<X, RigidBodyState<T>>) {
    return json{{"Pi", encode<T>(x.Pi)}, {"O", encode<T>(x.O)}};
  } else if constexpr (std::is_same_v<X, ManakovState<T>>) {
    return json{{"M", encode<T>(x.M)}, {"O", encode<T>(x.O)}};
  } else if constexpr (std::is_same_v<X, EngineState<T>>) {
    json j = json::object();
    if (x.form.has_quaternion())
      j["q"] = encode<T>(x.q);
    else
      j["O"] = encode<T>(x.O);
    j[angular_key(x.form.angular)] = encode<T>(x.angular());
    return j;
  } else {
    static_assert(sizeof(X) == 0, "no protocol encoding for this type");
  }
}

template <class T, class X>
X decode(const json& j, const std::string& what, Values values = Values::finite) {
  auto bad = [&](const std::string& why) { return ProtocolValueError(what + ": " + why); };
  if constexpr (std::is_same_v<X, T>) {
    return decode_scalar<T>(j, what, values);
  } else if constexpr (is_eigen_matrix<X>::value) {
    if (!j.is_array()) throw bad("expected an array, got " + j.dump().substr(0, 80));
    if constexpr (X::ColsAtCompileTime == 1) {
      if (X::RowsAtCompileTime != Eigen::Dynamic && j.size() != static_cast<std::size_t>(X::RowsAtCompileTime))
        throw bad("expected a vector of " + std::to_string(X::RowsAtCompileTime) + " entries, got " +
                  std::to_string(j.size()));
      X v(static_cast<Eigen::Index>(j.size()));
      for (std::size_t i = 0; i < j.size(); ++i) {
        if (j[i].is_array()) throw bad("expected a vector, got a nested array at entry " + std::to_string(i));
        v(static_cast<Eigen::Index>(i)) = decode_entry<T>(
            j[i], [&] { return what + "[" + std::to_string(i) + "]"; }, values);
      }
      return v;
    } else {
      const std::size_t rows = j.size();
      if (X::RowsAtCompileTime != Eigen::Dynamic && rows != static_cast<std::size_t>(X::RowsAtCompileTime))
        throw bad("expected a matrix of " + std::to_string(X::RowsAtCompileTime) + " rows, got " +
                  std::to_string(rows));
      if (rows == 0) return X(0, 0);
      if (!j[0].is_array()) throw bad("expected a matrix (an array of rows), got a flat array");
      const std::size_t cols = j[0].size();
      if (X::ColsAtCompileTime != Eigen::Dynamic && cols != static_cast<std::size_t>(X::ColsAtCompileTime))
        throw bad("expected " + std::to_string(X::ColsAtCompileTime) + " columns, got " + std::to_string(cols));
      X m(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
      for (std::size_t r = 0; r < rows; ++r) {
        if (!j[r].is_array() || j[r].size() != cols)
          throw bad("row " + std::to_string(r) + " is not an array of " + std::to_string(cols) +
                    " entries (rows differ)");
        for (std::size_t c = 0; c < cols; ++c)
          m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = decode_entry<T>(
              j[r][c], [&] { return what + "[" + std::to_string(r) + "][" + std::to_string(c) + "]"; }, values);
      }
      return m;
    }
  } else if constexpr (is_pair<X>::value) {
    if (!j.is_array() || j.size() != 2) throw bad("expected a pair (an array of 2 values)");
    return X{decode<T, typename X::first_type>(j[0], what + ".first", values),
             decode<T, typename X::second_type>(j[1], what + ".second", values)};
  } else if constexpr (std::is_same_v<X, RigidBodyState<T>>) {
    if (!j.is_object() || !j.contains("Pi") || !j.contains("O")) throw bad("expected {\"Pi\": ..., \"O\": ...}");
    return X{decode<T, Vec3<T>>(j["Pi"], what + ".Pi", values), decode<T, Mat3<T>>(j["O"], what + ".O", values)};
  } else if constexpr (std::is_same_v<X, ManakovState<T>>) {
    if (!j.is_object() || !j.contains("M") || !j.contains("O")) throw bad("expected {\"M\": ..., \"O\": ...}");
    return X{decode<T, MatX<T>>(j["M"], what + ".M", values), decode<T, MatX<T>>(j["O"], what + ".O", values)};
  } else if constexpr (std::is_same_v<X, int>) {
    if (!j.is_number_integer()) throw bad("expected an integer");
    return j.get<int>();
  } else if constexpr (std::is_same_v<X, LieAlgebraId>) {
    const std::string s = j.is_string() ? j.get<std::string>() : "";
    if (s == "so3") return LieAlgebraId::so3;
    if (s == "so4") return LieAlgebraId::so4;
    if (s == "sl2") return LieAlgebraId::sl2;
    throw bad("expected \"so3\", \"so4\" or \"sl2\"");
  } else {
    static_assert(sizeof(X) == 0, "no protocol decoding for this type");
  }
}

// A state in the declared form `f`: the object must hold the form's two keys ("q" and "omega", ...).
// Only a step returns one, so NaN and the infinities pass (Values::any).
template <class T>
EngineState<T> decode_engine_state(const json& j, const StateForm& f, const std::string& what) {
  constexpr Values any = Values::any;
  const char* a = attitude_key(f.attitude);
  const char* w = angular_key(f.angular);
  if (!j.is_object() || !j.contains(a) || !j.contains(w))
    throw ProtocolValueError(what + ": expected {\"" + a + "\": ..., \"" + w + "\": ...}, the declared state '" +
                             state_form_words(f) + "'; got " + j.dump().substr(0, 120));
  EngineState<T> u = to_declared<T>(f, Vec3<T>::Ones(), Mat3<T>::Identity(), Vec3<T>::Zero());
  if (f.has_quaternion())
    u.q = decode<T, Vec4<T>>(j[a], what + ".q", any);
  else
    u.O = decode<T, Mat3<T>>(j[a], what + ".O", any);
  u.angular() = decode<T, Vec3<T>>(j[w], what + "." + w, any);
  return u;
}

}  // namespace gm::protocol
