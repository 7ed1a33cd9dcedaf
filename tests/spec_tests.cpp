// Traceability of the spec catalogue: every entry is checked, pending or a documented erratum;
// every property names an entry and has negative controls that exist; the generated table is
// current.
#include "properties/registry.hpp"
#include "spec/catalogue.hpp"
#include "tests/mutants/mutants.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

namespace gm {
namespace {

Catalogue load() { return load_catalogue(default_catalogue_path()); }

TEST(Spec, CatalogueLoads) {
  Catalogue c;
  ASSERT_NO_THROW(c = load());
  EXPECT_GE(c.entries.size(), 40u);
}

TEST(Spec, Traceable) {
  const Catalogue c = load();
  std::vector<std::string> names;
  for (const auto& m : mutants()) names.push_back(m.name);
  const auto problems = traceability_problems(c, properties(), &names);
  std::ostringstream os;
  for (const auto& p : problems) os << "  " << p << "\n";
  EXPECT_TRUE(problems.empty()) << problems.size() << " traceability problems:\n" << os.str();
}

TEST(Spec, EveryMutantIsAUsedNegativeControl) {
  std::set<std::string> used;
  for (const auto& p : properties()) used.insert(p.negative_controls.begin(), p.negative_controls.end());
  for (const auto& m : mutants())
    EXPECT_TRUE(used.count(m.name)) << "mutant '" << m.name << "' is not the negative control of any property";
}

TEST(Spec, GeneratedTableIsCurrent) {
  const Catalogue c = load();
  const std::string expected = catalogue_markdown(c, properties());
  std::string path = GM_SOURCE_DIR;  // appended, not `+`: GCC 12 at -O1 flags the temporary (a false -Warray-bounds)
  path += "/spec/CATALOGUE.md";
  std::ifstream in(path);
  std::stringstream got;
  got << in.rdbuf();
  EXPECT_EQ(got.str(), expected) << path << " is stale; regenerate it with\n"
                                 << "  build/bin/geomech catalogue --markdown > spec/CATALOGUE.md";
}

TEST(Spec, MalformedCatalogueIsRejectedWithItsName) {
  const std::string path = ::testing::TempDir() + "/bad_catalogue.json";
  {
    std::ofstream f(path);
    f << R"({"format": "geomech-spec-catalogue 1", "source": "x", "entries": [{"id": "a", "section": "1"}]})";
  }
  try {
    load_catalogue(path);
    FAIL() << "a catalogue entry without 'place' was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("entry 'a'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("place"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gm
