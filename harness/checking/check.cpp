#include "harness/checking/check.hpp"

#include "harness/checking/first_fix.hpp"
#include "harness/checking/integrator_verdicts.hpp"
#include "harness/checking/portrait.hpp"
#include "harness/checking/verdict_io.hpp"
#include "harness/checking/work_precision.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/isolation/isolate.hpp"
#include "harness/isolation/sandbox.hpp"
#include "properties/support/show.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <tuple>

#include <unistd.h>

namespace gm::harness {

namespace {

struct Item {
  const Property* property;
  ScalarKind kind;
  std::string integrator;  // integrator-scoped properties: the one integrator this item drives
};

template <class Fn>
decltype(auto) with_scalar(ScalarKind k, Fn&& fn) {
  switch (k) {
    case ScalarKind::Double:
      return fn(static_cast<double*>(nullptr));
    case ScalarKind::MP50:
      return fn(static_cast<Real50*>(nullptr));
    case ScalarKind::Exact:
      break;
  }
  return fn(static_cast<Rational*>(nullptr));
}

bool subject_provides(const SubjectSet& s, ScalarKind k, const std::string& slot) {
  return with_scalar(k, [&](auto* tag) {
    using T = std::remove_pointer_t<decltype(tag)>;
    const Subject<T>* sub = s.get<T>();
    return sub != nullptr && sub->provides(slot);
  });
}

// Every slot p needs is provided in scalar k (otherwise its verdict is NOT PROVIDED, with why).
bool provides_needs(const SubjectSet& s, ScalarKind k, const Property& p) {
  return std::all_of(p.needs.begin(), p.needs.end(),
                     [&](const std::string& need) { return !is_slot_name(need) || subject_provides(s, k, need); });
}

bool has_step(const Property& p, const auto& integrator) { return has_step_kind(integrator, p.step); }

// The integrators of `s` in scalar k that property p drives.
std::vector<std::string> integrators_for(const Property& p, const SubjectSet& s, ScalarKind k) {
  if (k == ScalarKind::Exact) return {};
  return with_scalar(k, [&](auto* tag) {
    using T = std::remove_pointer_t<decltype(tag)>;
    std::vector<std::string> names;
    if constexpr (!is_exact_v<T>) {
      if (const Subject<T>* sub = s.get<T>())
        for (const auto& i : sub->integrators)
          if (has_step(p, i)) names.push_back(i.name);
    }
    return names;
  });
}

// A copy of `s` whose subject in scalar k keeps only the named integrator.
SubjectSet only_integrator(const SubjectSet& s, ScalarKind k, const std::string& name) {
  SubjectSet out = s;
  with_scalar(k, [&](auto* tag) {
    using T = std::remove_pointer_t<decltype(tag)>;
    if constexpr (!is_exact_v<T>) {
      auto copy = std::make_shared<Subject<T>>(*s.get<T>());
      std::erase_if(copy->integrators, [&](const Integrator<T>& i) { return i.name != name; });
      if constexpr (std::is_same_v<T, double>)
        out.d = copy;
      else
        out.mp = copy;
    }
    return 0;
  });
  return out;
}

Verdict base_verdict(const SubjectSet& s, const Item& item) {
  Verdict v;
  v.subject = s.name;
  v.property = item.property->id;
  v.spec = item.property->spec;
  v.title = item.property->title;
  v.scalar = scalar_name(item.kind);
  v.integrator = item.integrator;
  return v;
}

// A verdict's texts, each of a bounded size: a message of a property may quote a
// submission's message (bounded already where a remote one is read, not an in-process exception's),
// and its counterexample, notes and evidence values the submission returned.
void bound_texts(Verdict& v) {
  v.message = bounded_text(v.message, 2 * kMessageCap);
  for (auto& [type, value] : v.counterexample) value = bounded_text(value);
  for (auto& n : v.notes) n = bounded_text(n);
  for (auto& c : v.claims) c.evidence = bounded_text(c.evidence);
  v.discard_reason = bounded_text(v.discard_reason);
}

// All of a report's texts together stay under kReportTextBudget (every slot of a
// submission may raise a message as long as it is allowed): the longest messages are cut to 1 KiB
// until they fit, and the report says how many were.
void keep_within_budget(CheckResult& r) {
  auto size_of = [](const Verdict& v) {
    std::size_t n = v.message.size() + v.discard_reason.size();
    for (const auto& [type, value] : v.counterexample) n += value.size();
    for (const auto& note : v.notes) n += note.size();
    for (const auto& c : v.claims) n += c.evidence.size();
    return n;
  };
  std::size_t total = 0;
  for (const auto& v : r.verdicts) total += size_of(v);
  if (total <= kReportTextBudget) return;
  std::vector<Verdict*> longest;
  for (auto& v : r.verdicts) longest.push_back(&v);
  std::sort(longest.begin(), longest.end(),
            [&](const Verdict* a, const Verdict* b) { return size_of(*a) > size_of(*b); });
  std::size_t cut = 0;
  for (Verdict* v : longest) {
    if (total <= kReportTextBudget) break;
    const std::size_t before = size_of(*v);
    v->message = bounded_text(v->message, 1024);
    for (auto& [type, value] : v->counterexample) value = bounded_text(value, 1024);
    for (auto& note : v->notes) note = bounded_text(note, 1024);
    for (auto& c : v->claims) c.evidence = bounded_text(c.evidence, 1024);
    total -= before - size_of(*v);
    ++cut;
  }
  r.info.warnings.push_back("the messages of " + std::to_string(cut) +
                            " checks are cut to 1 KiB each: together the "
                            "messages of a report are kept under " +
                            std::to_string(kReportTextBudget >> 20) + " MiB, and each is shown up to " +
                            std::to_string(kMessageCap) +
                            " bytes (its beginning and its end) whatever the code under test raises");
}

// Turns the end of a child that did not report verdicts into one verdict.
Verdict abnormal_verdict(const SubjectSet& s, const Item& item, const TaskResult& t, const RunOptions& run) {
  Verdict v = base_verdict(s, item);
  v.seconds = t.seconds;
  v.seed = derive_seed(run.seed, item.property->id + "/" + v.scalar);  // as the runner derives it
  std::ostringstream m;
  switch (t.status) {
    case TaskResult::Status::TimedOut:
      v.outcome = Outcome::Timeout;
      if (t.detail.find("it waits") != std::string::npos || t.detail.find("it starves itself") != std::string::npos)
        m << "the check " << t.detail << ".";
      else
        m << "the check " << t.detail
          << ": the code under test hangs (an endless loop, an iteration that never converges) or is far too slow "
             "for this check.";
      break;
    case TaskResult::Status::Busy:
      // Not a verdict on the code: the kernel's accounting says the machine starved it (or cannot say).
      v.outcome = Outcome::Error;
      m << "the check " << t.detail
        << ": nothing is known about the code from it. Run it again on a less busy machine (the command below), or "
           "with fewer checks at once (--jobs).";
      v.machine_fault = "the machine's fault, not the code's: the check " + t.detail +
                        ". Fix: run it again on a less busy machine, or with fewer checks at once (--jobs).";
      v.word = kMachineErrorWord;
      break;
    case TaskResult::Status::Crashed:
      v.outcome = Outcome::Crash;
      if (t.signal != 0 || !t.sanitizer_report.empty())
        m << "the process running this check " << (t.signal != 0 ? "was " : "") << t.detail
          << ": the code under test crashed (an index out of range, a null or dangling pointer, unbounded "
             "recursion, a failed assertion, ...). No counterexample could be shrunk; replay the check with the "
             "command below, under a debugger if need be.";
      else
        m << "the process running this check " << t.detail << ".";
      break;
    case TaskResult::Status::Threw:
      v.outcome = Outcome::Error;
      m << "the harness could not run this check: it " << t.detail;
      break;
    case TaskResult::Status::Ok:
      v.outcome = Outcome::Error;
      m << "the check returned a result the harness cannot read";
      break;
  }
  v.message = m.str();
  if (!t.output.empty()) {
    std::string tail = t.output;
    while (!tail.empty() && (tail.back() == '\n' || tail.back() == '\r')) tail.pop_back();
    v.message += "\nlast output of the process:\n" + tail;
  }
  return v;
}

// The verdicts a child returns must be those of the check it ran. Anything else was written on the
// result channel by someone other than the property: in-process, the code under test shares the
// child with its judge and can write there. This catches a forgery that does not know
// which check it interrupts; one that does can only be stopped by untrusted mode. (A verdict with
// no integrator is the runner's "not provided" for an integrator check: it belongs.)
struct ForeignResult : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void check_verdicts_belong_to(const std::vector<Verdict>& vs, const Item& item) {
  if (vs.empty()) throw std::runtime_error("no verdict in the check's result");
  auto name = [](const std::string& property, const std::string& scalar, const std::string& integrator) {
    return property + " in " + scalar + (integrator.empty() ? "" : " of " + integrator);
  };
  for (const auto& v : vs)
    if (v.property != item.property->id || v.scalar != scalar_name(item.kind) ||
        (!item.integrator.empty() && !v.integrator.empty() && v.integrator != item.integrator))
      throw ForeignResult(
          "this check's result was not written by the property: it names the check " +
          name(v.property, v.scalar, v.integrator) + ", but the harness ran " +
          name(item.property->id, scalar_name(item.kind), item.integrator) +
          ". The code under test wrote on the harness's result channel (a forged verdict), so nothing is known "
          "about this check. Checking submissions, a lecturer uses untrusted mode (the default of check-class), "
          "where the code under test cannot reach that channel.");
}

// NOT PROVIDED verdicts say why in terms a student can act on.
void explain_not_provided(Verdict& v, const Property& p, const SubjectSet& s, const SubjectInfo& info) {
  if (v.outcome != Outcome::NotProvided) return;
  const auto kind = scalar_from_name(v.scalar);
  if (!kind) return;
  if (auto it = info.scalar_unavailable.find(v.scalar); it != info.scalar_unavailable.end()) {
    v.message = it->second;
    return;
  }
  for (const auto& need : p.needs) {
    if (!is_slot_name(need) || subject_provides(s, *kind, need)) continue;
    if (auto sc = info.slot_notes.find(v.scalar); sc != info.slot_notes.end())
      if (auto n = sc->second.find(need); n != sc->second.end()) {
        v.message = "needs slot '" + need + "': " + n->second;
        return;
      }
    if (*kind != ScalarKind::Double && subject_provides(s, ScalarKind::Double, need)) {
      v.message = "needs slot '" + need +
                  "', which is provided for double only (it is not a function template "
                  "on the scalar), so this check cannot run in " +
                  v.scalar;
      return;
    }
    v.message = "needs slot '" + need + "', which is not provided";
    return;
  }
  // A row of one integrator already says why (a step detected to compute in float, run in double only).
  if (p.scope == Scope::Integrator && *kind == ScalarKind::MP50 && v.integrator.empty()) {
    const auto in_double = integrators_for(p, s, ScalarKind::Double);
    if (in_double.empty()) return;
    // Each one stated to compute in double: the statement is the reason, not the signature.
    const bool all_stated = std::all_of(in_double.begin(), in_double.end(), [&](const std::string& name) {
      const IntegratorClaims* c = s.claims_for(name);
      return c && c->precision == "double";
    });
    v.message = all_stated ? "every integrator it drives is stated to compute in double (precision = \"double\"), so "
                             "it runs in double only"
                           : "the integrators are provided for double only (their steps are not function templates on "
                             "the scalar), so this check cannot run in mp50";
  }
}

std::vector<IntegratorInfo> integrator_info(const SubjectSet& s) {
  std::vector<IntegratorInfo> out;
  auto add = [&](const auto* sub, const char* scalar) {
    if (!sub) return;
    for (const auto& i : sub->integrators) {
      auto it = std::find_if(out.begin(), out.end(), [&](const IntegratorInfo& x) { return x.name == i.name; });
      if (it == out.end()) {
        IntegratorInfo info;
        info.name = i.name;
        info.form = i.form;
        if (const IntegratorClaims* c = s.claims_for(i.name)) {
          info.has_claims = true;
          info.claims = *c;
        }
        for (StepKind k : {StepKind::RigidBody, StepKind::Manakov, StepKind::Clebsch, StepKind::ManakovClebsch})
          if (has_step_kind(i, k)) info.steps.push_back(step_name(k));
        out.push_back(info);
        it = out.end() - 1;
      }
      it->scalars.push_back(scalar);
    }
  };
  add(s.d.get(), "double");
  add(s.mp.get(), "mp50");
  return out;
}

// Which property exercised which provided slot and integrator; what nothing exercised; what
// could not be checked at all (a check that ran nothing is not a pass).
void account_for_slots(CheckResult& result, const SubjectSet& s, const CheckConfig& cfg) {
  result.narrowed = !cfg.properties.empty() || !cfg.spec_prefix.empty() || cfg.scalars.size() < 3 ||
                    !cfg.integrator.empty() || !cfg.run.reproduce.empty() || !cfg.only_checks.empty();
  std::map<std::string, std::set<std::string>> by_slot;
  for (const auto& v : result.verdicts) {
    if (v.outcome == Outcome::NotProvided) continue;
    const Property* p = find_property(v.property);
    if (!p) continue;
    const auto kind = scalar_from_name(v.scalar);
    for (const auto& need : p->needs)
      if (kind && is_slot_name(need) && subject_provides(s, *kind, need)) by_slot[need].insert(p->id);
    if (!v.integrator.empty()) by_slot["integrator " + v.integrator].insert(p->id);
  }
  for (const auto& [slot, ps] : by_slot) result.exercised[slot] = std::vector<std::string>(ps.begin(), ps.end());
  const std::string why = result.narrowed ? "by the selected properties" : "by any property";
  std::set<std::string> provided;
  for (const auto& [scalar, slots] : result.provided) provided.insert(slots.begin(), slots.end());
  for (const auto& slot : provided)
    if (!by_slot.count(slot))
      result.unexercised.push_back("slot '" + slot + "' is provided but was not exercised " + why);
  for (const auto& i : result.integrators)
    if (!by_slot.count("integrator " + i.name))
      result.unexercised.push_back("integrator '" + i.name + "' is provided but was not exercised " + why);

  result.unchecked = result.info.unchecked;
  if (result.narrowed) return;  // a replay or a selection: unselected claims are "not selected", not unchecked
  for (const auto& i : result.integrators) {
    if (!i.has_claims) continue;
    auto check_claim = [&](const std::string& claim, bool claimed) {
      if (!claimed) return;
      // Checked: a check that judges the claim ran (its verdict decides it, a raise included).
      for (const auto& v : result.verdicts)
        if (v.integrator == i.name) {
          for (const auto& f : v.claims)
            if (f.claim == claim) return;
          if (v.outcome != Outcome::NotProvided) {
            const auto judged = judged_claims(v);
            if (std::find(judged.begin(), judged.end(), claim) != judged.end()) return;
          }
        }
      if (claim == "orthogonality" && i.form.has_quaternion())
        result.unchecked.push_back("integrator '" + i.name +
                                   "' claims orthogonality, but keeps its attitude as a "
                                   "quaternion: the matrix the suite reads it as, R(q / |q|), is orthogonal by "
                                   "construction, so nothing of yours is checked by it; claim unit_quaternion (|q| = 1 "
                                   "kept to round-off) instead");
      else
        result.unchecked.push_back("integrator '" + i.name + "' claims " + claim +
                                   ", and no property could check that claim (is its step provided in double?)");
    };
    check_claim("order", i.claims.order > 0);
    for (const auto& b : kBooleanClaims) check_claim(b.name, i.claims.*b.member);
  }
}

// One check's verdicts from how its task ended: the verdicts it returned (if they are its own), or
// one verdict saying how it ended (a crash, a timeout, a forgery); NOT PROVIDED ones say why.
std::vector<Verdict> verdicts_of(const SubjectSet& s, const SubjectInfo& info, const CheckConfig& cfg, const Item& item,
                                 const TaskResult& t) {
  std::vector<Verdict> vs;
  if (t.status == TaskResult::Status::Ok) {
    try {
      vs = verdicts_from_string(t.payload);
      check_verdicts_belong_to(vs, item);
    } catch (const ForeignResult& e) {
      vs = {abnormal_verdict(s, item, t, cfg.run)};  // an ERROR, with the seed and timing of this check
      vs.back().message = e.what();
    } catch (const std::exception& e) {
      TaskResult bad = t;
      bad.status = TaskResult::Status::Ok;
      vs = {abnormal_verdict(s, item, bad, cfg.run)};
      vs.back().message += std::string(" (") + e.what() + ")";
    }
  } else {
    vs = {abnormal_verdict(s, item, t, cfg.run)};
  }
  for (auto& v : vs) {
    explain_not_provided(v, *item.property, s, info);
    // What the code under test wrote or raised reaches the reports as inert text, each
    // text of a bounded size.
    bound_texts(v);
    v.message = inert_text(v.message);
    for (auto& [type, value] : v.counterexample) value = inert_text(value);
    for (auto& n : v.notes) n = inert_text(n);
    for (auto& c : v.claims) c.evidence = inert_text(c.evidence);
    v.discard_reason = inert_text(v.discard_reason);
  }
  return vs;
}

// Where a check goes in the schedule (run_check): smaller first.
std::tuple<int, int, int, int> schedule_key(const Item& item, bool replayed, bool claimed = false) {
  const Property& p = *item.property;
  int group;
  if (p.scope == Scope::Integrator)
    group = p.id.find("bounded_energy") != std::string::npos ? 4 : 3;  // the long runs last
  else if (p.needs.size() == 1 && p.id.rfind("definition_", 0) == 0)
    group = 0;  // a slot's own definition check
  else
    group = p.tolerance == ToleranceClass::Exact ? 1 : 2;  // identities before flows
  // Exact first where a property runs in rationals: its counterexample is the clearest (no
  // tolerance) and its cases are cheap; then double; 50 digits cost most.
  const int scalar = item.kind == ScalarKind::Exact ? 0 : item.kind == ScalarKind::Double ? 1 : 2;
  // An integrator's claimed checks before its unclaimed ones: a false claim leads the
  // output, what nobody claimed is characterised after.
  if (p.scope == Scope::Integrator) return {replayed ? 0 : 1, group, claimed ? 0 : 1, scalar};
  return {replayed ? 0 : 1, group, scalar, 0};
}

}  // namespace

std::string check_key(const Verdict& v) {
  return v.property + "/" + v.scalar + (v.integrator.empty() ? "" : "/" + v.integrator);
}

std::set<std::string> failed_checks_in_report(const std::string& dir) {
  std::set<std::string> out;
  if (dir.empty()) return out;
  try {
    std::ifstream in(dir + "/verdicts.json");
    if (!in) return out;
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const auto& v : j.at("verdicts")) {
      const std::string outcome = v.at("outcome").get<std::string>();
      if (outcome != "FAIL" && outcome != "CRASH" && outcome != "TIMEOUT" && outcome != "ERROR") continue;
      Verdict key;
      key.property = v.at("property").get<std::string>();
      key.scalar = v.at("scalar").get<std::string>();
      key.integrator = v.value("integrator", std::string());
      out.insert(check_key(key));
    }
  } catch (const std::exception&) {
    // no previous report, or one this version cannot read: nothing to replay first
  }
  return out;
}

