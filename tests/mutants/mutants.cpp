#include "tests/mutants/mutants.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace gm {

static std::vector<Mutant>& mutable_mutants() {
  static std::vector<Mutant> m;
  return m;
}

void register_mutant(Mutant m) {
  auto& all = mutable_mutants();
  for (const auto& x : all)
    if (x.name == m.name) throw std::logic_error("mutant registered twice: " + m.name);
  auto pos = std::lower_bound(all.begin(), all.end(), m.name,
                              [](const Mutant& a, const std::string& n) { return a.name < n; });
  all.insert(pos, std::move(m));
}

const std::vector<Mutant>& mutants() { return mutable_mutants(); }

static std::map<std::string, std::vector<ScalarKind>>& restrictions() {
  static std::map<std::string, std::vector<ScalarKind>> r;
  return r;
}

void mutant_wrong_only_in(const std::string& name, std::vector<ScalarKind> kinds) {
  restrictions()[name] = std::move(kinds);
}

bool mutant_wrong_in(const std::string& name, ScalarKind k) {
  auto it = restrictions().find(name);
  return it == restrictions().end() || std::find(it->second.begin(), it->second.end(), k) != it->second.end();
}

const Mutant* find_mutant(std::string_view name) {
  for (const auto& m : mutants())
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace gm
