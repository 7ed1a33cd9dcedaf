// Gradebook export: rubric parsing, scoring and RFC 4180 CSV for Moodle / Canvas.
// The LMS facts behind the column choices are documented in GRADEBOOK.md.
#include "harness/class/gradebook.hpp"

#include "harness/isolation/inert_text.hpp"
#include "harness/remote/slot_names.hpp"

#include <cctype>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace gm::harness {
namespace {

using nlohmann::json;

[[noreturn]] void rubric_error(const Rubric& r, const std::string& key, const std::string& expected) {
  throw std::runtime_error("rubric \"" + r.source + "\": key \"" + key + "\": " + expected);
}

// A weight is a finite JSON number >= 0 (JSON booleans are not numbers here).
double read_weight(const Rubric& r, const json& v, const std::string& key) {
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0)
    rubric_error(r, key, "expected a number >= 0, got " + v.dump());
  return v.get<double>();
}

// A slot name written by hand: a misspelt one would be a slot nobody provides, and every student
// would lose its share without a word ("casimr" cost every correct student 7.7 points).
void check_slot_name(const Rubric& r, const std::string& key, const std::string& name) {
  static const std::vector<std::string> slots = slot_name_list();
  if (std::find(slots.begin(), slots.end(), name) != slots.end()) return;
  static const std::vector<std::string> steps = {"rigid_body_step", "manakov_step", "clebsch_step",
                                                 "manakov_clebsch_step"};
  if (std::find(steps.begin(), steps.end(), name) != steps.end())
    rubric_error(r, key,
                 "\"" + name +
                     "\" is an integrator's step, not a slot: an integrator earns credit by its "
                     "claims (claims_weight, claims) and in the area \"integrators\"");
  rubric_error(r, key,
               "unknown slot \"" + name + "\"" + did_you_mean(name, slots) + "; `geomech slots` lists the slot names");
}

void check_claim_name(const Rubric& r, const std::string& key, const std::string& name) {
  static const std::vector<std::string> claims = claim_name_list();
  if (std::find(claims.begin(), claims.end(), name) != claims.end()) return;
  std::string list;
  for (const auto& c : claims) list += (list.empty() ? "" : ", ") + c;
  rubric_error(r, key, "unknown claim \"" + name + "\"" + did_you_mean(name, claims) + "; the claims are " + list);
}

const json& read_object(const Rubric& r, const json& v, const std::string& key) {
  if (!v.is_object()) rubric_error(r, key, "expected an object of weights, got " + v.dump());
  return v;
}

// The identifier columns of each format, before the grade column.
const std::vector<std::string> kMoodleIds = {"Implementation", "Username", "Email address", "ID number"};
const std::vector<std::string> kCanvasIds = {"Student", "ID", "SIS User ID", "SIS Login ID", "Section"};

// Canvas drops any column whose header contains one of these (its total columns),
// so a grade item named like that would never be imported.
const std::vector<std::string> kCanvasTotals = {"Current Score",  "Current Points", "Current Grade",
                                                "Final Score",    "Final Points",   "Final Grade",
                                                "Override Score", "Override Grade", "Override Status"};

void check_item(const Rubric& r) {
  if (r.item.empty()) rubric_error(r, "item", "expected a non-empty string");
  for (unsigned char c : r.item)
    if (c < 0x20) rubric_error(r, "item", "expected a single line without control characters");
  const auto& ids = r.format == LmsFormat::canvas ? kCanvasIds : kMoodleIds;
  if (std::find(ids.begin(), ids.end(), r.item) != ids.end() ||
      (r.format == LmsFormat::moodle && r.feedback && r.item == "Feedback"))
    rubric_error(r, "item", "\"" + r.item + "\" clashes with a fixed column name");
  if (r.format == LmsFormat::canvas)
    for (const auto& word : kCanvasTotals)
      if (r.item.find(word) != std::string::npos)
        rubric_error(r, "item", "Canvas would not read a column named \"" + r.item + "\" as an assignment");
}

double weight_of(const std::map<std::string, double>& weights, double fallback, const std::string& name) {
  auto it = weights.find(name);
  return it == weights.end() ? fallback : it->second;
}

// Integer cents keep rounding and printing identical on every machine and locale.
long long cents(double value) { return std::llround(value * 100.0); }