int scalar_rank(const std::string& scalar) {
  if (scalar == "double") return 0;
  if (scalar == "mp50") return 1;
  if (scalar == "exact") return 2;
  return 3;
}

std::optional<ScalarKind> scalar_from_name(const std::string& name) {
  if (name == "double") return ScalarKind::Double;
  if (name == "mp50") return ScalarKind::MP50;
  if (name == "exact") return ScalarKind::Exact;
  return std::nullopt;
}

int CheckResult::count(Outcome o) const {
  return static_cast<int>(
      std::count_if(verdicts.begin(), verdicts.end(), [o](const Verdict& v) { return v.outcome == o; }));
}

int CheckResult::ran() const {
  return static_cast<int>(verdicts.size()) - count(Outcome::NotProvided) - count(Outcome::NotCharacterised);
}

bool CheckResult::ok() const {
  return count(Outcome::Fail) + count(Outcome::Crash) + count(Outcome::Timeout) + count(Outcome::Error) == 0 &&
         ran() > 0 && unchecked.empty();
}

int CheckResult::exit_code() const {
  for (const auto& v : verdicts)
    if (!v.machine_fault.empty()) return kExitMachine;
  return ok() ? 0 : 1;
}

std::string CheckResult::verdict_word() const {
  if (count(Outcome::Fail) + count(Outcome::Crash) + count(Outcome::Timeout) + count(Outcome::Error) > 0) return "FAIL";
  if (ran() == 0) return "NOTHING CHECKED";
  if (!unchecked.empty()) return "UNCHECKED";
  return "PASS";
}

