// The replies of an implementation behind the protocol, kept per process so that a call repeated
// with the same arguments is answered from memory instead of by another round trip.
//
// The slots are functions of their arguments (the notes' maps: hat, ad*, the Lagrangians, an
// integrator's step), and the properties often ask the same value again: a finite difference
// evaluates l(xi + e eta) at eight e with the same hat(eta), a flow's error estimate repeats its
// first stage. Measured on examples/students/correct.m (2026-11-26), half of the calls of the six
// costliest double checks repeated an earlier call exactly, up to 12 in 13 in
// matrix_euler_poincare_any_lagrangian_so_n.
//
// A slot that is not a function of its arguments (a persistent or global variable, a random
// draw) would be hidden by the memory, so one repeat in every `kRecheckEvery` is asked again and
// compared; a different answer is an error naming the slot and both answers.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <unordered_map>

namespace gm::protocol {

class CallMemo {
 public:
  static constexpr long kRecheckEvery = 64;
  // Then it starts afresh: a reply of a 3x3 matrix and its key take about 1.3 kB, so some 40 MB at most.
  static constexpr std::size_t kMaxEntries = 32768;

  // The reply remembered for `key`, or nothing; `recheck` is set when this repeat should be asked
  // again and compared (`compare`).
  const nlohmann::json* find(const std::string& key, bool* recheck);
  void remember(const std::string& key, const nlohmann::json& result);
  // Empty when `now` is the remembered reply; otherwise what was asked twice and the two answers.
  static std::string compare(const nlohmann::json& before, const nlohmann::json& now);

  long hits() const { return hits_; }
  long misses() const { return misses_; }

 private:
  std::unordered_map<std::string, nlohmann::json> replies_;
  long hits_ = 0, misses_ = 0;
};

}  // namespace gm::protocol