// Feedback goes into one CSV cell: no line breaks or tabs, single spaces.
std::string one_line(std::string_view text) {
  std::string out;
  for (unsigned char c : text) {
    if (c < 0x20 || c == 0x7f) c = ' ';
    if (c == ' ' && (out.empty() || out.back() == ' ')) continue;
    out += static_cast<char>(c);
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// "a, b, c +4 more": long lists would drown the one line the student reads.
std::string short_list(const std::vector<std::string>& items, std::size_t keep = 5) {
  std::string out;
  for (std::size_t i = 0; i < items.size() && i < keep; ++i) out += (i ? ", " : "") + items[i];
  if (items.size() > keep) out += " +" + std::to_string(items.size() - keep) + " more";
  return out;
}

// The first `n` bytes of `text`, or fewer, ending at a UTF-8 character boundary.
std::string utf8_prefix(const std::string& text, std::size_t n) {
  if (text.size() <= n) return text;
  while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80) --n;
  return text.substr(0, n);
}

// The last `n` bytes of `text`, or fewer, starting at a UTF-8 character boundary.
std::string utf8_suffix(const std::string& text, std::size_t n) {
  if (text.size() <= n) return text;
  std::size_t at = text.size() - n;
  while (at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) ++at;
  return text.substr(at);
}

// "head; middle; tail" in at most `max_bytes`: the head (the grade and its counts) and the tail (the
// pointer to the report) are kept whole, and the middle loses its own middle ("... "), so that the
// first fix keeps its beginning and its end (a cut at 400 bytes lost the report's path).
std::string feedback_line(const std::string& head, const std::string& middle, const std::string& tail,
                          std::size_t max_bytes = 400) {
  auto join = [](const std::string& a, const std::string& b) { return a.empty() ? b : b.empty() ? a : a + "; " + b; };
  const std::string whole = join(join(head, middle), tail);
  if (whole.size() <= max_bytes) return whole;
  const std::string ends = join(join(head, "x"), tail);  // the room the middle's separators take
  const std::string mark = " ... ";
  if (ends.size() + mark.size() + 8 > max_bytes)  // no room for a middle: the head is cut instead
    return join(utf8_prefix(head, max_bytes - std::min(max_bytes, tail.size() + 2 + mark.size())) + mark, tail);
  const std::size_t room = max_bytes - (ends.size() - 1) - mark.size();
  // The cut falls between words, never inside a quoted name: a cut in 'manakov_Omega' read as a
  // function 'manakov. A name the cut would split is kept whole if it ends near, else
  // the cut moves back to the word before it.
  const std::size_t near = 64;
  std::string first = utf8_prefix(middle, room - room / 3);
  if (first.size() < middle.size() && std::count(first.begin(), first.end(), '\'') % 2 == 1) {
    const std::size_t close = middle.find('\'', first.size());
    if (close != std::string::npos && close + 1 - first.size() <= near && close + 1 + 8 <= room)
      first = middle.substr(0, close + 1);
    else
      first = first.substr(0, first.rfind('\''));
  }
  if (first.size() < middle.size() && middle[first.size()] != ' ' && first.back() != ' ') {
    const std::size_t space = first.rfind(' ');
    if (space != std::string::npos && first.size() - space <= near) first = first.substr(0, space);
  }
  while (!first.empty() && first.back() == ' ') first.pop_back();
  std::string last = utf8_suffix(middle, room - std::min(room, first.size()));
  if (last.size() < middle.size() && middle[middle.size() - last.size() - 1] != ' ') {
    const std::size_t space = last.find(' ');
    if (space != std::string::npos && space <= near) last = last.substr(space + 1);
  }
  if (std::count(last.begin(), last.end(), '\'') % 2 == 1) {  // it starts inside a quoted name
    const std::size_t open_end = last.find('\'');
    if (open_end <= near) last = last.substr(open_end + 1);
    while (!last.empty() && last.front() == ' ') last.erase(0, 1);
  }
  return join(join(head, first + mark + last), tail);
}

// 100 -> "100", 12.5 -> "12.5", 66.666 -> "66.67": a weight or a maximum as a person writes it.
std::string trimmed_number(double value) {
  std::string s = format_points(value);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string csv_row(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i)
    line += (i ? "," : "") + csv_field(spreadsheet_safe(inert_text(fields[i])));
  return line + "\r\n";  // RFC 4180 line break; both importers also accept it (GRADEBOOK.md)
}

// The keys that hold one value (item, points, format, feedback, claims_weight, assignment).
void read_plain_key(Rubric& r, const std::string& key, const json& v) {
  if (key == "item") {
    if (!v.is_string()) rubric_error(r, key, "expected a string, got " + v.dump());
    r.item = v.get<std::string>();
  } else if (key == "points") {
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() <= 0)
      rubric_error(r, key, "expected a number > 0, got " + v.dump());
    r.points = v.get<double>();
  } else if (key == "format") {
    if (v == "moodle")
      r.format = LmsFormat::moodle;
    else if (v == "canvas")
      r.format = LmsFormat::canvas;
    else
      rubric_error(r, key, "expected \"moodle\" or \"canvas\", got " + v.dump());
  } else if (key == "feedback") {
    if (!v.is_boolean()) rubric_error(r, key, "expected true or false, got " + v.dump());
    r.feedback = v.get<bool>();
  } else if (key == "claims_weight") {
    r.claims_weight = read_weight(r, v, key);
  } else if (key == "assignment") {
    if (!v.is_array() || v.empty()) rubric_error(r, key, "expected a non-empty list of slot names");
    std::vector<std::string> slots;
    for (const auto& s : v) {
      if (!s.is_string() || s.get<std::string>().empty())
        rubric_error(r, key, "expected slot names as non-empty strings, got " + s.dump());
      if (std::find(slots.begin(), slots.end(), s.get<std::string>()) != slots.end())
        rubric_error(r, key, "slot " + s.dump() + " is listed twice");
      check_slot_name(r, key, s.get<std::string>());
      slots.push_back(s.get<std::string>());
    }
    r.assignment = slots;
  } else {
    rubric_error(r, key,
                 "unknown key; expected item, points, format, feedback, slots, assignment, "
                 "areas, claims_weight, claims or visibility");
  }
}

