// Tests for the gradebook export: scoring under a rubric, rubric and roster
// errors, and the shape of the CSV that Moodle and Canvas import.
#include "harness/class/gradebook.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <locale>
#include <stdexcept>

using namespace gm::harness;

namespace {

StudentResult checked(std::string name, std::vector<std::string> provided, std::vector<std::string> wrong = {}) {
  StudentResult s;
  s.name = std::move(name);
  s.status = "checked";
  s.provided = std::move(provided);
  s.wrong = std::move(wrong);
  s.report = s.name + "/report.md";
  return s;
}

// The message of the runtime_error `f` throws, or "" when it does not throw.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// What a gradebook file must look like for an LMS import: parseable RFC 4180,
// CRLF only, no BOM, the expected header, every row as wide as the header.
void ExpectWellFormedGradebook(const std::string& csv, const std::vector<std::string>& header) {
  if (csv.substr(0, 3) == "\xEF\xBB\xBF") {
    ADD_FAILURE() << "BOM present";
    return;
  }
  for (std::size_t i = 0; i < csv.size(); ++i)
    if (csv[i] == '\n' && (i == 0 || csv[i - 1] != '\r')) {
      // A line feed inside a quoted field is data, so only count those outside quotes.
      std::size_t quotes = 0;
      for (std::size_t j = 0; j < i; ++j) quotes += csv[j] == '"';
      if (quotes % 2 == 0) ADD_FAILURE() << "bare LF line end at byte " << i;
    }
  std::vector<std::vector<std::string>> rows;
  try {
    rows = parse_csv(csv);
  } catch (const std::runtime_error& e) {
    ADD_FAILURE() << "malformed CSV: " << e.what();
    return;
  }
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0], header);
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_EQ(rows[i].size(), header.size()) << "row " << i + 1 << " is ragged";
}

}  // namespace

TEST(Gradebook, DefaultRubricGivesPartialCreditPerCorrectSlot) {
  const std::vector<StudentResult> cls = {
      checked("alice", {"hamiltonian_3_4", "omega_3_5", "legendre_3_1", "reconstruction_2_10"},
              {"reconstruction_2_10"}),
      checked("bob", {"hamiltonian_3_4", "omega_3_5"})};
  const Rubric r;  // the default rubric
  const auto assignment = resolve_assignment(r, cls);
  EXPECT_EQ(assignment,
            (std::vector<std::string>{"hamiltonian_3_4", "legendre_3_1", "omega_3_5", "reconstruction_2_10"}));
  EXPECT_EQ(format_points(score_student(cls[0], r, assignment).points), "75.00");
  EXPECT_EQ(format_points(score_student(cls[1], r, assignment).points), "50.00");
  EXPECT_EQ(score_student(cls[0], r, assignment).breakdown, (std::vector<std::string>{"slots 3/4"}));
}

TEST(Gradebook, SlotsOutsideTheAssignmentEarnNothing) {
  const Rubric r = parse_rubric(R"({"assignment": ["hamiltonian_3_4", "omega_3_5", "legendre_3_1"]})", "week2.json");
  const auto s = checked("alice", {"hamiltonian_3_4", "omega_3_5", "casimir"});
  const auto score = score_student(s, r, resolve_assignment(r, {s}));
  EXPECT_EQ(format_points(score.points), "66.67");  // 2 of 3, rounded to 2 decimals
  EXPECT_NE(score.feedback.find("missing: legendre_3_1"), std::string::npos) << score.feedback;
}

TEST(Gradebook, SlotWeightsChangeEachSlotsShare) {
  const Rubric r = parse_rubric(R"({"points": 10, "assignment": ["hamiltonian_3_4", "omega_3_5", "legendre_3_1"],
                                    "slots": {"default": 1, "hamiltonian_3_4": 2}})",
                                "w.json");
  // Max weight 4: H (2) correct and omega (1) correct -> 3/4 of 10 points.
  EXPECT_EQ(format_points(score_student(checked("a", {"hamiltonian_3_4", "omega_3_5"}), r, *r.assignment).points),
            "7.50");
  // A wrong slot earns nothing even when provided.
  EXPECT_EQ(format_points(
                score_student(checked("b", {"hamiltonian_3_4", "legendre_3_1"}, {"hamiltonian_3_4"}), r, *r.assignment)
                    .points),
            "2.50");
}

