#include "harness/checking/verdict_io.hpp"

#include <cmath>
#include <stdexcept>

namespace gm::harness {

using nlohmann::json;

json number_to_json(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

double number_from_json(const json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "nan") return std::nan("");
  if (s == "inf") return HUGE_VAL;
  if (s == "-inf") return -HUGE_VAL;
  throw std::invalid_argument("not a number: '" + s + "'");
}

Outcome outcome_from_name(const std::string& name) {
  for (Outcome o : {Outcome::Pass, Outcome::Fail, Outcome::NotProvided, Outcome::Crash, Outcome::Timeout,
                    Outcome::Error, Outcome::NotCharacterised})
    if (name == outcome_name(o)) return o;
  throw std::invalid_argument("unknown outcome '" + name + "'");
}

json to_json(const Verdict& v) {
  json j;
  j["subject"] = v.subject;
  j["property"] = v.property;
  j["spec"] = v.spec;
  j["title"] = v.title;
  j["scalar"] = v.scalar;
  j["integrator"] = v.integrator;
  j["outcome"] = outcome_name(v.outcome);
  j["message"] = v.message;
  json ce = json::array();
  for (const auto& [type, value] : v.counterexample) ce.push_back({{"type", type}, {"value", value}});
  j["counterexample"] = ce;
  j["reproduce"] = v.reproduce;
  j["seed"] = v.seed;
  j["cases"] = v.cases;
  j["cases_planned"] = v.cases_planned;
  if (v.shrink_stopped) j["shrink_stopped"] = true;
  j["discarded"] = v.discarded;
  j["discard_reason"] = v.discard_reason;
  j["worst_eps_units"] = number_to_json(v.worst_eps_units);
  j["worst_absolute"] = number_to_json(v.worst_absolute);
  j["worst_check"] = v.worst_check;
  j["checks"] = v.checks;
  j["seconds"] = number_to_json(v.seconds);
  j["profile"] = {{"calls", v.protocol.calls},
                  {"round_trips", v.protocol.round_trips},
                  {"memo_hits", v.protocol.memo_hits},
                  {"waiting_seconds", number_to_json(v.protocol.waiting_seconds)},
                  {"code_cpu_seconds", number_to_json(v.code_cpu_seconds)},
                  {"suite_cpu_seconds", number_to_json(v.suite_cpu_seconds)}};
  json series = json::array();
  for (const auto& s : v.series) {
    json pts = json::array();
    for (const auto& [x, y] : s.points) pts.push_back({number_to_json(x), number_to_json(y)});
    series.push_back({{"figure", s.figure},
                      {"name", s.name},
                      {"x_label", s.x_label},
                      {"y_label", s.y_label},
                      {"log_x", s.log_x},
                      {"log_y", s.log_y},
                      {"reference_slope", number_to_json(s.reference_slope)},
                      {"points", pts}});
  }
  j["series"] = series;
  json claims = json::array();
  for (const auto& c : v.claims)
    claims.push_back({{"claim", c.claim},
                      {"claimed", c.claimed},
                      {"holds", c.holds},
                      {"evidence", c.evidence},
                      {"complete", c.complete},
                      {"measured", c.measured}});
  j["claims"] = claims;
  if (!v.word.empty()) j["word"] = v.word;
  if (!v.machine_fault.empty()) j["machine_fault"] = v.machine_fault;
  if (!v.judged_precision.empty())
    j["judged_precision"] = {{"name", v.judged_precision}, {"how", v.judged_precision_how}};
  j["owner"] = v.outcome == Outcome::Pass || v.outcome == Outcome::NotProvided ? "none"
               : !v.machine_fault.empty()                                      ? "machine"
                                                                               : "code";
  if (!v.step_raised.empty()) j["step_raised"] = {{"message", v.step_raised}, {"where", v.step_raised_where}};
  return j;
}

Verdict verdict_from_json(const json& j) {
  Verdict v;
  v.subject = j.at("subject").get<std::string>();
  v.property = j.at("property").get<std::string>();
  v.spec = j.at("spec").get<std::string>();
  v.title = j.at("title").get<std::string>();
  v.scalar = j.at("scalar").get<std::string>();
  v.integrator = j.at("integrator").get<std::string>();
  v.outcome = outcome_from_name(j.at("outcome").get<std::string>());
  v.message = j.at("message").get<std::string>();
  for (const auto& c : j.at("counterexample"))
    v.counterexample.emplace_back(c.at("type").get<std::string>(), c.at("value").get<std::string>());
  v.reproduce = j.at("reproduce").get<std::string>();
  v.seed = j.at("seed").get<std::uint64_t>();
  v.cases = j.at("cases").get<int>();
  v.cases_planned = j.value("cases_planned", v.cases);  // absent from reports written before the time budget
  v.shrink_stopped = j.value("shrink_stopped", false);
  v.discarded = j.value("discarded", 0);  // absent from reports written before it was counted
  v.discard_reason = j.value("discard_reason", std::string());
  v.worst_eps_units = number_from_json(j.at("worst_eps_units"));
  v.worst_absolute = number_from_json(j.at("worst_absolute"));
  v.worst_check = j.at("worst_check").get<std::string>();
  v.checks = j.at("checks").get<long>();
  v.seconds = number_from_json(j.at("seconds"));
  if (j.contains("profile") && j["profile"].is_object()) {  // absent from reports written before it
    const json& f = j["profile"];
    v.protocol.calls = f.value("calls", 0L);
    v.protocol.round_trips = f.value("round_trips", 0L);
    v.protocol.memo_hits = f.value("memo_hits", 0L);
    v.protocol.waiting_seconds = f.contains("waiting_seconds") ? number_from_json(f["waiting_seconds"]) : 0.0;
    v.code_cpu_seconds = f.contains("code_cpu_seconds") ? number_from_json(f["code_cpu_seconds"]) : 0.0;
    v.suite_cpu_seconds = f.contains("suite_cpu_seconds") ? number_from_json(f["suite_cpu_seconds"]) : 0.0;
  }
  for (const auto& s : j.at("series")) {
    Series out;
    out.figure = s.at("figure").get<std::string>();
    out.name = s.at("name").get<std::string>();
    out.x_label = s.at("x_label").get<std::string>();
    out.y_label = s.at("y_label").get<std::string>();
    out.log_x = s.at("log_x").get<bool>();
    out.log_y = s.at("log_y").get<bool>();
    out.reference_slope = number_from_json(s.at("reference_slope"));
    for (const auto& p : s.at("points")) out.points.emplace_back(number_from_json(p.at(0)), number_from_json(p.at(1)));
    v.series.push_back(std::move(out));
  }
  for (const auto& c : j.at("claims"))
    v.claims.push_back(ClaimFinding{c.at("claim").get<std::string>(), c.at("claimed").get<bool>(),
                                    c.at("holds").get<bool>(), c.at("evidence").get<std::string>(),
                                    c.value("complete", true), c.value("measured", std::string())});
  v.word = j.value("word", std::string());
  v.machine_fault = j.value("machine_fault", std::string());
  if (j.contains("judged_precision")) {
    v.judged_precision = j["judged_precision"].value("name", std::string());
    v.judged_precision_how = j["judged_precision"].value("how", std::string());
  }
  if (j.contains("step_raised")) {
    v.step_raised = j["step_raised"].value("message", std::string());
    v.step_raised_where = j["step_raised"].value("where", std::string());
  }
  return v;
}

std::string verdicts_to_string(const std::vector<Verdict>& vs) {
  json a = json::array();
  for (const auto& v : vs) a.push_back(to_json(v));
  return a.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::vector<Verdict> verdicts_from_string(const std::string& s) {
  std::vector<Verdict> out;
  for (const auto& j : json::parse(s)) out.push_back(verdict_from_json(j));
  return out;
}

}  // namespace gm::harness