// "visibility": {"casimir": "after_due_date", "energy": "hidden", "default": "visible"}: a slot, a
// claim or an area, and when its test is shown to the student by an autograder (AUTOGRADERS.md).
void read_visibility(Rubric& r, const std::string& key, const std::string& name, const json& level) {
  const std::vector<std::string> levels(kVisibilityLevels.begin(), kVisibilityLevels.end());
  if (!level.is_string() || std::find(levels.begin(), levels.end(), level.get<std::string>()) == levels.end())
    rubric_error(r, key,
                 "expected \"visible\", \"after_due_date\", \"after_published\" or \"hidden\", got " + level.dump() +
                     (level.is_string() ? did_you_mean(level.get<std::string>(), levels) : ""));
  if (name == "default") {
    r.visibility_default = level.get<std::string>();
    return;
  }
  const std::vector<std::string> slots = slot_name_list(), claims = claim_name_list();
  const bool known = std::find(slots.begin(), slots.end(), name) != slots.end() ||
                     std::find(claims.begin(), claims.end(), name) != claims.end() ||
                     std::find(kKnownAreas.begin(), kKnownAreas.end(), name) != kKnownAreas.end();
  if (!known) {
    std::vector<std::string> all = slots;
    all.insert(all.end(), claims.begin(), claims.end());
    all.insert(all.end(), kKnownAreas.begin(), kKnownAreas.end());
    rubric_error(r, key,
                 "\"" + name + "\" is not a slot, a claim or an area" + did_you_mean(name, all) +
                     "; `geomech slots` lists the slot names");
  }
  r.visibility[name] = level.get<std::string>();
}

void check_maximum(const Rubric& r) {
  double slot_max = 0;
  if (r.assignment) {
    for (const auto& s : *r.assignment) slot_max += weight_of(r.slot_weights, r.slot_default, s);
  } else {
    slot_max = r.slot_default;
    for (const auto& [name, w] : r.slot_weights) slot_max += w;
  }
  double area_max = 0;
  for (const auto& [name, w] : r.area_weights) area_max += w;
  if (slot_max + area_max + r.claims_weight <= 0)
    rubric_error(r, r.assignment ? "assignment" : "slots",
                 "the weights make the maximum grade 0; give a slot, an area or claims_weight a positive weight");
}

}  // namespace

