// Traceability of the spec catalogue: every entry is checked, pending or a documented erratum;
// every property names an entry and has negative controls that exist; the generated table is
// current.
#include "properties/registry.hpp"
#include "spec/catalogue.hpp"
#include "tests/mutants/mutants.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

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

// The catalogue points at the files. Every property records the file that registers it,
// a file of a part of the notes (properties/<part>/, not support/) that exists and names the
// property's id; spec/CATALOGUE.md prints it.
TEST(Spec, EveryPropertyNamesItsFile) {
  ASSERT_FALSE(properties().empty());
  for (const auto& p : properties()) {
    SCOPED_TRACE(p.id);
    ASSERT_EQ(p.file.rfind("properties/", 0), 0u) << "recorded file: '" << p.file << "'";
    const std::size_t slash = p.file.find('/', 11);
    ASSERT_NE(slash, std::string::npos) << p.file << " is not in a folder of a part of the notes";
    EXPECT_NE(p.file.substr(11, slash - 11), "support") << p.file << " registers a property in support/";
    std::string path = GM_SOURCE_DIR;
    path += "/" + p.file;
    std::ifstream in(path);
    ASSERT_TRUE(in.good()) << path << " does not exist";
    std::stringstream text;
    text << in.rdbuf();
    // The id as a word: quoted in the registration, or the body's name where a macro makes the id
    // of it (GM_DEFINITION in properties/definitions/).
    const std::string& t = text.str();
    auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    bool named = false;
    for (std::size_t at = t.find(p.id); at != std::string::npos && !named; at = t.find(p.id, at + 1))
      named = (at == 0 || !word_char(t[at - 1])) && (at + p.id.size() == t.size() || !word_char(t[at + p.id.size()]));
    EXPECT_TRUE(named) << p.file << " does not name " << p.id;
  }
}

TEST(Spec, SourceInTreeKeepsFromTheLastPropertiesFolder) {
  EXPECT_EQ(source_in_tree("/home/a/properties/clone/properties/s3_4_nambu/nambu_bracket.cpp"),
            "properties/s3_4_nambu/nambu_bracket.cpp");
  EXPECT_EQ(source_in_tree("properties/s1_euler_poincare/so4.cpp"), "properties/s1_euler_poincare/so4.cpp");
  // controls: a folder whose name only ends in "properties", and a file outside properties/
  EXPECT_EQ(source_in_tree("/x/myproperties/a.cpp"), "/x/myproperties/a.cpp");
  EXPECT_EQ(source_in_tree("/x/tests/harness_tests.cpp"), "/x/tests/harness_tests.cpp");
}

// A property's id is its function's name, spelt once: GM_PROPERTY sets it; the control, a
// definition that spells an id of its own, is refused naming the function and its file.
TEST(Spec, APropertysIdIsItsFunctionsName) {
  const PropertyDef def = registered_as(PropertyDef{.spec = "s2.hat-map"}, "hat_is_cross_product",
                                        "/src/properties/s2_1_rigid_body/hat_map.cpp");
  EXPECT_EQ(def.id, "hat_is_cross_product");
  EXPECT_EQ(def.file, "properties/s2_1_rigid_body/hat_map.cpp");
  ASSERT_NE(find_property("hat_is_cross_product"), nullptr);
  EXPECT_EQ(find_property("hat_is_cross_product")->file, "properties/s2_1_rigid_body/hat_map.cpp");
  try {
    (void)registered_as(PropertyDef{.id = "hat_is_cross_product"}, "hat_is_cross_product", "properties/x.cpp");
    ADD_FAILURE() << "a spelt id was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("GM_PROPERTY(hat_is_cross_product, ...) in properties/x.cpp spells its id"),
              std::string::npos)
        << e.what();
  }
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