TEST(Gradebook, AreaWeightsPayTheFractionOfChecksPassed) {
  const Rubric r = parse_rubric(R"({"assignment": ["hamiltonian_3_4"], "slots": {"default": 0},
                                    "areas": {"sec. 1": 3, "momentum maps": 1}})",
                                "areas.json");
  auto s = checked("a", {"hamiltonian_3_4"});
  s.areas["sec. 1"] = {5, 10};        // 3 * 0.5
  s.areas["momentum maps"] = {4, 4};  // 1 * 1
  s.areas["sec. 2"] = {0, 9};         // weight 0: ignored
  const auto score = score_student(s, r, *r.assignment);
  EXPECT_EQ(format_points(score.points), "62.50");  // 2.5 of 4
  EXPECT_EQ(score.breakdown, (std::vector<std::string>{"momentum maps 4/4", "sec. 1 5/10"}));
  // An area with no checks run gives no credit rather than dividing by zero.
  EXPECT_EQ(format_points(score_student(checked("b", {"hamiltonian_3_4"}), r, *r.assignment).points), "0.00");
}

TEST(Gradebook, ClaimCreditIsVerifiedWeightOverClaimsMade) {
  const Rubric r = parse_rubric(R"({"assignment": ["hamiltonian_3_4"], "claims_weight": 1,
                                    "claims": {"default": 1, "order": 2}})",
                                "claims.json");
  auto s = checked("a", {"hamiltonian_3_4"});
  s.claims = {{"midpoint", "order", "verified"},      // 2 of 2
              {"midpoint", "energy", "FALSE CLAIM"},  // 0 of 1
              {"euler", "symmetric", "UNCHECKED"},    // 0 of 1
              {"euler", "casimir", "not claimed"}};   // not a claim: not counted
  const auto score = score_student(s, r, *r.assignment);
  // Slot 1 of 1 plus claims 1 * 2/4: 1.5 of 2.
  EXPECT_EQ(format_points(score.points), "75.00");
  EXPECT_EQ(score.breakdown.back(), "claims 1/3 verified");
  EXPECT_NE(score.feedback.find("false claims: midpoint energy"), std::string::npos) << score.feedback;
}

TEST(Gradebook, StudentWhoMakesNoClaimsEarnsNoClaimCredit) {
  const Rubric r = parse_rubric(R"({"assignment": ["hamiltonian_3_4"], "claims_weight": 1})", "c.json");
  EXPECT_EQ(format_points(score_student(checked("a", {"hamiltonian_3_4"}), r, *r.assignment).points), "50.00");
}

TEST(Gradebook, StudentThatDoesNotCompileScoresZeroWithTheReason) {
  StudentResult s = checked("carol", {"hamiltonian_3_4", "omega_3_5"});
  s.status = "does not compile";
  s.first_fix = "rigid_body.cpp:12: missing ';'\nand more";
  const std::vector<StudentResult> cls = {s, checked("dave", {"hamiltonian_3_4", "omega_3_5"})};
  const auto score = score_student(s, Rubric{}, resolve_assignment(Rubric{}, cls));
  EXPECT_EQ(format_points(score.points), "0.00");
  EXPECT_EQ(
      score.feedback,
      "0.00 of 100: does not compile; fix first: rigid_body.cpp:12: missing ';' and more; report: carol/report.md");
  const auto rows = parse_csv(write_gradebook_csv(cls, Rubric{}));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][4], "0.00");
  EXPECT_EQ(rows[1][5], score.feedback);
}