std::string reproduce_command(const CheckResult& r, const Verdict& v) {
  if (!r.info.randomised) return r.info.reproduce_prefix;
  std::string prefix =
      r.info.reproduce_prefix.empty() ? "build/bin/geomech check --subject " + r.subject : r.info.reproduce_prefix;
  std::string cmd = prefix + " --property " + v.property + " --scalar " + v.scalar;
  if (!v.integrator.empty()) cmd += " --integrator " + v.integrator;
  if (!v.reproduce.empty())
    cmd += " --reproduce '" + v.reproduce + "'";
  else
    cmd += " --seed " + std::to_string(r.seed);
  return cmd;
}

namespace {

// The checks a run selects: each property in each scalar asked for, per integrator for an
// integrator's property; a 50-digit run left to --thorough is listed in result.left_to_thorough.
std::vector<Item> select_items(const SubjectSet& s, const CheckConfig& cfg, CheckResult& result) {
  std::vector<Item> items;
  for (const auto& p : properties()) {
    if (!cfg.properties.empty() &&
        std::find(cfg.properties.begin(), cfg.properties.end(), p.id) == cfg.properties.end())
      continue;
    if (!cfg.spec_prefix.empty() && p.spec.rfind(cfg.spec_prefix, 0) != 0) continue;
    for (ScalarKind k : cfg.scalars) {
      if (!p.runs_in(k)) continue;
      if (!cfg.only_checks.empty() && !cfg.only_checks.count(p.id + "/" + scalar_name(k))) continue;
      if (cfg.thorough_only.count(p.id + "/" + scalar_name(k))) {
        // Listed, not run; one whose slots are missing stays NOT PROVIDED, which says more.
        if (provides_needs(s, k, p) && (p.scope != Scope::Integrator || !integrators_for(p, s, k).empty())) {
          result.left_to_thorough.push_back(p.id + " [" + scalar_name(k) + "]");
          continue;
        }
      }
      if (p.scope == Scope::Integrator) {
        auto names = integrators_for(p, s, k);
        const bool has_any = !names.empty();
        if (!cfg.integrator.empty()) std::erase_if(names, [&](const std::string& n) { return n != cfg.integrator; });
        for (const auto& n : names) items.push_back(Item{&p, k, n});
        // With --integrator, a property none of whose integrators is the one asked for is left
        // out (it used to run all of them); with no integrator at all the runner says so.
        if (has_any) continue;
      }
      items.push_back(Item{&p, k, {}});
    }
  }
  return items;
}

// The selection in words (result.selection), with what this run leaves out.
void say_selection(const CheckConfig& cfg, CheckResult& result) {
  std::ostringstream sel;
  if (cfg.properties.empty() && cfg.spec_prefix.empty())
    sel << "all " << properties().size() << " properties";
  else {
    sel << "selected properties:";
    for (const auto& p : cfg.properties) sel << " --property " << p;
    if (!cfg.spec_prefix.empty()) sel << " --spec " << cfg.spec_prefix;
  }
  if (cfg.scalars.size() < 3) {
    sel << "; scalars:";
    for (auto k : cfg.scalars) sel << " " << scalar_name(k);
  }
  if (!cfg.integrator.empty()) sel << "; integrator " << cfg.integrator;
  if (!cfg.only_checks.empty()) sel.str(cfg.selection_note);
  if (!result.left_to_thorough.empty())
    sel << "; " << result.left_to_thorough.size() << " costly 50-digit runs left to --thorough";
  if (!cfg.case_factor_note.empty()) {
    result.case_factor = cfg.run.case_factor;
    result.case_factor_note = cfg.case_factor_note;
    sel << "; " << cfg.run.case_factor << " of each property's cases (--thorough: all)";
  }
  result.selection = sel.str();
  result.thorough_only_note = result.left_to_thorough.empty() ? "" : cfg.thorough_only_note;
}

// Whether an integrator's check judges a claim its integrator makes.
bool claimed(const SubjectSet& s, const Item& item) {
  if (item.integrator.empty()) return false;
  const IntegratorClaims* c = s.claims_for(item.integrator);
  return c != nullptr && claims_any(*c, item.property->judges);
}

// The checks that failed in the previous run of this report.
std::vector<bool> replayed_items(const SubjectSet& s, const CheckConfig& cfg, const std::vector<Item>& items) {
  std::vector<bool> replayed(items.size(), false);
  for (std::size_t i = 0; i < items.size(); ++i) {
    Verdict v = base_verdict(s, items[i]);
    replayed[i] = cfg.failed_before.count(check_key(v)) > 0;
  }
  return replayed;
}

// The order that finds the likely mistake first: what failed last time; then every slot's own
// definition check, in every scalar; then the other properties, algebraic identities before flows;
// then the integrators' claims after the slots their steps call; the long runs (bounded energy, the
// pictures and the work-precision diagram) start as the flows begin, so that the rest runs beside
// them (start_order_of), and their verdicts come last. Within a group the exact rationals and double
// before 50 digits, which cost most. The verdicts are sorted afterwards: the order changes when a
// result is known, never what it is.
std::vector<std::size_t> schedule(const SubjectSet& s, const std::vector<Item>& items,
                                  const std::vector<bool>& replayed) {
  std::vector<std::size_t> order(items.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto ka = schedule_key(items[a], replayed[a], claimed(s, items[a])),
               kb = schedule_key(items[b], replayed[b], claimed(s, items[b]));
    return ka < kb;
  });
  return order;
}

