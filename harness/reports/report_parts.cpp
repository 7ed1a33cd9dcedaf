// What the report's formats share (harness/reports/report_parts.hpp).
#include "harness/reports/report_parts.hpp"

#include "harness/reports/report.hpp"

#include "harness/checking/integrator_verdicts.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/reports/html_page.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace gm::harness::report_parts {

const Property* property_of(const Verdict& v) { return find_property(v.property); }

std::string eps_text(double units) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2g eps", units);
  return buf;
}

// How the report names a slot to fix: "slot `x`" for C++ (the slot is the function's name there);
// for an implementation in another language, the function in the student's file.
std::string slot_named(const CheckResult& r, const std::string& slot, const char* quote) {
  return harness::slot_named(r.info, slot, quote);
}

std::string file_safe(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '-';
  return out;
}

std::string place_of(const Verdict& v, const Catalogue* c) {
  if (c)
    if (const SpecEntry* e = c->find(v.spec)) return e->place;
  return {};
}

// Rows of the result table: property (+ integrator) -> scalar -> verdict, in verdict order.
std::vector<std::pair<std::string, std::map<std::string, const Verdict*>>> table_rows(const CheckResult& r) {
  std::vector<std::pair<std::string, std::map<std::string, const Verdict*>>> rows;
  for (const auto& v : r.verdicts) {
    const std::string name = row_name(v);
    auto it = std::find_if(rows.begin(), rows.end(), [&](const auto& x) { return x.first == name; });
    if (it == rows.end()) {
      rows.push_back({name, {}});
      it = rows.end() - 1;
    }
    it->second[v.scalar] = &v;
  }
  return rows;
}

bool nothing_ran(const std::map<std::string, const Verdict*>& by_scalar) {
  for (const auto& [scalar, v] : by_scalar)
    if (v->outcome != Outcome::NotProvided) return false;
  return true;
}

// The table cell of a verdict: its word, decided once (harness/checking/integrator_verdicts.hpp),
// with what a pass measured: the order where one was measured, the cases run of those planned when
// the time budget was spent, the worst residual.
std::string verdict_cell(const Verdict& v, bool exact_column) {
  std::string cell = v.word.empty() ? outcome_name(v.outcome) : v.word;
  if (v.outcome != Outcome::Pass) return cell;
  for (const auto& f : v.claims)
    if (f.claim == "order" && f.measured.rfind("order ", 0) == 0) return cell + " p = " + f.measured.substr(6);
  const bool plain = cell == "PASS";
  if (plain && v.cases_planned > v.cases)  // the time budget was spent: cases run / planned
    cell += " " + std::to_string(v.cases) + "/" + std::to_string(v.cases_planned);
  if (!exact_column && v.checks > 0 && plain)
    cell += " " + eps_text(v.worst_eps_units) + (v.judged_precision.empty() ? "" : " (" + v.judged_precision + ")");
  return cell;
}