TEST(Gradebook, CsvQuotesANameWithACommaAndAQuote) {
  const std::string name = "O'Neil, \"Ace\"";
  const std::string csv = write_gradebook_csv({checked(name, {"hamiltonian_3_4"})}, Rubric{});
  EXPECT_NE(csv.find("\r\n\"O'Neil, \"\"Ace\"\"\",\"O'Neil, \"\"Ace\"\"\",,,100.00,"), std::string::npos) << csv;
  ExpectWellFormedGradebook(csv, gradebook_header(Rubric{}));
  EXPECT_EQ(parse_csv(csv)[1][0], name);
  EXPECT_EQ(csv_field("plain"), "plain");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
}

TEST(Gradebook, MoodleHeaderIsExact) {
  const Rubric r = parse_rubric(R"({"item": "Week 2: Euler, Poinsot"})", "m.json");
  const std::string csv = write_gradebook_csv({checked("alice", {"hamiltonian_3_4"})}, r);
  EXPECT_EQ(csv.substr(0, csv.find("\r\n")),
            "Implementation,Username,Email address,ID number,\"Week 2: Euler, Poinsot\",Feedback");
  const Rubric quiet = parse_rubric(R"({"feedback": false})", "q.json");
  EXPECT_EQ(gradebook_header(quiet),
            (std::vector<std::string>{"Implementation", "Username", "Email address", "ID number", "geomech"}));
}

TEST(Gradebook, CanvasHeaderAndPointsPossibleRowAreExact) {
  const Rubric r = parse_rubric(R"j({"format": "canvas", "item": "Rigid body (4521)", "points": 20})j", "c.json");
  const std::string csv = write_gradebook_csv(
      {checked("bob", {"hamiltonian_3_4", "legendre_3_1"}, {"legendre_3_1"}), checked("alice", {"hamiltonian_3_4"})},
      r);
  EXPECT_EQ(csv,
            "Student,ID,SIS User ID,SIS Login ID,Section,Rigid body (4521)\r\n"
            "Points Possible,,,,,20.00\r\n"
            "alice,,,,,10.00\r\n"
            "bob,,,,,10.00\r\n");
  ExpectWellFormedGradebook(csv, gradebook_header(r));
}

TEST(Gradebook, RowsAreSortedAndNumbersIgnoreTheLocale) {
  // A global locale with a decimal comma must not leak into the file.
  struct Comma : std::numpunct<char> {
    char do_decimal_point() const override { return ','; }
  };
  const std::locale saved = std::locale::global(std::locale(std::locale::classic(), new Comma));
  const std::string csv = write_gradebook_csv(
      {checked("zoe", {"a", "b", "c"}, {"c"}), checked("Bea", {"a"}), checked("adam", {})}, Rubric{});
  std::locale::global(saved);
  const auto rows = parse_csv(csv);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[1][0], "Bea");  // byte order: upper case sorts first, on every machine
  EXPECT_EQ(rows[2][0], "adam");
  EXPECT_EQ(rows[3][0], "zoe");
  EXPECT_EQ(rows[1][4], "33.33");
  EXPECT_EQ(rows[2][4], "0.00");
  EXPECT_EQ(rows[3][4], "66.67");
  EXPECT_EQ(format_points(1.005), "1.00");  // same binary double everywhere, same digits
  EXPECT_EQ(format_points(12.5), "12.50");
}

TEST(Gradebook, FeedbackIsOneShortLine) {
  std::vector<std::string> many;
  for (int i = 0; i < 40; ++i) many.push_back("slot_with_a_long_name_" + std::to_string(i));
  auto s = checked("a", many, many);
  s.first_fix = std::string(500, 'x') + "\r\n\tend";
  const auto score = score_student(s, Rubric{}, many);
  EXPECT_LE(score.feedback.size(), 400u);
  EXPECT_EQ(score.feedback.find_first_of("\r\n\t"), std::string::npos);
  EXPECT_NE(score.feedback.find("+35 more"), std::string::npos) << score.feedback;
  // Cut in the middle: the grade at the start, the first fix's beginning and end, the
  // report's path at the end.
  EXPECT_EQ(score.feedback.rfind("0.00 of 100: 0 of 40 slots correct; wrong: ", 0), 0u) << score.feedback;
  EXPECT_NE(score.feedback.find("fix first: xxx"), std::string::npos) << score.feedback;
  EXPECT_NE(score.feedback.find("x ... x"), std::string::npos) << score.feedback;
  const std::string end = "xxx end; report: a/report.md";
  EXPECT_EQ(score.feedback.substr(score.feedback.size() - end.size()), end) << score.feedback;
}