// The order tasks start in. The pictures and the work-precision diagram (the tasks after the
// n_items checks) are the longest single tasks (11 s for an untrusted C++ implementation, most of it
// alone at the end when started last): they start once the slots' own checks and the exact
// identities have started, so that the other checks run beside them. So do the bounded-energy runs,
// for the same reason: started last, `correct.m`'s (10 s) ran alone at the end of its check
// (2026-11-27). Their verdicts still come after every slot's own check.
std::vector<std::size_t> start_order_of(const SubjectSet& s, const std::vector<Item>& items,
                                        const std::vector<bool>& replayed, const std::vector<std::size_t>& order,
                                        std::size_t n_tasks) {
  const std::size_t n_items = order.size();
  auto group_from = [&](std::size_t from, int group) {
    while (from < n_items) {
      const auto key = schedule_key(items[order[from]], replayed[order[from]], claimed(s, items[order[from]]));
      if (std::get<0>(key) == 1 && std::get<1>(key) >= group) break;
      ++from;
    }
    return from;
  };
  const std::size_t split = group_from(0, 2), long_runs = group_from(split, 4);
  std::vector<std::size_t> start;
  for (std::size_t t = 0; t < split; ++t) start.push_back(t);
  for (std::size_t t = n_items; t < n_tasks; ++t) start.push_back(t);
  for (std::size_t t = long_runs; t < n_items; ++t) start.push_back(t);
  for (std::size_t t = split; t < long_runs; ++t) start.push_back(t);
  return start;
}

