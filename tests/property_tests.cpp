// The ctest wiring of the properties: for every registered property and every scalar it runs in,
//   reference.<scalar>.<property>            -- the reference subject must PASS;
//   negative.<scalar>.<property>__<mutant>   -- each of the property's negative controls must FAIL.
// Labels: the scalar (double, mp50, exact), the spec kind (algebraic, dynamic, variational), the
// section (s1, s2, s3, mm), "reference" or "negative-control", and the spec entry id.
#include "impl/reference_subject.hpp"
#include "properties/runner.hpp"
#include "spec/catalogue.hpp"
#include "tests/mutants/mutants.hpp"
#include "tests/support/ctest_script.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <map>
#include <stdexcept>

namespace gm {
namespace {

const Catalogue* catalogue_or_null() {
  static const Catalogue* c = []() -> const Catalogue* {
    try {
      return new Catalogue(load_catalogue(default_catalogue_path()));
    } catch (const std::exception& e) {
      std::cerr << "geomech: " << e.what() << "\n";
      return nullptr;
    }
  }();
  return c;
}

ScalarKind kind_of(const std::string& scalar) {
  if (scalar == "double") return ScalarKind::Double;
  if (scalar == "mp50") return ScalarKind::MP50;
  return ScalarKind::Exact;
}

// $GEOMECH_CASE_FACTOR multiplies the reference tests' case counts (at least one case each). The
// sanitized CI phase sets 0.25 (CMakePresets.json): it looks for memory errors and undefined
// behaviour on every code path of every property and scalar, while the full counts run unsanitized
// in the test phase. Negative controls always run their full counts: a control may need several
// cases to meet its mistake. A value that is not a positive number is an error, not ignored.
RunOptions reference_run_options() {
  RunOptions o;
  const char* f = std::getenv("GEOMECH_CASE_FACTOR");
  if (!f || !*f) return o;
  char* end = nullptr;
  const double v = std::strtod(f, &end);
  if (end == f || *end != '\0' || !(v > 0))
    throw std::invalid_argument(std::string("GEOMECH_CASE_FACTOR must be a positive number, not '") + f + "'");
  o.case_factor = v;
  return o;
}

class ReferenceTest : public ::testing::Test {
 public:
  ReferenceTest(const Property* p, ScalarKind k) : p_(p), k_(k) {}
  void TestBody() override {
    RunOptions options;
    try {
      options = reference_run_options();
    } catch (const std::exception& e) {
      FAIL() << e.what();
    }
    for (const auto& v : run_property(*p_, reference_subject(), k_, options)) {
      std::cout << format_verdict(v) << "\n";
      if (v.outcome != Outcome::Pass) ADD_FAILURE() << "the reference implementation must pass:\n" << format_verdict(v);
    }
  }

 private:
  const Property* p_;
  ScalarKind k_;
};

class NegativeControlTest : public ::testing::Test {
 public:
  NegativeControlTest(const Property* p, ScalarKind k, std::string mutant) : p_(p), k_(k), mutant_(std::move(mutant)) {}
  void TestBody() override {
    const Mutant* m = find_mutant(mutant_);
    ASSERT_NE(m, nullptr) << "negative control '" << mutant_ << "' is not a registered mutant";
    const SubjectSet subject = m->make(reference_subject());
    bool failed = false;
    // The failure is what is asserted, not its smallest case: no shrinking (in rationals it can take
    // minutes).
    RunOptions no_shrinking;
    no_shrinking.shrink = false;
    for (const auto& v : run_property(*p_, subject, k_, no_shrinking)) {
      if (v.outcome == Outcome::Fail) {
        failed = true;
        std::cout << "as it should, '" << p_->id << "' fails on '" << mutant_ << "' (" << m->description << "):\n"
                  << format_verdict(v) << "\n";
        // A failure shows its inputs by the notes' names, never as RapidCheck's list of
        // C++ types ("double = 0.5"): named in the message (showing_inputs) or drawn with a name.
        if (!v.counterexample.empty() && !inputs_in_message(v) && !counterexample_by_name(v))
          ADD_FAILURE() << "the counterexample of '" << p_->id << "' has values without a name (draw them with "
                        << "gen(...).as(\"name\") or dyn::pick(gen, \"name\"), or show them with showing_inputs):\n"
                        << format_verdict(v);
      } else if (v.outcome != Outcome::Pass) {
        ADD_FAILURE() << "negative control could not run:\n" << format_verdict(v);
      }
    }
    if (!failed)
      ADD_FAILURE() << "property '" << p_->id << "' does not fail on its negative control '" << mutant_ << "' ("
                    << m->description << "): the property checks nothing that this mistake breaks";
  }

 private:
  const Property* p_;
  ScalarKind k_;
  std::string mutant_;
};

void register_property_tests() {
  for (const auto& p : properties()) {
    for (ScalarKind k : {ScalarKind::Double, ScalarKind::MP50, ScalarKind::Exact}) {
      if (!p.runs_in(k)) continue;
      const std::string scalar = scalar_name(k);
      ::testing::RegisterTest(("reference." + scalar).c_str(), p.id.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                              [&p, k]() -> ::testing::Test* { return new ReferenceTest(&p, k); });
      for (const auto& m : p.negative_controls)
        if (mutant_wrong_in(m, k))  // a precision mistake is right in double by construction
          ::testing::RegisterTest(("negative." + scalar).c_str(), (p.id + "__" + m).c_str(), nullptr, nullptr, __FILE__,
                                  __LINE__,
                                  [&p, k, m]() -> ::testing::Test* { return new NegativeControlTest(&p, k, m); });
    }
  }
}

std::vector<std::string> labels_for(const std::string& suite, const std::string& name) {
  std::vector<std::string> labels;
  const auto dot = suite.find('.');
  if (dot == std::string::npos) {  // the machinery's own tests
    std::vector<std::string> meta = {"meta"};
    if (name.find("Reject") != std::string::npos || name.find("Malformed") != std::string::npos)
      meta.push_back("bad-input");
    return meta;
  }
  const std::string role = suite.substr(0, dot), scalar = suite.substr(dot + 1);
  labels.push_back(scalar);
  labels.push_back(role == "reference" ? "reference" : "negative-control");
  const std::string prop_id = name.substr(0, name.find("__"));
  if (const Property* p = find_property(prop_id)) {
    labels.push_back("spec=" + p->spec);
    if (const Catalogue* c = catalogue_or_null())
      if (const SpecEntry* e = c->find(p->spec)) {
        labels.push_back(e->kind);
        labels.push_back(e->section == "MM" ? "mm" : "s" + e->section);
      }
  }
  (void)kind_of;
  return labels;
}

}  // namespace
}  // namespace gm

int main(int argc, char** argv) {
  gm::register_property_tests();
  if (gm::testing_support::maybe_write_ctest_script(argc, argv, gm::labels_for)) return 0;
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