// The cut never splits a quoted name ("'manakov ..." lost the function's name): wherever
// the cut falls in a first fix, its quotes stay paired, and a name cut into is kept whole.
TEST(Gradebook, TheFeedbackCutKeepsAFunctionsName) {
  const std::vector<std::string> slots = {"manakov_Omega"};
  int whole = 0;
  for (int pad = 0; pad < 200; pad += 3) {
    auto s = checked("dave", slots, slots);
    s.first_fix =
        std::string(pad, 'w') +
        " Octave function 'manakov_Omega' in dave/manakov_Omega.m is wrong: at Pi = " + std::string(300, '9') +
        " it returns the transpose";
    const std::string f = score_student(s, Rubric{}, slots).feedback;
    EXPECT_LE(f.size(), 400u);
    EXPECT_EQ(std::count(f.begin(), f.end(), '\''), f.find("'manakov_Omega'") == std::string::npos ? 0 : 2)
        << "pad " << pad << ": " << f;
    whole += f.find("function 'manakov_Omega'") != std::string::npos;
  }
  EXPECT_GT(whole, 0);  // the name is kept where the cut reaches it
}

// "slots 11/12" beside a weighted 92.31 read as a mistake. The feedback says the grade, the
// count and the weight together, and the weight of what is wrong.
TEST(Gradebook, FeedbackSaysCountsAndWeightsTogether) {
  const Rubric r =
      parse_rubric(R"({"assignment": ["hat", "vee", "casimir", "euler_3_8"], "slots": {"euler_3_8": 2}})", "w.json");
  auto s = checked("bob", {"hat", "vee", "casimir", "euler_3_8"}, {"casimir"});
  s.first_fix = "Python function 'casimir' in bob.py is wrong: its own check definition_casimir fails";
  const auto score = score_student(s, r, *r.assignment);
  EXPECT_EQ(format_points(score.points), "80.00");
  EXPECT_EQ(score.feedback,
            "80.00 of 100: 3 of 4 slots correct (weight 4 of 5); wrong: casimir (weight 1); fix first: "
            "Python function 'casimir' in bob.py is wrong: its own check definition_casimir fails; "
            "report: bob/report.md");
  // Its items are the grade, part by part: each slot with its weight in points.
  ASSERT_EQ(score.items.size(), 4u);
  double sum = 0;
  for (const auto& i : score.items) sum += i.points;
  EXPECT_NEAR(sum, 80.0, 1e-9);
  EXPECT_EQ(score.items[2].name, "casimir");
  EXPECT_EQ(score.items[2].state, "wrong");
  EXPECT_NEAR(score.items[3].max_points, 40.0, 1e-9);  // euler_3_8, weight 2 of 5
  // With equal weights the counts alone say it.
  const Rubric plain = parse_rubric(R"({"assignment": ["hat", "vee", "casimir", "euler_3_8"]})", "p.json");
  EXPECT_EQ(score_student(s, plain, *plain.assignment).feedback.substr(0, 58),
            "75.00 of 100: 3 of 4 slots correct; wrong: casimir; fix fi");
}