// The result's account of the subject before any check runs: its name, description, seed,
// integrators and the slots it provides in each scalar.
CheckResult result_of_subject(const SubjectSet& s, const SubjectInfo& info, const CheckConfig& cfg) {
  CheckResult result;
  result.subject = s.name;
  result.description = s.description;
  result.info = info;
  result.seed = cfg.run.seed;
  result.integrators = integrator_info(s);
  for (ScalarKind k : {ScalarKind::Double, ScalarKind::MP50, ScalarKind::Exact})
    for (const auto& slot : subject_slots())
      if (subject_provides(s, k, slot.name)) result.provided[scalar_name(k)].push_back(slot.name);
  return result;
}

// One task per check, in the scheduled order: it runs the property and returns its verdicts as text.
std::vector<std::function<std::string()>> check_tasks(const SubjectSet& s, const std::vector<Item>& items,
                                                      const std::vector<std::size_t>& order, const RunOptions& run) {
  std::vector<std::function<std::string()>> tasks;
  for (std::size_t i : order) {
    const Item item = items[i];
    tasks.push_back([&s, item, run]() {
      std::vector<Verdict> vs =
          item.integrator.empty()
              ? run_property(*item.property, s, item.kind, run)
              : run_property(*item.property, only_integrator(s, item.kind, item.integrator), item.kind, run);
      for (auto& v : vs) bound_texts(v);  // before they cross to the harness
      return verdicts_to_string(vs);
    });
  }
  return tasks;
}