Rubric parse_rubric(std::string_view json_text, const std::string& source) {
  Rubric r;
  r.source = source;
  json doc;
  try {
    doc = json::parse(json_text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number past double's range (1e999)
    throw std::runtime_error("rubric \"" + source + "\": not valid JSON: " + e.what());
  }
  if (!doc.is_object()) rubric_error(r, "(top level)", "expected a JSON object");
  // Every error is named, not only the first: each key (and each name under slots, claims, areas
  // and visibility) is read on its own, and the refusal lists what all of them said.
  std::vector<std::string> errors;
  auto each = [&](auto&& read) {
    try {
      read();
    } catch (const std::runtime_error& e) {
      errors.push_back(e.what());
    }
  };
  for (const auto& [key, v] : doc.items()) {
    if (key == "slots" || key == "claims") {
      const bool slots = key == "slots";
      each([&] { read_object(r, v, key); });
      if (!v.is_object()) continue;
      for (const auto& [name, w] : v.items())
        each([&] {
          const double weight = read_weight(r, w, key + "." + name);
          if (name != "default") (slots ? check_slot_name : check_claim_name)(r, key + "." + name, name);
          if (name == "default")
            (slots ? r.slot_default : r.claim_default) = weight;
          else
            (slots ? r.slot_weights : r.claim_weights)[name] = weight;
        });
    } else if (key == "areas") {
      each([&] { read_object(r, v, key); });
      if (!v.is_object()) continue;
      for (const auto& [name, w] : v.items())
        each([&] {
          if (std::find(kKnownAreas.begin(), kKnownAreas.end(), name) == kKnownAreas.end())
            rubric_error(r, key + "." + name,
                         "unknown area; expected one of \"sec. 1\", \"sec. 2\", "
                         "\"sec. 3\", \"momentum maps\", \"integrators\"");
          r.area_weights[name] = read_weight(r, w, key + "." + name);
        });
    } else if (key == "visibility") {
      each([&] {
        if (!v.is_object()) rubric_error(r, key, "expected an object of slot, claim or area names, got " + v.dump());
      });
      if (!v.is_object()) continue;
      for (const auto& [name, level] : v.items()) each([&] { read_visibility(r, key + "." + name, name, level); });
    } else {
      each([&] { read_plain_key(r, key, v); });
    }
  }
  each([&] { check_item(r); });
  // Reject weights that leave nothing to earn. With an explicit assignment the
  // slot maximum is known now; otherwise any positive slot weight may count.
  if (errors.empty()) each([&] { check_maximum(r); });
  if (errors.size() == 1) throw std::runtime_error(errors[0]);
  if (!errors.empty()) {
    std::string all = "rubric \"" + r.source + "\" has " + std::to_string(errors.size()) + " errors:";
    for (const auto& e : errors) all += "\n  " + e;
    throw std::runtime_error(all);
  }
  return r;
}

std::vector<std::string> resolve_assignment(const Rubric& rubric, const std::vector<StudentResult>& cls) {
  if (rubric.assignment) return *rubric.assignment;
  std::set<std::string> all;
  for (const auto& s : cls) all.insert(s.provided.begin(), s.provided.end());
  return {all.begin(), all.end()};
}

namespace {

// A student's score as it is built: the score so far, and the counts its words are made of.
struct Scoring {
  Scoring(const StudentResult& student, const Rubric& rubric, const std::vector<std::string>& slots, double slots_max,
          double points_per_weight)
      : st(student), r(rubric), assignment(slots), slot_max(slots_max), scale(points_per_weight) {}
  const StudentResult& st;
  const Rubric& r;
  const std::vector<std::string>& assignment;
  const double slot_max;
  const double scale;  // rubric weight -> points
  const bool graded = st.status == "checked";
  Score out;
  int correct = 0;
  double slot_earned = 0, earned = 0;
  std::vector<std::string> wrong_list, missing, not_exercised;
  std::vector<std::string> area_words;
  int n_made = 0, n_verified = 0;
  std::vector<std::string> false_claims;

  // Adds an item: its weight and what was earned of it, in the rubric's weights and in points.
  void item(ScoreItem::Kind kind, std::string name, double weight, double gained, std::string state,
            std::string detail) {
    out.items.push_back(ScoreItem{kind, std::move(name), weight, gained, weight * scale, gained * scale,
                                  std::move(state), std::move(detail)});
  }
};

// Scores the assignment's slots, an item each; lists the wrong, missing and not exercised ones
// for the words.
void score_slots(Scoring& sc) {
  const StudentResult& st = sc.st;
  const Rubric& r = sc.r;
  const std::vector<std::string>& assignment = sc.assignment;
  const std::set<std::string> provided(st.provided.begin(), st.provided.end());
  const std::set<std::string> wrong(st.wrong.begin(), st.wrong.end());
  const std::set<std::string> unexercised(st.unexercised.begin(), st.unexercised.end());
  for (const auto& s : assignment) {
    const double w = weight_of(r.slot_weights, r.slot_default, s);
    if (w <= 0) continue;
    const auto why = st.why_wrong.find(s);
    const std::string detail = why == st.why_wrong.end() ? "" : why->second;
    if (!sc.graded) {
      sc.item(ScoreItem::Kind::Slot, s, w, 0, st.status, "");
    } else if (wrong.count(s)) {
      sc.item(ScoreItem::Kind::Slot, s, w, 0, "wrong", detail);
    } else if (provided.count(s)) {
      ++sc.correct, sc.slot_earned += w;
      sc.item(ScoreItem::Kind::Slot, s, w, w, "correct", "");
    } else if (unexercised.count(s)) {
      sc.not_exercised.push_back(s);
      sc.item(ScoreItem::Kind::Slot, s, w, 0, "not exercised", "provided, but no check that ran calls it");
    } else {
      sc.missing.push_back(s);
      sc.item(ScoreItem::Kind::Slot, s, w, 0, "missing", "not provided");
    }
  }
  for (const auto& s : st.wrong)  // in the order of the first fixes
    if (std::find(assignment.begin(), assignment.end(), s) != assignment.end() &&
        weight_of(r.slot_weights, r.slot_default, s) > 0)
      sc.wrong_list.push_back(s);
}

// Scores each weighted area by the share of its checks that passed.
void score_areas(Scoring& sc) {
  const StudentResult& st = sc.st;
  for (const auto& [area, w] : sc.r.area_weights) {
    if (w <= 0) continue;
    auto it = st.areas.find(area);
    const int run = !sc.graded || it == st.areas.end() ? 0 : it->second.second;
    const int passed = run <= 0 ? 0 : std::clamp(it->second.first, 0, run);
    const double e = run > 0 ? (w * passed) / run : 0;  // no checks run: no evidence, no credit
    sc.earned += e;
    const std::string counts = std::to_string(passed) + "/" + std::to_string(run);
    sc.item(ScoreItem::Kind::Area, area, w, e, counts + " checks passed", run > 0 ? "" : "no check of this area ran");
    if (sc.graded)
      sc.out.breakdown.push_back(area + " " + counts), sc.area_words.push_back(area + " " + counts + " checks");
  }
}

// Scores the integrator claims: the claims weight shared among the claims made, earned by those verified.
void score_claims(Scoring& sc) {
  const StudentResult& st = sc.st;
  const Rubric& r = sc.r;
  double made = 0;
  for (const auto& c : st.claims) {
    const double w = weight_of(r.claim_weights, r.claim_default, c.claim);
    if (c.status == "not claimed" || w <= 0) continue;
    made += w;
  }
  for (const auto& c : st.claims) {
    const double w = weight_of(r.claim_weights, r.claim_default, c.claim);
    if (c.status == "not claimed" || w <= 0 || !sc.graded) continue;
    ++sc.n_made;
    const double share = r.claims_weight * w / made, e = c.status.rfind("verified", 0) == 0 ? share : 0;
    sc.n_verified += c.status.rfind("verified", 0) == 0;
    if (c.status == "FALSE CLAIM") sc.false_claims.push_back(c.integrator + " " + c.claim);
    sc.earned += e;
    sc.item(ScoreItem::Kind::Claim, c.integrator + " " + c.claim, share, e, c.status, "");
  }
  // No claims made: no claim credit (making none would otherwise be the safest way to score).
  if (sc.n_made == 0)
    sc.item(ScoreItem::Kind::Claim, "claims", r.claims_weight, 0, sc.graded ? "none made" : st.status, "");
  if (sc.graded)
    sc.out.breakdown.push_back("claims " + std::to_string(sc.n_verified) + "/" + std::to_string(sc.n_made) +
                               " verified");
}

// The feedback in words: the grade first, then what it rests on, counts and weights
// together ("11 of 12 slots correct (weight 12 of 13)", "casimir (weight 1)"), the first fix, and
// the report; clipped in the middle, never at its ends.
void write_feedback(Scoring& sc) {
  const StudentResult& st = sc.st;
  const Rubric& r = sc.r;
  const std::vector<std::string>& assignment = sc.assignment;
  Score& out = sc.out;
  bool uniform = true;
  for (const auto& s : assignment) uniform = uniform && weight_of(r.slot_weights, r.slot_default, s) == r.slot_default;
  const auto weighted = [&](const std::vector<std::string>& slots) {
    std::vector<std::string> out_list;
    for (const auto& s : slots) {
      out_list.push_back(
          uniform ? s : s + " (weight " + trimmed_number(weight_of(r.slot_weights, r.slot_default, s)) + ")");
    }
    return short_list(out_list);
  };
  std::vector<std::string> notes;
  std::string head = format_points(out.points) + " of " + trimmed_number(r.points);
  if (!sc.graded) {
    head += ": " + st.status;
  } else {
    std::vector<std::string> parts;
    if (sc.slot_max > 0) {
      std::string slots = std::to_string(sc.correct) + " of " + std::to_string(assignment.size()) +
                          (assignment.size() == 1 ? " slot" : " slots") + " correct";
      if (!uniform) slots += " (weight " + trimmed_number(sc.slot_earned) + " of " + trimmed_number(sc.slot_max) + ")";
      parts.push_back(slots);
    }
    parts.insert(parts.end(), sc.area_words.begin(), sc.area_words.end());
    if (r.claims_weight > 0)
      parts.push_back(sc.n_made == 0 ? std::string("no integrator claims made")
                                     : std::to_string(sc.n_verified) + " of " + std::to_string(sc.n_made) +
                                           (sc.n_made == 1 ? " claim verified" : " claims verified"));
    for (std::size_t i = 0; i < parts.size(); ++i) head += (i ? ", " : ": ") + parts[i];
    if (!sc.wrong_list.empty()) notes.push_back("wrong: " + weighted(sc.wrong_list));
    if (!sc.missing.empty()) notes.push_back("missing: " + weighted(sc.missing));
    if (!sc.not_exercised.empty()) notes.push_back("not exercised by the checks run: " + weighted(sc.not_exercised));
    if (!sc.false_claims.empty()) notes.push_back("false claims: " + short_list(sc.false_claims));
  }
  out.headline = one_line(head);
  out.notes = notes;
  if (!one_line(st.first_fix).empty()) notes.push_back("fix first: " + one_line(st.first_fix));
  std::string middle;
  for (const auto& n : notes) middle += (middle.empty() ? "" : "; ") + n;
  const std::string tail = st.report.empty() ? "" : "report: " + one_line(st.report);
  out.feedback = feedback_line(one_line(head), one_line(middle), tail);
}

// The words of a student with no grade: the grader's machine failed its check, or it is not checked yet.
void say_no_grade(const StudentResult& st, Score& out) {
  if (st.status == kGraderError) {
    // The machine's fault is not the student's: no grade (an empty cell), and words without the
    // grader's paths; the lecturer's summary says what failed and its fix.
    out.headline = "no grade yet: the grading machine could not check this submission";
    out.feedback =
        "no grade yet: the grading machine could not check this submission (a problem of the grader, not of "
        "your code); it will be checked again";
    if (st.left_to_lecturer) {
      out.headline = "no grade yet: the lecturer decides how this submission's check ended";
      out.feedback =
          "no grade yet: this submission's check ended the same way in each run; the lecturer decides how to grade "
          "it";
    }
  }
  if (st.status == kNotCheckedYet) {
    // A class run stopped before this submission: no grade, and the row says why, as
    // the summary does; an empty grade cell is "no grade" to both importers.
    out.headline = "no grade yet: " + kNotCheckedYet;
    out.feedback =
        "no grade yet: the class run stopped before checking this submission; the same command again resumes it";
  }
}

}  // namespace

Score score_student(const StudentResult& st, const Rubric& r, const std::vector<std::string>& assignment) {
  double slot_max = 0, max = r.claims_weight;
  for (const auto& s : assignment) slot_max += weight_of(r.slot_weights, r.slot_default, s);
  max += slot_max;
  for (const auto& [name, w] : r.area_weights) max += w;
  if (max <= 0)
    rubric_error(r, "assignment",
                 "the maximum grade is 0 for this class (" + std::to_string(assignment.size()) +
                     " assignment slots); list the slots under \"assignment\"");
  Scoring sc(st, r, assignment, slot_max, r.points / max);
  Score& out = sc.out;
  out.max_points = r.points;
  // Every assignment slot, every weighted area and the claims are items, graded or not: a student
  // who was not checked sees what the assignment asked for, each at 0.
  score_slots(sc);
  sc.earned = sc.slot_earned;
  score_areas(sc);
  if (r.claims_weight > 0) score_claims(sc);
  if (sc.graded && slot_max > 0)
    out.breakdown.insert(out.breakdown.begin(),
                         "slots " + std::to_string(sc.correct) + "/" + std::to_string(assignment.size()));
  out.points = sc.graded ? static_cast<double>(cents(sc.earned * sc.scale)) / 100.0 : 0.0;
  for (auto& i : out.items) {  // a claim's item is "<integrator> <claim>"; its visibility is the claim's
    const std::string name = i.kind == ScoreItem::Kind::Claim ? i.name.substr(i.name.rfind(' ') + 1) : i.name;
    const auto v = r.visibility.find(name);
    i.visibility = v == r.visibility.end() ? r.visibility_default : v->second;
  }

  write_feedback(sc);
  out.no_grade = st.status == kGraderError || st.status == kNotCheckedYet;
  say_no_grade(st, out);
  return std::move(out);
}

std::vector<std::string> gradebook_header(const Rubric& r) {
  std::vector<std::string> h = r.format == LmsFormat::canvas ? kCanvasIds : kMoodleIds;
  h.push_back(r.item);
  if (r.format == LmsFormat::moodle && r.feedback) h.push_back("Feedback");
  return h;
}

std::string write_gradebook_csv(const std::vector<StudentResult>& cls, const Rubric& r,
                                const std::optional<Roster>& roster) {
  std::vector<const StudentResult*> rows;
  for (const auto& s : cls) rows.push_back(&s);
  std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->name < b->name; });
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (rows[i]->name == rows[i - 1]->name)
      throw std::runtime_error("gradebook: implementation name \"" + rows[i]->name + "\" appears twice");
  const auto assignment = resolve_assignment(r, cls);
  std::string out = csv_row(gradebook_header(r));
  // Canvas reads the maximum for the assignment column from this row.
  if (r.format == LmsFormat::canvas) out += csv_row({"Points Possible", "", "", "", "", format_points(r.points)});
  for (const auto* s : rows) {
    const Score score = score_student(*s, r, assignment);
    RosterEntry id;
    const bool listed = roster && roster->count(s->name);
    if (listed)
      id = roster->at(s->name);
    else
      id.username = id.full_name = s->name;  // no roster row: the implementation name identifies
    const std::string grade = score.no_grade ? "" : format_points(score.points);
    if (r.format == LmsFormat::canvas) {
      out += csv_row({id.full_name.empty() ? s->name : id.full_name, id.canvas_id, id.sis_user_id, id.sis_login_id,
                      id.section, grade});
    } else {
      std::vector<std::string> f = {s->name, id.username, id.email, id.id_number, grade};
      if (r.feedback) f.push_back(score.feedback);
      out += csv_row(f);
    }
  }
  return out;
}