TEST(Gradebook, RosterMapsImplementationNamesToLmsIdentifiers) {
  const Roster roster = parse_roster(
      "\xEF\xBB\xBFname,username,email,id_number,canvas_id,sis_user_id,sis_login_id,section,full_name\n"
      "alice,asmith,alice@uni.example,S001,1042,SIS-1,asmith,Mon lab,\"Smith, Alice\"\n"
      "ghost,g,g@uni.example,S999,,,,,\n",
      "roster.csv");
  const std::vector<StudentResult> cls = {checked("alice", {"hamiltonian_3_4"}), checked("bob", {"hamiltonian_3_4"})};
  EXPECT_EQ(parse_csv(write_gradebook_csv(cls, Rubric{}, roster)),
            (std::vector<std::vector<std::string>>{
                gradebook_header(Rubric{}),
                {"alice", "asmith", "alice@uni.example", "S001", "100.00",
                 "100.00 of 100: 1 of 1 slot correct; report: alice/report.md"},
                {"bob", "bob", "", "", "100.00", "100.00 of 100: 1 of 1 slot correct; report: bob/report.md"}}));
  Rubric canvas;
  canvas.format = LmsFormat::canvas;
  const auto rows = parse_csv(write_gradebook_csv(cls, canvas, roster));
  EXPECT_EQ(rows[2], (std::vector<std::string>{"Smith, Alice", "1042", "SIS-1", "asmith", "Mon lab", "100.00"}));
  EXPECT_EQ(rows[3], (std::vector<std::string>{"bob", "", "", "", "", "100.00"}));
  EXPECT_EQ(roster_warnings(cls, roster),
            (std::vector<std::string>{"\"bob\" has no roster row; its name is used as identifier",
                                      "roster row \"ghost\" matches no implementation in the class"}));
}

TEST(Gradebook, RosterErrorsNameTheFileAndTheProblem) {
  EXPECT_EQ(error_of([] { parse_roster("name,user\nalice,a\n", "r.csv"); }),
            "roster \"r.csv\": unknown column \"user\"; expected name, full_name, username, email, id_number, "
            "canvas_id, sis_user_id, sis_login_id, section");
  EXPECT_EQ(error_of([] { parse_roster("username\na\n", "r.csv"); }), "roster \"r.csv\": no \"name\" column");
  EXPECT_EQ(error_of([] { parse_roster("name\nalice\nalice\n", "r.csv"); }),
            "roster \"r.csv\": name \"alice\" appears twice");
  EXPECT_EQ(error_of([] { parse_roster("name,email\nalice\n", "r.csv"); }),
            "roster \"r.csv\": row 2 has 1 fields, header has 2");
  EXPECT_EQ(error_of([] { parse_roster("name\n\"alice\n", "r.csv"); }),
            "roster \"r.csv\": CSV line 2: unbalanced quote");
}