// The limits and hooks the checks' processes run under: jobs, timeout, memory, isolation, workers.
IsolationOptions isolation_options(const SubjectInfo& info, const CheckConfig& cfg) {
  IsolationOptions io;
  io.jobs = cfg.jobs;
  io.timeout_seconds = cfg.timeout_given ? cfg.timeout_seconds : cfg.timeout_seconds * timeout_factor(info);
  io.memory_limit_mb = cfg.memory_limit_mb;
  io.isolate = cfg.isolate;
  io.prepare_worker = info.prepare_worker;
  io.worker_done = info.worker_done;
  io.worker_times = info.worker_times;  // the code's CPU and queueing behind the protocol
  // The suite's own tests bring the wall guard and the busy limit within seconds, so that a check
  // starved on purpose reaches them (GEOMECH_TEST_LIMITS="WALL_FACTOR WALL_FLOOR BUSY_FACTOR").
  if (const char* t = std::getenv("GEOMECH_TEST_LIMITS")) {
    std::istringstream in(t);
    double factor = 0, floor = 0, busy = 0;
    if (in >> factor >> floor >> busy && factor >= 1 && floor >= 0 && busy >= 1) {
      io.wall_factor = factor;
      io.wall_floor = floor;
      io.busy_factor = busy;
    }
  }
  return io;
}

