#include "tests/mutants/mutants.hpp"

#include <algorithm>
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

const Mutant* find_mutant(std::string_view name) {
  for (const auto& m : mutants())
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace gm