TEST(Gradebook, RubricErrorsNameTheFileAndTheKey) {
  const auto err = [](const char* json) { return error_of([&] { parse_rubric(json, "rubric.json"); }); };
  EXPECT_EQ(err(R"({"pionts": 10})"),
            "rubric \"rubric.json\": key \"pionts\": unknown key; expected item, points, format, feedback, slots, "
            "assignment, areas, claims_weight, claims or visibility");
  EXPECT_EQ(err(R"({"slots": {"hamiltonian_3_4": -1}})"),
            "rubric \"rubric.json\": key \"slots.hamiltonian_3_4\": expected a number >= 0, got -1");
  EXPECT_EQ(err(R"({"claims": {"order": "two"}})"),
            "rubric \"rubric.json\": key \"claims.order\": expected a number >= 0, got \"two\"");
  EXPECT_EQ(err(R"({"points": true})"), "rubric \"rubric.json\": key \"points\": expected a number > 0, got true");
  EXPECT_EQ(err(R"({"points": 0})"), "rubric \"rubric.json\": key \"points\": expected a number > 0, got 0");
  EXPECT_EQ(err(R"({"assignment": []})"),
            "rubric \"rubric.json\": key \"assignment\": expected a non-empty list of slot names");
  EXPECT_EQ(err(R"({"assignment": ["hamiltonian_3_4", "hamiltonian_3_4"]})"),
            "rubric \"rubric.json\": key \"assignment\": slot \"hamiltonian_3_4\" is listed twice");
  EXPECT_EQ(err(R"({"format": "blackboard"})"),
            "rubric \"rubric.json\": key \"format\": expected \"moodle\" or \"canvas\", got \"blackboard\"");
  EXPECT_EQ(err(R"({"areas": {"sec 1": 2}})"),
            "rubric \"rubric.json\": key \"areas.sec 1\": unknown area; expected one of \"sec. 1\", \"sec. 2\", "
            "\"sec. 3\", \"momentum maps\", \"integrators\"");
  EXPECT_EQ(err(R"({"slots": {"default": 0}})"),
            "rubric \"rubric.json\": key \"slots\": the weights make the maximum grade 0; give a slot, an area or "
            "claims_weight a positive weight");
  EXPECT_EQ(err(R"({"assignment": ["hamiltonian_3_4"], "slots": {"hamiltonian_3_4": 0}})"),
            "rubric \"rubric.json\": key \"assignment\": the weights make the maximum grade 0; give a slot, an area "
            "or claims_weight a positive weight");
  EXPECT_EQ(err(R"({"format": "canvas", "item": "Final Score"})"),
            "rubric \"rubric.json\": key \"item\": Canvas would not read a column named \"Final Score\" as an "
            "assignment");
  EXPECT_EQ(err(R"({"format": "canvas", "item": "Section"})"),
            "rubric \"rubric.json\": key \"item\": \"Section\" clashes with a fixed column name");
  EXPECT_EQ(err(R"({"format": "canvas", "item": "Student projects"})"), "");  // only exact names clash
  EXPECT_EQ(err(R"({"item": "Feedback"})"),
            "rubric \"rubric.json\": key \"item\": \"Feedback\" clashes with a fixed column name");
  EXPECT_EQ(err("[1]"), "rubric \"rubric.json\": key \"(top level)\": expected a JSON object");
  EXPECT_EQ(err("{\"item\": ").rfind("rubric \"rubric.json\": not valid JSON: ", 0), 0u);
  // A valid rubric parses to what it says.
  const Rubric ok = parse_rubric(R"({"item": "W3", "points": 20, "slots": {"default": 2, "hamiltonian_3_4": 1},
                                     "areas": {"integrators": 4}, "claims_weight": 5, "claims": {"order": 3}})",
                                 "rubric.json");
  EXPECT_EQ(ok.item, "W3");
  EXPECT_EQ(ok.points, 20);
  EXPECT_EQ(ok.slot_default, 2);
  EXPECT_EQ(ok.slot_weights.at("hamiltonian_3_4"), 1);
  EXPECT_EQ(ok.area_weights.at("integrators"), 4);
  EXPECT_EQ(ok.claims_weight, 5);
  EXPECT_EQ(ok.claim_weights.at("order"), 3);
  EXPECT_FALSE(ok.assignment.has_value());
}