// The outcomes counted, with the findings on claims nobody made apart from the passes they are
// reported as: "4 PASS, 10 does not hold, 0 FAIL" (a check of an unclaimed property that finds it
// does not hold passes the check, and is not a pass of the property).
std::string summary_counts(const CheckResult& r) {
  int does_not_hold = 0, not_established = 0;
  for (const auto& v : r.verdicts)
    if (v.outcome == Outcome::Pass && v.word.rfind("does not hold", 0) == 0)
      ++does_not_hold;
    else if (v.outcome == Outcome::Pass && v.word.rfind("not established", 0) == 0)
      ++not_established;
  std::ostringstream os;
  bool first = true;
  for (Outcome o : {Outcome::Pass, Outcome::Fail, Outcome::NotProvided, Outcome::Crash, Outcome::Timeout,
                    Outcome::Error, Outcome::NotCharacterised}) {
    int n = r.count(o);
    if (o == Outcome::Pass) n -= does_not_hold + not_established;
    if (n == 0 && o != Outcome::Pass && o != Outcome::Fail) continue;
    os << (first ? "" : ", ") << n << " " << outcome_name(o);
    first = false;
    if (o == Outcome::Pass && does_not_hold > 0) os << ", " << does_not_hold << " does not hold";
    if (o == Outcome::Pass && not_established > 0) os << ", " << not_established << " not established";
  }
  return os.str();
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

Missing missing_of(const CheckResult& r) {
  Missing m;
  for (const auto& v : r.verdicts)
    if (v.outcome == Outcome::NotProvided) m.by_reason[v.message].insert(v.property + " [" + v.scalar + "]");
  return m;
}

// Why a NOT PROVIDED check did not run: "not written" when a slot or integrator it needs
// is not in the implementation at all, "double only" when it is there but not in this scalar
// (Octave computes in double, numpy code does, a C++ slot written for double). A summary counts the
// two apart: the second is the language's or the code's precision, not missing work.
std::string not_provided_kind(const CheckResult& r, const Verdict& v) {
  auto in = [&](const std::string& scalar, const std::string& slot) {
    auto it = r.provided.find(scalar);
    return it != r.provided.end() && std::find(it->second.begin(), it->second.end(), slot) != it->second.end();
  };
  auto anywhere = [&](const std::string& slot) {
    for (const auto& [scalar, slots] : r.provided)
      if (std::find(slots.begin(), slots.end(), slot) != slots.end()) return true;
    return false;
  };
  const Property* p = property_of(v);
  if (!p) return r.info.scalar_unavailable.count(v.scalar) ? "double only" : "not written";
  bool other_scalar = false;
  for (const auto& need : p->needs) {
    if (!is_slot_name(need) || in(v.scalar, need)) continue;
    if (!anywhere(need)) return "not written";
    other_scalar = true;
  }
  if (p->scope == Scope::Integrator) {
    if (r.integrators.empty()) return "not written";
    bool here = false;
    for (const auto& i : r.integrators)
      here = here || std::find(i.scalars.begin(), i.scalars.end(), v.scalar) != i.scalars.end();
    other_scalar = other_scalar || !here;
  }
  return other_scalar || r.info.scalar_unavailable.count(v.scalar) ? "double only" : "not written";
}

// A table cell or a list item: inert, on one line, nothing Markdown or HTML would act on.
std::string md_cell(const std::string& s) { return md_inline(s); }

// A code block that no text inside can close.
std::string fence(const std::string& s) { return md_fenced(s); }

// "computes in float (stated: the engine is built in float); judged at float's round-off, eps =
// 1.19e-07", "computes in float (detected: ...)", or empty: how every view says an integrator's
// precision.
std::string precision_words(const IntegratorInfo& integ) {
  const std::string stated = bounded_text(inert_text(integ.claims.precision), 40);
  const std::string reason = bounded_text(inert_text(integ.claims.precision_reason), 300);
  std::string out;
  if (!integ.judged_precision.empty() && integ.claims.precision.empty())
    out = "computes in " + integ.judged_precision + " (" + bounded_text(inert_text(integ.judged_precision_how), 300) +
          ")";
  else if (!stated.empty())
    out = "computes in " + stated + (reason.empty() ? " (stated, without a reason)" : " (stated: " + reason + ")");
  if (integ.judged_precision == "float") out += "; judged at float's round-off, eps = 1.19e-07";
  if (!integ.claims.precision.empty() && integ.judged_precision.empty() && stated != "double")
    out += "; not a precision the suite knows (float, single or double): judged at the scalar's own";
  return out;
}

// " (declared domain: |Omega| <= 1e+06, h >= 1e-09; nothing outside it is checked)", or empty.
std::string domain_words(const StepDomain& d) {
  if (!d.declared()) return {};
  std::string w;
  char buf[64];
  if (d.max_omega > 0) std::snprintf(buf, sizeof buf, "|Omega| <= %.3g", d.max_omega), w += buf;
  if (d.max_pi > 0) std::snprintf(buf, sizeof buf, "%s|state| <= %.3g", w.empty() ? "" : ", ", d.max_pi), w += buf;
  if (d.min_h > 0) std::snprintf(buf, sizeof buf, "%s|h| >= %.3g", w.empty() ? "" : ", ", d.min_h), w += buf;
  return " (declared domain: " + w + "; nothing outside it is checked)";
}

// Whether the verdict is a check of a claim its integrator made.
bool judges_a_claim_made(const CheckResult& r, const Verdict& v) {
  if (v.integrator.empty()) return false;
  for (const auto& i : r.integrators)
    if (i.name == v.integrator) return i.has_claims && claims_any(i.claims, judged_claims(v));
  return false;
}

std::string anchor_of(const Verdict& v) {
  return file_safe(v.property + "-" + v.scalar + (v.integrator.empty() ? "" : "-" + v.integrator));
}

}  // namespace gm::harness::report_parts
