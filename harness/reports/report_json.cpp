// verdicts.json: the report of a check for machines and class mode (report.hpp, json_report).
#include "harness/checking/integrator_verdicts.hpp"
#include "harness/checking/verdict_io.hpp"
#include "harness/reports/report.hpp"
#include "harness/reports/report_parts.hpp"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace gm::harness {

using namespace report_parts;
using nlohmann::json;

json json_report(const CheckResult& r, const Catalogue* c) {
  json j;
  j["format"] = "geomech-report 1";
  j["subject"] = r.subject;
  j["description"] = r.description;
  j["source"] = r.info.source;
  j["reproduce_prefix"] = r.info.reproduce_prefix;
  j["seed"] = r.seed;
  j["selection"] = r.selection;
  j["seconds"] = number_to_json(r.seconds);
  j["exit_code"] = r.exit_code();
  j["warnings"] = r.info.warnings;
  j["verdict"] = r.verdict_word();
  j["unchecked"] = r.unchecked;
  j["unexercised"] = r.unexercised;
  j["exercised"] = r.exercised;
  j["scalar_unavailable"] = r.info.scalar_unavailable;
  j["provided"] = r.provided;
  json counts;
  for (Outcome o : {Outcome::Pass, Outcome::Fail, Outcome::NotProvided, Outcome::Crash, Outcome::Timeout,
                    Outcome::Error, Outcome::NotCharacterised})
    counts[outcome_name(o)] = r.count(o);
  j["counts"] = counts;
  j["left_to_thorough"] = r.left_to_thorough;
  if (!r.left_to_thorough.empty()) j["left_to_thorough_why"] = r.thorough_only_note;
  if (r.case_factor > 0) j["case_factor"] = {{"factor", r.case_factor}, {"why", r.case_factor_note}};
  if (!r.work_precision_left_out.empty()) j["work_precision_left_out"] = r.work_precision_left_out;
  json integrators = json::array();
  for (const auto& i : r.integrators) {
    json claims = json::array();
    for (const auto& row : claim_rows(r, i))
      claims.push_back({{"claim", row.claim},
                        {"claimed", row.claimed},
                        {"status", row.status},
                        {"measured", row.measured},
                        {"why", row.why},
                        {"fails", row.fails},
                        {"evidence", row.evidence}});
    json one{{"name", i.name}, {"steps", i.steps}, {"scalars", i.scalars}, {"claims", claims}};
    if (!i.form.is_notes()) one["state"] = state_form_words(i.form);
    if (!i.claims.precision.empty())
      one["precision"] = {{"stated", i.claims.precision}, {"reason", i.claims.precision_reason}};
    if (!i.judged_precision.empty())
      one["precision"]["judged"] = {{"name", i.judged_precision}, {"how", i.judged_precision_how}};
    json domain = json::object();
    if (i.claims.domain.max_omega > 0) domain["max_omega"] = i.claims.domain.max_omega;
    if (i.claims.domain.max_pi > 0) domain["max_pi"] = i.claims.domain.max_pi;
    if (i.claims.domain.min_h > 0) domain["min_h"] = i.claims.domain.min_h;
    one["domain"] = domain;
    integrators.push_back(std::move(one));
  }
  j["integrators"] = integrators;
  // The slots wrong by their own check, the one most other failures call first, each with the line
  // the console's FIRST FIX prints (a class summary says them in words).
  j["language"] = r.info.language->id;
  if (!r.info.notebook.empty()) j["notebook"] = r.info.notebook;  // a notebook's code cells, and what did not run
  if (!r.info.interpreter.empty()) j["interpreter"] = r.info.interpreter;
  json first_fix = json::array();
  {
    const RootCauses& rc = r.first_fixes;
    for (const auto& slot : rc.order) {
      const Verdict* direct = &rc.broken.at(slot);
      json entry = {{"slot", slot}, {"property", direct->property}, {"scalar", direct->scalar}};
      if (auto c = rc.calls_broken.find(slot); c != rc.calls_broken.end()) {
        entry["calls"] = c->second;
        entry["line"] = slot_named(r, slot, "'") + " fails its own check " + direct->property + " in " +
                        direct->scalar + ", and it calls '" + c->second + "', which is wrong: fix that first";
      } else {
        entry["line"] = slot_named(r, slot, "'") + " is wrong: its own check " + direct->property + " fails in " +
                        direct->scalar + ": " + first_line(direct->message);
      }
      first_fix.push_back(std::move(entry));
    }
  }
  j["first_fix"] = first_fix;
  json verdicts = json::array();
  for (const auto& v : r.verdicts) {
    json jv = to_json(v);
    jv["area"] = area_of(v, c);
    if (is_problem(v.outcome)) jv["reproduce_command"] = reproduce_command(r, v);
    if (v.outcome == Outcome::NotProvided) jv["not_provided"] = not_provided_kind(r, v);
    verdicts.push_back(std::move(jv));
  }
  j["verdicts"] = verdicts;
  json portraits = json::array();
  for (const auto& p : r.portraits) portraits.push_back(to_json(p));
  j["portraits"] = portraits;
  return j;
}

}  // namespace gm::harness