// A misspelt slot in the assignment was accepted, and every correct student lost its share
// (92.31 for 12 of 13). Every name written by hand is checked against the slot table and the claim
// names, with the closest names offered.
TEST(Gradebook, UnknownSlotOrClaimInARubricIsRefusedWithDidYouMean) {
  const auto err = [](const char* json) { return error_of([&] { parse_rubric(json, "week3.json"); }); };
  EXPECT_EQ(err(R"({"assignment": ["hat", "casimr"]})"),
            "rubric \"week3.json\": key \"assignment\": unknown slot \"casimr\" (did you mean \"casimir\"?); "
            "`geomech slots` lists the slot names");
  EXPECT_EQ(err(R"({"slots": {"default": 1, "Euler_3_8": 2}})"),
            "rubric \"week3.json\": key \"slots.Euler_3_8\": unknown slot \"Euler_3_8\" (did you mean \"euler_3_8\"?); "
            "`geomech slots` lists the slot names");
  EXPECT_EQ(err(R"({"assignment": ["euler_3_9"]})"),
            "rubric \"week3.json\": key \"assignment\": unknown slot \"euler_3_9\" (did you mean \"euler_3_7\" or "
            "\"euler_3_8\"?); `geomech slots` lists the slot names");
  EXPECT_EQ(err(R"({"assignment": ["H"]})"),
            "rubric \"week3.json\": key \"assignment\": unknown slot \"H\"; `geomech slots` lists the slot names");
  EXPECT_EQ(err(R"({"assignment": ["hat", "rigid_body_step"]})"),
            "rubric \"week3.json\": key \"assignment\": \"rigid_body_step\" is an integrator's step, not a slot: an "
            "integrator earns credit by its claims (claims_weight, claims) and in the area \"integrators\"");
  EXPECT_EQ(err(R"({"claims_weight": 1, "claims": {"symetric": 2}})"),
            "rubric \"week3.json\": key \"claims.symetric\": unknown claim \"symetric\" (did you mean \"symmetric\"?); "
            "the claims are order, symmetric, casimir, energy, orthogonality, spectrum, poisson, noether, equivariant, "
            "bounded_energy, symplectic, unit_quaternion");
  // The control: the same rubrics with the names spelt right are read.
  EXPECT_EQ(err(R"({"assignment": ["hat", "casimir"], "slots": {"default": 1, "euler_3_8": 2},
                    "claims_weight": 1, "claims": {"symmetric": 2, "default": 1}})"),
            "");
}

TEST(Gradebook, ZeroMaximumForTheClassIsAnError) {
  // Nobody provides a slot and nothing else is weighted: there is nothing to grade.
  StudentResult s = checked("a", {});
  s.status = "does not compile";
  EXPECT_NE(error_of([&] { write_gradebook_csv({s}, Rubric{}); }).find("maximum grade is 0 for this class"),
            std::string::npos);
  EXPECT_EQ(error_of([] {
              write_gradebook_csv({checked("a", {"hamiltonian_3_4"}), checked("a", {})}, Rubric{});
            }),
            "gradebook: implementation name \"a\" appears twice");
}

TEST(Gradebook, OutputIsUtf8WithoutBomAndCrlfLineEnds) {
  const std::string csv =
      write_gradebook_csv({checked("Åsa", {"hamiltonian_3_4"}), checked("bo", {"hamiltonian_3_4"})}, Rubric{});
  ExpectWellFormedGradebook(csv, gradebook_header(Rubric{}));
  EXPECT_EQ(csv.rfind("\r\n"), csv.size() - 2);     // the last record ends with a line break too
  EXPECT_EQ(csv.find(",\r\n"), std::string::npos);  // no trailing separators
}

// Negative control: the shape check above must fail on malformed files, or
// its passing would prove nothing.
TEST(Gradebook, ShapeCheckRejectsMalformedCsv) {
  const std::vector<std::string> header = {"a", "b"};
  EXPECT_THROW(parse_csv("a,b\r\n\"unbalanced,1\r\n"), std::runtime_error);
  EXPECT_THROW(parse_csv("a,b\r\nx\"y,1\r\n"), std::runtime_error);
  EXPECT_THROW(parse_csv("a,b\r\n\"x\"y,1\r\n"), std::runtime_error);
  EXPECT_THROW(parse_csv("a,b\r1,2\r\n"), std::runtime_error);
  EXPECT_NONFATAL_FAILURE(ExpectWellFormedGradebook("a,b\r\n\"unbalanced,1\r\n", header), "malformed CSV");
  EXPECT_NONFATAL_FAILURE(ExpectWellFormedGradebook("a,b\r\n1,2,3\r\n", header), "ragged");
  EXPECT_NONFATAL_FAILURE(ExpectWellFormedGradebook("a,b\r\n1,2\n", header), "bare LF");
  EXPECT_NONFATAL_FAILURE(ExpectWellFormedGradebook("\xEF\xBB\xBF"
                                                    "a,b\r\n1,2\r\n",
                                                    header),
                          "BOM");
  ExpectWellFormedGradebook("a,b\r\n\"1\n2\",3\r\n", header);  // a quoted line feed is data: fine
}