// The verdicts in report order: by property, then scalar, then integrator.
void sort_verdicts(CheckResult& result) {
  std::stable_sort(result.verdicts.begin(), result.verdicts.end(), [](const Verdict& a, const Verdict& b) {
    if (a.property != b.property) return a.property < b.property;
    if (a.scalar != b.scalar) return scalar_rank(a.scalar) < scalar_rank(b.scalar);
    return a.integrator < b.integrator;
  });
}

}  // namespace

CheckResult run_check(const SubjectSet& s, const SubjectInfo& info, const CheckConfig& cfg) {
  const auto start = std::chrono::steady_clock::now();
  // Values and types in failures are written in the implementation's language (support/show.hpp);
  // the checks' processes inherit it.
  value_style() = info.language->values;
  CheckResult result = result_of_subject(s, info, cfg);

  const std::vector<Item> items = select_items(s, cfg, result);
  say_selection(cfg, result);

  // The order that finds the likely mistake first (schedule).
  const std::vector<bool> replayed = replayed_items(s, cfg, items);
  const std::vector<std::size_t> order = schedule(s, items, replayed);

  RunOptions run = cfg.run;
  run.out_of_process = info.out_of_process;
  std::vector<std::function<std::string()>> tasks = check_tasks(s, items, order, run);
  const std::size_t n_items = tasks.size();
  auto portrait_tasks = cfg.portraits ? portrait_task_list(s, cfg) : std::vector<PortraitTask>{};
  if (cfg.portraits)
    if (auto wp = work_precision_task(s, cfg)) {
      if (cfg.work_precision_left_out.empty())
        portrait_tasks.push_back(std::move(*wp));
      else
        result.work_precision_left_out = cfg.work_precision_left_out;
    }
  for (const auto& pt : portrait_tasks) tasks.push_back(pt.run);

  IsolationOptions io = isolation_options(info, cfg);
  io.start_order = start_order_of(s, items, replayed, order, tasks.size());

  // Each check's verdicts the moment it ends, told to the listeners (check_events.hpp).
  std::vector<std::vector<Verdict>> by_task(n_items);
  CheckProgress progress;
  progress.total = tasks.size();
  std::map<std::size_t, std::string> running;
  auto task_name = [&](std::size_t t) {
    if (t >= n_items) return std::string("pictures and work-precision diagram");
    const Item& item = items[order[t]];
    return item.property->id + " [" + scalar_name(item.kind) + (item.integrator.empty() ? "" : ", " + item.integrator) +
           "]";
  };
  auto tell_progress = [&]() {
    progress.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // What is left, at the pace so far (the long runs make this an underestimate until they have
    // run; it says "about").
    progress.left = progress.done == 0 ? -1.0
                                       : progress.elapsed / static_cast<double>(progress.done) *
                                             static_cast<double>(progress.total - progress.done);
    progress.running.clear();
    for (const auto& [t, name] : running) progress.running.push_back(name);
    for (CheckListener* l : cfg.listeners) l->progress(progress);
  };
  std::size_t replay_count = 0;
  for (bool r : replayed) replay_count += r;
  for (CheckListener* l : cfg.listeners) l->scheduled(progress.total, replay_count);
  io.on_started = [&](std::size_t t) {
    running[t] = task_name(t);
    tell_progress();
  };
  io.on_finished = [&](std::size_t t, const TaskResult& result) {
    running.erase(t);
    ++progress.done;
    if (t < n_items) {
      by_task[t] = verdicts_of(s, info, cfg, items[order[t]], result);
      progress.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      for (CheckListener* l : cfg.listeners) l->finished(by_task[t], replayed[order[t]], progress);
    }
    tell_progress();
  };
  const auto results = run_isolated(tasks, io);

  for (std::size_t t = 0; t < n_items; ++t)
    for (auto& v : by_task[t]) result.verdicts.push_back(std::move(v));
  for (std::size_t j = 0; j < portrait_tasks.size(); ++j)
    result.portraits.push_back(portrait_from_task(portrait_tasks[j], results[n_items + j]));

  sort_verdicts(result);
  keep_within_budget(result);
  account_for_slots(result, s, cfg);
  decide_integrator_verdicts(result);  // once; every view renders it
  decide_first_fixes(result);          // once, from the complete verdicts
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (CheckListener* l : cfg.listeners) l->ended(result);
  return result;
}

}  // namespace gm::harness