Roster parse_roster(std::string_view text, const std::string& source) {
  const auto fail = [&](const std::string& what) { throw std::runtime_error("roster \"" + source + "\": " + what); };
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // spreadsheets like to add a BOM
  std::vector<std::vector<std::string>> rows;
  try {
    rows = parse_csv(text);
  } catch (const std::runtime_error& e) {
    fail(e.what());
  }
  const auto trim = [](std::string s) {
    s.erase(0, s.find_first_not_of(" \t"));
    s.erase(s.find_last_not_of(" \t") + 1);
    return s;
  };
  if (rows.empty()) fail("empty file; expected a header row with a \"name\" column");
  const std::vector<std::string> known = {"name",      "full_name",   "username",     "email",  "id_number",
                                          "canvas_id", "sis_user_id", "sis_login_id", "section"};
  std::vector<std::string> header;
  for (const auto& h : rows[0]) {
    header.push_back(trim(h));
    if (std::find(known.begin(), known.end(), header.back()) == known.end())
      fail("unknown column \"" + header.back() +
           "\"; expected name, full_name, username, email, "
           "id_number, canvas_id, sis_user_id, sis_login_id, section");
  }
  if (std::find(header.begin(), header.end(), "name") == header.end()) fail("no \"name\" column");
  Roster roster;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i].size() == 1 && trim(rows[i][0]).empty()) continue;  // blank line
    if (rows[i].size() != header.size())
      fail("row " + std::to_string(i + 1) + " has " + std::to_string(rows[i].size()) + " fields, header has " +
           std::to_string(header.size()));
    std::map<std::string, std::string> f;
    for (std::size_t c = 0; c < header.size(); ++c) f[header[c]] = trim(rows[i][c]);
    if (f["name"].empty()) fail("row " + std::to_string(i + 1) + " has an empty name");
    if (roster.count(f["name"])) fail("name \"" + f["name"] + "\" appears twice");
    roster[f["name"]] = {f["full_name"], f["username"],    f["email"],        f["id_number"],
                         f["canvas_id"], f["sis_user_id"], f["sis_login_id"], f["section"]};
  }
  return roster;
}

