#include "harness/remote/slot_names.hpp"

#include "core/subject.hpp"

#include <algorithm>
#include <cctype>
#include <set>

namespace gm::harness {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Levenshtein distance, ignoring underscores' absence ("euler38" vs "euler_3_8" is 2).
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

// Words students use for a slot, by concept (the index printed by `geomech slots --concepts`).
const std::vector<std::pair<const char*, const char*>>& aliases() {
  static const std::vector<std::pair<const char*, const char*>> a = {
      {"energy", "hamiltonian_3_4"},
      {"hamiltonian", "hamiltonian_3_4"},
      {"kinetic_energy", "lagrangian_2_5"},
      {"lagrangian", "lagrangian_2_5"},
      {"euler", "euler_3_8"},
      {"euler_equations", "euler_3_8"},
      {"euler_rhs", "euler_3_8"},
      {"rhs", "euler_3_8"},
      {"vector_field", "euler_3_8"},
      {"pi_dot", "euler_3_8"},
      {"dpi_dt", "euler_3_8"},
      {"omega_dot", "euler_2_1"},
      {"omega", "omega_3_5"},
      {"angular_velocity", "omega_3_5"},
      {"legendre", "legendre_3_1"},
      {"body_momentum", "legendre_3_1"},
      {"angular_momentum", "legendre_3_1"},
      {"casimir_function", "casimir"},
      {"c", "casimir"},
      {"reconstruction", "reconstruction_2_10"},
      {"attitude", "reconstruction_2_10"},
      {"o_dot", "reconstruction_2_10"},
      {"do_dt", "reconstruction_2_10"},
      {"spatial_angular_momentum", "spatial_momentum"},
      {"noether", "spatial_momentum"},
      {"j", "momentum_map"},
      {"hat_map", "hat"},
      {"skew", "hat"},
      {"vee_map", "vee"},
      {"unhat", "vee"},
      {"lie_poisson", "lie_poisson_3_6"},
      {"poisson_bracket", "lie_poisson_3_6"},
      {"bracket", "lie_poisson_3_6"},
      {"nambu", "nambu_3_13"},
      {"nambu_bracket", "nambu_3_13"},
      {"clebsch", "clebsch_3_21"},
      {"inertia", "inertia_tensor_2_3"},
      {"inertia_tensor", "inertia_tensor_2_3"},
      {"manakov", "manakov_2_34"},
      {"coadjoint", "ad_star"},
      {"trace_pairing", "pairing"},
      {"inner_product", "pairing"},
  };
  return a;
}

const SlotInfo* slot_named(const std::string& name) {
  for (const auto& s : subject_slots())
    if (name == s.name) return &s;
  return nullptr;
}

}  // namespace

const std::vector<SlotConcept>& slot_concepts() {
  static const std::vector<SlotConcept> c = {
      {"the hat map so(3) <-> R^3", "hat, vee"},
      {"the trace pairing", "pairing"},
      {"Euler's equations for Pi", "euler_3_8 (vector), euler_3_7 (components), euler_matrix_2_12 (matrix)"},
      {"Euler's equations for Omega", "euler_2_2 (vector), euler_2_1 (components)"},
      {"kinetic energy (Lagrangian)", "lagrangian_2_5, lagrangian_2_13"},
      {"energy (Hamiltonian)", "hamiltonian_3_4, hamiltonian_3_3, hamiltonian_2_21"},
      {"angular velocity from momentum", "omega_3_5"},
      {"body angular momentum from velocity", "legendre_3_1"},
      {"Casimir |Pi|^2/2", "casimir"},
      {"reconstruction of the attitude", "reconstruction_2_10"},
      {"spatial angular momentum (Noether)", "spatial_momentum"},
      {"the momentum map J = p x q", "momentum_map"},
      {"Lie-Poisson bracket", "lie_poisson_3_6 (vectors), lie_poisson_2_23 (matrices)"},
      {"Nambu bracket and motion", "nambu_3_13, nambu_motion_3_14"},
      {"Clebsch variables", "clebsch_3_21"},
      {"Manakov's SO(n) body", "manakov_M, manakov_Omega, manakov_2_34, manakov_lagrangian, manakov_clebsch_3_23"},
      {"an integrator",
       "rigid_body_step, manakov_step, clebsch_step, manakov_clebsch_step (in a struct with a name and claims)"},
  };
  return c;
}

std::string closest_claim(const std::string& key, const std::vector<std::string>& known) {
  const std::string low = lower(key);
  std::string best;
  std::size_t best_d = 4;
  for (const auto& k : known) {
    const std::size_t d = distance(low, k);
    const bool prefix = k.size() >= 4 && (low.rfind(k.substr(0, 4), 0) == 0);  // "symmetry" for "symmetric"
    if ((d < best_d && d * 3 <= k.size()) || (prefix && best.empty())) {
      best = k;
      best_d = d;
    }
  }
  return best;
}

std::vector<std::string> slot_name_list() {
  std::vector<std::string> out;
  for (const auto& s : subject_slots()) out.push_back(s.name);
  return out;
}

std::vector<std::string> claim_name_list() {
  std::vector<std::string> out{"order"};
  for (const auto& c : kBooleanClaims) out.push_back(c.name);
  return out;
}

std::string did_you_mean(const std::string& name, const std::vector<std::string>& known) {
  const std::string low = lower(name);
  std::size_t best = std::max<std::size_t>(1, (low.size() + 2) / 3);  // at most a third of the name wrong
  std::vector<std::string> closest;
  for (const auto& k : known) {
    const std::size_t d = distance(low, lower(k));
    if (d > best) continue;
    if (d < best) best = d, closest.clear();
    closest.push_back(k);
  }
  if (closest.empty()) return "";
  std::string out = " (did you mean ";
  for (std::size_t i = 0; i < closest.size(); ++i)
    out += (i == 0 ? "" : i + 1 == closest.size() ? " or " : ", ") + ("\"" + closest[i] + "\"");
  return out + "?)";
}

std::vector<std::string> slot_name_advice(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  static const std::set<std::string> not_slots = {
      "rigid_body_step", "manakov_step", "clebsch_step", "manakov_clebsch_step", "main", "name",
      "claims",          "description",  "operator"};
  for (const auto& name : names) {
    if (is_slot_name(name) || not_slots.count(name)) continue;
    const std::string low = lower(name);
    const SlotInfo* guess = nullptr;
    for (const auto& [alias, slot] : aliases())
      if (low == alias) guess = slot_named(slot);
    if (!guess && low.size() >= 4) {
      std::size_t best = 3;
      for (const auto& s : subject_slots()) {
        const std::size_t d = distance(low, s.name);
        if (d < best && d * 4 <= std::string(s.name).size()) {
          best = d;
          guess = &s;
        }
      }
    }
    if (!guess) continue;
    out.push_back("`" + name + "` is not a slot name, so nothing checks it; did you mean `" + guess->name + "` (" +
                  guess->place + ": " + guess->meaning + ")? `geomech slots` lists the names");
  }
  return out;
}

}  // namespace gm::harness