std::vector<std::string> roster_warnings(const std::vector<StudentResult>& cls, const Roster& roster) {
  std::vector<std::string> out;
  std::set<std::string> names;
  for (const auto& s : cls) {
    names.insert(s.name);
    if (!roster.count(s.name)) out.push_back("\"" + s.name + "\" has no roster row; its name is used as identifier");
  }
  for (const auto& [name, entry] : roster)
    if (!names.count(name)) out.push_back("roster row \"" + name + "\" matches no implementation in the class");
  std::sort(out.begin(), out.end());
  return out;
}

std::string spreadsheet_safe(const std::string& cell) {
  if (cell.empty() || std::string_view("=+-@\t\r").find(cell[0]) == std::string_view::npos) return cell;
  // A number ("-1.5") is data, not a formula; anything else that starts so is made text.
  std::size_t i = cell[0] == '-' || cell[0] == '+' ? 1 : 0;
  bool digits = false, dot = false;
  for (; i < cell.size(); ++i) {
    if (std::isdigit(static_cast<unsigned char>(cell[i])) != 0)
      digits = true;
    else if (cell[i] == '.' && !dot)
      dot = true;
    else
      break;
  }
  if (digits && i == cell.size()) return cell;
  return "'" + cell;
}

std::string csv_field(std::string_view v) {
  if (v.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(v);
  std::string q = "\"";
  for (char c : v) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::vector<std::vector<std::string>> parse_csv(std::string_view t) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string field;
  bool in_quotes = false, closed = false, any = false;  // closed: a quoted field just ended
  int line = 1, opened_at = 0;
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error("CSV line " + std::to_string(line) + ": " + what);
  };
  const auto end_field = [&] { row.push_back(field), field.clear(), closed = false; };
  for (std::size_t i = 0; i < t.size(); ++i) {
    const char c = t[i];
    any = true;
    if (in_quotes) {
      if (c == '"' && i + 1 < t.size() && t[i + 1] == '"')
        field += '"', ++i;
      else if (c == '"')
        in_quotes = false, closed = true;
      else
        field += c, line += c == '\n';
    } else if (c == ',') {
      end_field();
    } else if (c == '\r' || c == '\n') {
      if (c == '\r' && (i + 1 >= t.size() || t[++i] != '\n')) fail("carriage return without line feed");
      end_field(), rows.push_back(std::move(row)), row.clear(), ++line, any = false;
    } else if (closed) {
      fail("text after a closing quote");
    } else if (c == '"') {
      if (!field.empty()) fail("quote inside an unquoted field");
      in_quotes = true, opened_at = line;
    } else {
      field += c;
    }
  }
  if (in_quotes) throw std::runtime_error("CSV line " + std::to_string(opened_at) + ": unbalanced quote");
  if (any) end_field(), rows.push_back(std::move(row));
  return rows;
}

std::string format_points(double value) {
  const long long c = cents(value), a = c < 0 ? -c : c;
  const std::string frac = std::to_string(a % 100);
  return (c < 0 ? "-" : "") + std::to_string(a / 100) + "." + (frac.size() < 2 ? "0" : "") + frac;
}

}  // namespace gm::harness
