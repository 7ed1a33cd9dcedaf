#include "properties/runner.hpp"

#include "properties/support/step_guard.hpp"
#include "properties/support/step_precision.hpp"
#include "properties/support/tolerance.hpp"

#include <rapidcheck.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <optional>
#include <regex>
#include <sstream>
#include <unordered_map>

// Exported by librapidcheck but declared only in its private headers.
namespace rc::detail {
std::string reproduceMapToString(const std::unordered_map<std::string, Reproduce>& reproduceMap);
std::unordered_map<std::string, Reproduce> stringToReproduceMap(const std::string& str);
}  // namespace rc::detail

namespace gm {

std::uint64_t derive_seed(std::uint64_t base, const std::string& property_key) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a
  for (unsigned char c : property_key) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h ^ (base * 0x9E3779B97F4A7C15ull);
}

namespace {

// RapidCheck describes a discard as "file:line:\nRC_DISCARD(...)\n\nreason" or, for RC_PRE,
// "file:line:\nRC_PRE(condition)\n\nExpands to:\nvalues". The reason is the text after the blank
// line for RC_DISCARD, and the condition that did not hold for RC_PRE.
std::string discard_reason(const std::string& text) {
  const auto head_end = text.find('\n');
  const auto blank = text.find("\n\n");
  if (head_end == std::string::npos || blank == std::string::npos || blank < head_end) return text;
  const std::string macro = text.substr(head_end + 1, blank - head_end - 1);
  std::string rest = text.substr(blank + 2);
  while (!rest.empty() && rest.back() == '\n') rest.pop_back();
  if (rest.rfind("Expands to:", 0) == 0 || rest.empty()) {
    std::string condition = macro;
    if (condition.rfind("RC_PRE(", 0) == 0 && condition.back() == ')')
      condition = condition.substr(7, condition.size() - 8);
    return "the precondition " + condition + " does not hold";
  }
  return rest;
}

using Clock = std::chrono::steady_clock;

// Thrown by the listener between cases when the case budget is spent: RapidCheck's search loop
// calls the listener outside any handler of its own, so this leaves the loop after a passing case.
struct CaseBudgetSpent {
  int passed;
};

// The text of the discard that stands for "shrinking stopped by its budget" in the final run.
constexpr const char* kShrinkStopped = "geomech: shrinking stopped by its time budget";
// What RapidCheck says of a case that ran and threw nothing (rapidcheck/detail/Property.hpp).
constexpr const char* kRapidCheckSuccess = "no exceptions thrown";

// Prints nothing; counts the discarded cases (a discarded case is not a check, and the
// verdict says how many there were); keeps the time budgets (RunOptions) and the last failing case
// seen, which stands for the counterexample when shrinking is stopped.
class SilentListener : public rc::detail::TestListener {
 public:
  SilentListener(Clock::time_point start, const RunOptions& o, int planned)
      : start_(start),
        cpu_start_(code_cpu_seconds()),
        case_budget_(o.case_budget_seconds),
        shrink_budget_(o.shrink_budget_seconds),
        planned_(planned) {}

  int discarded = 0;
  std::string first_reason;
  // The smallest failing case found so far (the first failure, then each accepted shrink).
  bool failed = false;
  std::string failure_description;
  std::vector<std::pair<std::string, std::string>> failure_example;

  void onTestCaseFinished(const rc::detail::CaseDescription& d) override {
    using Type = rc::detail::CaseResult::Type;
    if (d.result.type == Type::Discard) {
      if (discarded++ > 0) return;
      first_reason = discard_reason(d.result.description);
      return;
    }
    if (d.result.type == Type::Failure) {
      failed = true;
      failure_time_ = Clock::now();
      failure_cpu_ = code_cpu_seconds();
      keep(d);
      return;
    }
    ++passed_;
    if (case_budget_ > 0 && passed_ < planned_ && code_cpu_seconds() - cpu_start_ > case_budget_)
      throw CaseBudgetSpent{passed_};
  }
  void onShrinkTried(const rc::detail::CaseDescription& d, bool accepted) override {
    if (accepted) keep(d);
  }
  void onTestFinished(const rc::detail::TestMetadata&, const rc::detail::TestResult&) override {}

  // During shrinking: whether the shrink budget is spent (each further candidate is then discarded
  // before it runs, so shrinking ends quickly with the smallest failure found).
  bool shrink_budget_spent() const {
    return failed && shrink_budget_ > 0 && code_cpu_seconds() - failure_cpu_ > shrink_budget_;
  }

 private:
  static double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
  void keep(const rc::detail::CaseDescription& d) {
    failure_description = d.result.description;
    failure_example = d.example ? d.example() : decltype(failure_example){};
    failure_raise = current_step_raise();  // the case that just ran
  }

 public:
  // The step's raise in the failing case kept (the one reported), if the step raised there.
  std::optional<StepRaise> failure_raise;

 private:
  Clock::time_point start_, failure_time_;
  double cpu_start_ = 0, failure_cpu_ = 0;
  double case_budget_, shrink_budget_;
  int planned_;
  int passed_ = 0;
};

struct RcEnv {
  std::optional<std::uint64_t> seed;
  std::optional<int> max_success;
  std::unordered_map<std::string, rc::detail::Reproduce> reproduce;
};

// $RC_PARAMS, read the way RapidCheck documents it (seed=, max_success=, reproduce=).
const RcEnv& rc_env() {
  static const RcEnv env = [] {
    RcEnv e;
    const char* s = std::getenv("RC_PARAMS");
    if (!s || !*s) return e;
    rc::detail::Configuration defaults;
    defaults.testParams.seed = 0;
    defaults.testParams.maxSuccess = -1;
    try {
      auto cfg = rc::detail::configFromString(s, defaults);
      if (cfg.testParams.seed != 0) e.seed = cfg.testParams.seed;
      if (cfg.testParams.maxSuccess >= 0) e.max_success = cfg.testParams.maxSuccess;
      e.reproduce = cfg.reproduce;
    } catch (const std::exception& ex) {
      std::fprintf(stderr, "geomech: ignoring malformed RC_PARAMS (%s)\n", ex.what());
    }
    return e;
  }();
  return env;
}

// The type of a counterexample value in the student's language (support/show.hpp, ValueStyle): Python
// and Octave students never wrote Vec3<Real50>.
std::string in_language(const std::string& shown) {
  const ValueStyle& style = value_style();
  if (style.vector_type.empty()) return shown;
  static const std::regex typed(R"((Vec|Mat)(\w+)<(\w+)>)");
  std::smatch m;
  auto scalar = [&](const std::string& S) {
    return S == "Rational" ? style.rational_name : S == "double" ? style.double_name : style.mp50_name;
  };
  auto fill = [](std::string pattern, const std::string& n, const std::string& s) {
    for (auto at = pattern.find("{n}"); at != std::string::npos; at = pattern.find("{n}")) pattern.replace(at, 3, n);
    for (auto at = pattern.find("{s}"); at != std::string::npos; at = pattern.find("{s}")) pattern.replace(at, 3, s);
    return pattern;
  };
  if (std::regex_match(shown, m, typed)) {
    const std::string kind = m[1], dims = m[2], S = scalar(m[3]);
    if (kind == "Vec") return fill(dims == "X" ? style.any_vector_type : style.vector_type, dims, S);
    return fill(dims == "XxX" ? style.any_matrix_type : style.matrix_type, dims, S);
  }
  if (shown == "double" || shown == "Real50" || shown == "Rational") return scalar(shown);
  return shown;
}

// RapidCheck names counterexample values by their C++ type; Eigen-over-Boost types are pages
// long. Shorten them to Vec3<Rational>, Mat3x3<Real50>, VecX<double>, ...
std::string pretty_type(const std::string& t) {
  auto scalar = [](const std::string& s) -> std::string {
    if (s.find("rational_adaptor") != std::string::npos) return "Rational";
    if (s.find("cpp_bin_float<50") != std::string::npos) return "Real50";
    if (s.find("cpp_bin_float<70") != std::string::npos) return "Real70";
    if (s.find("double") != std::string::npos) return "double";
    if (s.find("int") != std::string::npos && s.find("<") == std::string::npos) return s;
    return {};
  };
  if (t.rfind("gm::Polynomial<", 0) == 0) return "Polynomial<" + scalar(t) + ">";  // support/polynomial.hpp
  if (t.rfind("Eigen::Matrix<", 0) == 0) {
    // ..., R, C, Options, MaxR, MaxC>
    std::vector<std::string> parts;
    std::string cur;
    int depth = 0;
    for (std::size_t i = std::string("Eigen::Matrix<").size(); i < t.size(); ++i) {
      const char c = t[i];
      if (c == '<') ++depth;
      if (c == '>') {
        if (depth == 0) break;
        --depth;
      }
      if (c == ',' && depth == 0) {
        parts.push_back(cur);
        cur.clear();
      } else if (c != ' ') {
        cur += c;
      }
    }
    parts.push_back(cur);
    if (parts.size() >= 3) {
      const std::string S = scalar(parts[0]);
      auto dim = [](const std::string& d) { return d == "-1" ? std::string("X") : d; };
      if (!S.empty()) {
        if (parts[2] == "1") return "Vec" + dim(parts[1]) + "<" + S + ">";
        return "Mat" + dim(parts[1]) + "x" + dim(parts[2]) + "<" + S + ">";
      }
    }
    return t;
  }
  const std::string S = scalar(t);
  return S.empty() ? t : S;
}

// Whether a counterexample label is a type as pretty_type and in_language render it (a drawn value
// without a name) rather than a name given by the property.
bool is_type_label(const std::string& label) {
  static const std::regex type(
      R"((.*(<|::).*)|int|unsigned( int)?|long|bool|double|float|char|Real50|Real70|Rational|Fraction|mpf|matrix|)"
      R"((\d+ )?(list of|column vector|matrix).*|\d+x\d+ column vector|(\d+-)?list of .*)");
  return std::regex_match(label, type);
}

}  // namespace

bool counterexample_by_name(const Verdict& v) {
  if (v.counterexample.empty()) return false;
  for (const auto& [label, value] : v.counterexample)
    if (is_type_label(label)) return false;
  return true;
}

bool inputs_in_message(const Verdict& v) { return v.message.find("inputs, by the notes' names:") != std::string::npos; }

std::string counterexample_heading(const Verdict& v) {
  std::string h = v.shrink_stopped ? "counterexample (shrinking stopped by its time budget; not minimal)"
                                   : "counterexample (shrunk)";
  return h + (counterexample_by_name(v) ? ", by the notes' names:" : ":");
}

namespace {

int default_cases(const Property& p, ScalarKind k) {
  switch (k) {
    case ScalarKind::Double:
      return p.cases.d;
    case ScalarKind::MP50:
      return p.cases.mp;
    case ScalarKind::Exact:
      return p.cases.q;
  }
  return 1;
}

thread_local const RunOptions* run_options_in_progress = nullptr;

std::function<double()>& code_cpu_clock() {
  static std::function<double()> clock;
  return clock;
}

template <class Fn>
void run_checked(Verdict& v, const Property& p, ScalarKind k, const RunOptions& o, Fn&& fn) {
  const auto start = Clock::now();
  struct Current {
    const RunOptions* saved = run_options_in_progress;
    explicit Current(const RunOptions& o) { run_options_in_progress = &o; }
    ~Current() { run_options_in_progress = saved; }
  } current(o);
  static const RcEnv no_env;
  const RcEnv& env = o.honour_rc_params ? rc_env() : no_env;
  std::uint64_t base = o.seed;
  if (env.seed) base = *env.seed;
  // Not the integrator's name: every integrator of a subject is checked on the same draws,
  // so that identical steps get identical verdicts, to the last digit of their evidence.
  v.seed = derive_seed(base, p.id + "/" + v.scalar);

  rc::detail::TestParams params;
  params.seed = v.seed;
  int cases = o.cases > 0 ? o.cases : static_cast<int>(default_cases(p, k) * o.case_factor + 0.5);
  if (env.max_success) cases = *env.max_success;
  params.maxSuccess = cases < 1 ? 1 : cases;
  v.cases_planned = params.maxSuccess;
  params.maxSize = 100;
  params.disableShrinking = !o.shrink;

  rc::detail::TestMetadata metadata;
  metadata.id = v.key();
  metadata.description = p.title;

  std::unordered_map<std::string, rc::detail::Reproduce> reproduce = env.reproduce;
  if (!o.reproduce.empty()) reproduce = rc::detail::stringToReproduceMap(o.reproduce);

  std::string missing_slot;
  residual_log().reset();
  recorded_claims().clear();
  SilentListener listener(start, o, params.maxSuccess);
  std::optional<rc::detail::TestResult> result;
  int budget_passed = -1;  // >= 0: the case budget stopped the run after this many passing cases
  auto attempt = [&](const std::unordered_map<std::string, rc::detail::Reproduce>& with) {
    try {
      result = rc::detail::checkProperty(rc::detail::toProperty([&] {
                                           if (listener.shrink_budget_spent()) RC_DISCARD(kShrinkStopped);
                                           recorded_series().clear();
                                           recorded_notes().clear();
                                           current_step_raise().reset();
                                           quaternion_sign_given() =
                                               1;  // an attitude regime of this case may draw the other sign
                                           try {
                                             fn();
                                           } catch (const SlotMissing& e) {
                                             missing_slot = e.slot();
                                             throw;
                                           } catch (const OutsideDomain& e) {
                                             // A state or step outside the integrator's declared domain: not checked.
                                             current_step_raise().reset();
                                             RC_DISCARD(e.what());
                                           }
                                         }),
                                         metadata, params, listener, with);
    } catch (const CaseBudgetSpent& b) {
      budget_passed = b.passed;
    }
  };
  attempt(reproduce);
  // A replayed case that passes alone, where the check it came from failed, depends on
  // what the implementation kept from earlier calls (a cache, a global). The replay then runs the
  // whole sequence of the check again, from its seed, and names the state if it fails there.
  bool state_between_calls = false;
  if (rc::detail::Error replay_error; !reproduce.empty() && result && result->match(replay_error) &&
                                      replay_error.description.find("not a failure") != std::string::npos) {
    attempt({});
    rc::detail::FailureResult again;
    state_between_calls = result && result->match(again);
  }

  v.series = recorded_series();
  recorded_series().clear();
  v.notes = recorded_notes();
  recorded_notes().clear();
  v.claims = recorded_claims();
  recorded_claims().clear();
  const auto& log = residual_log();
  v.worst_eps_units = log.worst_eps_units;
  v.worst_absolute = log.worst_absolute;
  v.worst_check = log.worst_check;
  v.checks = log.checks;
  v.discarded = listener.discarded;
  v.discard_reason = listener.first_reason;

  rc::detail::SuccessResult success;
  rc::detail::FailureResult failure;
  rc::detail::GaveUpResult gave_up;
  rc::detail::Error error;
  if (budget_passed >= 0) {
    v.outcome = Outcome::Pass;
    v.cases = budget_passed;
  } else if (result->match(success)) {
    v.outcome = Outcome::Pass;
    v.cases = success.numSuccess;
  } else if (result->match(failure)) {
    v.cases = failure.numSuccess;
    if (!missing_slot.empty()) {
      v.outcome = Outcome::Error;
      v.message = "property '" + p.id + "' called slot '" + missing_slot +
                  "' without listing it in its needs (a defect of the property, not of the subject)";
    } else {
      v.outcome = Outcome::Fail;
      v.message = failure.description;
      if (state_between_calls)
        v.message = "fails after " + std::to_string(failure.numSuccess) +
                    " earlier cases of this check, not alone: the case replayed by itself passes, so the "
                    "implementation keeps state between calls (a cache, a global, a default argument changed in "
                    "place) and a later call sees what an earlier one left. The whole sequence replays with "
                    "--seed instead of --reproduce.\n" +
                    failure.description;
      auto example = failure.counterExample;
      if (listener.failed && failure.description.find(kShrinkStopped) != std::string::npos) {
        // The final run of the smallest case was discarded by the shrink budget: that case failed
        // when it was tried, with this description and these inputs.
        v.shrink_stopped = true;
        v.message = listener.failure_description;
        example = listener.failure_example;
      } else if (listener.failed && failure.description == kRapidCheckSuccess) {
        // RapidCheck's words for a run that passed: the smallest case failed when it was tried and
        // passed when run again (the implementation's process died or answered "fatal" the first
        // time, and a fresh copy answered). What it failed with is the listener's.
        v.message = listener.failure_description +
                    "\n(this case failed when it was tried and passed when run again: the implementation does not "
                    "answer the same input the same way each time)";
        example = listener.failure_example;
      }
      for (const auto& [type, value] : example) v.counterexample.emplace_back(in_language(pretty_type(type)), value);
      if (listener.failure_raise) {
        v.step_raised = listener.failure_raise->message;
        v.step_raised_where = listener.failure_raise->where;
        v.step_raised_rate = listener.failure_raise->rate;
        v.step_raised_size = listener.failure_raise->size;
      }
      // A state-dependent failure replays as the whole sequence (the seed), not as its last case.
      if (!state_between_calls) v.reproduce = rc::detail::reproduceMapToString({{metadata.id, failure.reproduce}});
    }
  } else if (result->match(gave_up)) {
    v.outcome = Outcome::Error;
    v.cases = gave_up.numSuccess;
    v.message = "gave up after too many discarded cases: " + gave_up.description;
  } else if (result->match(error)) {
    v.outcome = Outcome::Error;
    v.message = error.description;
  }
  v.seconds = std::chrono::duration<double>(Clock::now() - start).count();
}

template <class T>
Verdict base_verdict(const Property& p, const SubjectSet& s) {
  Verdict v;
  v.subject = s.name;
  v.property = p.id;
  v.spec = p.spec;
  v.title = p.title;
  v.scalar = ScalarInfo<T>::name;
  return v;
}

// NOT PROVIDED reasons shared by both scopes; empty when everything is there.
template <class T>
std::string missing_for(const Property& p, const SubjectSet& s, Outcome& outcome) {
  outcome = Outcome::NotProvided;
  const Subject<T>* subject = s.get<T>();
  if (!subject)
    return std::string("the subject has no ") + ScalarInfo<T>::name +
           " instantiation (write it as a template on the scalar to be checked in " + ScalarInfo<T>::name + ")";
  for (const auto& need : p.needs) {
    if (!is_slot_name(need)) {
      outcome = Outcome::Error;
      return "property '" + p.id + "' lists '" + need + "' in its needs, which is not a subject slot";
    }
    if (!subject->provides(need)) return "needs slot '" + need + "', which the subject does not provide";
  }
  return {};
}

template <class T>
std::vector<Verdict> run_in(const Property& p, const SubjectSet& s, ScalarKind k, const RunOptions& o,
                            const SubjectBody<T>* body, const IntegratorBody<T>* ibody) {
  std::vector<Verdict> out;
  Outcome why_outcome;
  const std::string why = missing_for<T>(p, s, why_outcome);
  if (p.scope == Scope::Subject) {
    Verdict v = base_verdict<T>(p, s);
    if (!why.empty()) {
      v.outcome = why_outcome;
      v.message = why;
    } else {
      const Subject<T>& subject = *s.get<T>();
      run_checked(v, p, k, o, [&] { (*body)(subject); });
    }
    out.push_back(std::move(v));
    return out;
  }
  if (!why.empty()) {
    Verdict v = base_verdict<T>(p, s);
    v.outcome = why_outcome;
    v.message = why;
    out.push_back(std::move(v));
    return out;
  }
  const Subject<T>& subject = *s.get<T>();
  for (const auto& integrator : subject.integrators) {
    if (!has_step_kind(integrator, p.step)) continue;  // integrators for another system are not candidates
    Verdict v = base_verdict<T>(p, s);
    v.integrator = integrator.name;
    const IntegratorClaims* claims = s.claims_for(integrator.name);
    IntegratorClaims none;
    none.integrator = integrator.name;
    const Integrator<T> guarded_integrator = guarded(integrator);  // a raise is told as one
    // A claim is verified only on all its planned cases: no time budget cuts them (a
    // slow step takes longer; the timeout still stops a hang).
    RunOptions all_cases = o;
    all_cases.case_budget_seconds = 0;
    struct Domain {  // the integrator's declared domain, for the draws and the guard
      StepDomain saved = current_step_domain();
      explicit Domain(const StepDomain& d) { current_step_domain() = d; }
      ~Domain() { current_step_domain() = saved; }
    } domain(claims ? claims->domain : StepDomain{});
    // The precision the step computes in, for every tolerance of its checks.
    const JudgedAt precision(precision_to_judge<T>(guarded_integrator, claims));
    // A step detected to compute in float is judged as one stated to: in double only (a 50-digit run
    // of a float computation measures float's round-off again).
    if constexpr (!std::is_same_v<T, double>) {
      if (current_step_precision().detected && current_step_precision().coarser_than<double>()) {
        v.outcome = Outcome::NotProvided;
        v.message = "your step computes in " + current_step_precision().name + " (" + current_step_precision().how +
                    "), so it is checked in double only, as a step stated to compute in " +
                    current_step_precision().name + " is";
        out.push_back(std::move(v));
        continue;
      }
    }
    run_checked(v, p, k, all_cases, [&] { (*ibody)(subject, guarded_integrator, claims ? *claims : none); });
    // A raise beyond some size does not hide a finding below it: with no domain declared, the check
    // is run again inside the range where the step was seen to work (|Omega| and |Pi| below a
    // quarter of where it raised, when that still holds the states the checks draw, of size about
    // 1). A failure there is the verdict, said with the raise; a pass there leaves the raise's verdict
    // (the claim is not verified beyond) and says it passes inside.
    const bool declared = claims && claims->domain.declared();
    // A replay (--reproduce) runs the one case it names and says what that case does, as the run it
    // replays printed it: the runs again below draw cases of their own, which a replay's string
    // would force into the case it names instead.
    const bool replay = !o.reproduce.empty();
    if (!replay && v.outcome == Outcome::Fail && !v.step_raised.empty() && !declared && v.step_raised_rate >= 64 &&
        v.step_raised_size >= 64) {
      StepDomain inside;
      inside.max_omega = v.step_raised_rate / 4;
      inside.max_pi = v.step_raised_size / 4;
      Verdict again = base_verdict<T>(p, s);
      again.integrator = integrator.name;
      {
        Domain narrowed(inside);
        run_checked(again, p, k, all_cases, [&] { (*ibody)(subject, guarded_integrator, claims ? *claims : none); });
      }
      char range[160];
      std::snprintf(range, sizeof range, "|Omega| <= %.3g and |Pi| <= %.3g", inside.max_omega, inside.max_pi);
      const std::string raised =
          "your step raised at " + v.step_raised_where + ": " + v.step_raised.substr(0, v.step_raised.find('\n'));
      if (again.step_raised.empty() && again.outcome == Outcome::Fail) {
        again.message = raised + "; run again inside " + range +
                        " (where it works; declare a domain to set it), the check fails there too:\n" + again.message;
        again.notes.push_back(raised + "; the check was run again inside " + range + ", where it fails");
        v = std::move(again);
      } else if (again.step_raised.empty() && again.outcome == Outcome::Pass &&
                 !claims_any(claims ? *claims : none, p.judges)) {
        // Nothing was claimed: what was measured inside is the finding ("holds (not claimed)"), said
        // with the range and the raise beyond it, never "nothing could be measured".
        again.notes.push_back(raised + "; measured inside " + range + ", where the step works");
        again.message = "measured inside " + std::string(range) + ", where the step works (" + raised + ")" +
                        (again.message.empty() ? "" : "\n" + again.message);
        v = std::move(again);
      } else if (again.step_raised.empty() && again.outcome == Outcome::Pass) {
        v.notes.push_back("run again inside " + std::string(range) + " (where the step works), the check passes there");
        v.message += std::string("\n(run again inside ") + range + ", where the step works, the check passes there)";
      }
    }
    // A claimed check that failed with a raise is run once more with the raising cases discarded:
    // when the cases that run to their end fail, the claim is contradicted (FALSE CLAIM, said with the
    // raise), not merely unverified; when they pass, the raise's verdict stays.
    if (!replay && v.outcome == Outcome::Fail && !v.step_raised.empty() && claims && claims_any(*claims, p.judges)) {
      Verdict again = base_verdict<T>(p, s);
      again.integrator = integrator.name;
      {
        struct Discarding {
          Discarding() { discard_step_raises() = true; }
          ~Discarding() { discard_step_raises() = false; }
        } discarding;
        run_checked(again, p, k, all_cases, [&] { (*ibody)(subject, guarded_integrator, *claims); });
      }
      const std::string raised =
          "your step raised at " + v.step_raised_where + ": " + v.step_raised.substr(0, v.step_raised.find('\n'));
      if (again.outcome == Outcome::Fail && again.step_raised.empty()) {
        again.message = raised + "; in the cases where it did not raise the check fails too:\n" + again.message;
        again.notes.push_back(raised + "; the cases where it did not raise fail too");
        v = std::move(again);
      } else if (again.outcome == Outcome::Pass) {
        v.notes.push_back("the cases where the step did not raise pass");
      }
    }
    // The step raised in the case reported: a claimed property FAILS (its claim could not be
    // verified); one that judges only claims nobody made, or none, could measure nothing and says so.
    if (v.outcome == Outcome::Fail && !v.step_raised.empty() && !claims_any(claims ? *claims : none, p.judges)) {
      // Cases that ran to their end before the raise keep what they measured: said, not "nothing".
      std::string before;
      for (const auto& f : v.claims)
        if (!f.holds) before = f.evidence;
      v.outcome = Outcome::NotCharacterised;
      v.message = "not characterised: your step raised at " + v.step_raised_where + ": " + v.step_raised +
                  (before.empty() ? " (nothing of " + (p.judges.empty() ? std::string("this") : p.judges.front()) +
                                        " was claimed, and nothing could be measured)"
                                  : " (not claimed; before that, a case measured to its end: " + before + ")");
      v.counterexample.clear();
      v.reproduce.clear();
    }
    if (current_step_precision().template coarser_than<T>()) {
      v.judged_precision = current_step_precision().name;
      v.judged_precision_how = current_step_precision().how;
    }
    out.push_back(std::move(v));
  }
  if (out.empty()) {
    Verdict v = base_verdict<T>(p, s);
    v.outcome = Outcome::NotProvided;
    v.message = std::string("the subject provides no integrator with a ") + step_name(p.step);
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace

void set_code_cpu_clock(std::function<double()> clock) { code_cpu_clock() = std::move(clock); }

namespace {
double self_cpu() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

double code_cpu_seconds() {
  if (code_cpu_clock()) return code_cpu_clock()();
  return self_cpu();
}

const RunOptions& current_run_options() {
  static const RunOptions defaults;
  return run_options_in_progress ? *run_options_in_progress : defaults;
}

bool claims_any(const IntegratorClaims& c, const std::vector<std::string>& judged) {
  for (const auto& claim : judged) {
    if (claim == "order" && c.order > 0) return true;
    for (const auto& b : kBooleanClaims)
      if (claim == b.name && c.*b.member) return true;
  }
  return false;
}

std::vector<Verdict> run_property(const Property& p, const SubjectSet& s, ScalarKind k, const RunOptions& o) {
  // A slot's own definition check compares the subject's result with the notes' formula: its
  // failures say "yours" and "the notes'" rather than lhs and rhs.
  struct Sides {
    detail::SideNames saved = detail::side_names();
    ~Sides() { detail::side_names() = saved; }
  } restore;
  const bool definition = p.scope == Scope::Subject && p.needs.size() == 1 && p.id.rfind("definition_", 0) == 0;
  detail::side_names() = definition ? detail::SideNames{"yours", "the notes'"} : detail::SideNames{};
  const ProtocolCounts before = protocol_counts();
  const double self_before = self_cpu(), code_before = code_cpu_seconds();
  std::vector<Verdict> out;
  switch (k) {
    case ScalarKind::Double:
      out = run_in<double>(p, s, k, o, &p.d, &p.int_d);
      break;
    case ScalarKind::MP50:
      out = run_in<Real50>(p, s, k, o, &p.mp, &p.int_mp);
      break;
    case ScalarKind::Exact:
      out = run_in<Rational>(p, s, k, o, &p.q, nullptr);
      break;
  }
  // Where the time went, shared evenly among the verdicts of one run (one per integrator).
  const ProtocolCounts& after = protocol_counts();
  const double self = self_cpu() - self_before, code = code_cpu_seconds() - code_before;
  const double n = out.empty() ? 1.0 : static_cast<double>(out.size());
  for (auto& v : out) {
    v.protocol.calls = static_cast<long>((after.calls - before.calls) / n);
    v.protocol.round_trips = static_cast<long>((after.round_trips - before.round_trips) / n);
    v.protocol.memo_hits = static_cast<long>((after.memo_hits - before.memo_hits) / n);
    v.protocol.waiting_seconds = (after.waiting_seconds - before.waiting_seconds) / n;
    // In process, the code under test runs on the suite's own clock: all of it is counted as the suite's.
    v.code_cpu_seconds = code_cpu_clock() ? (code - self) / n : 0.0;
    v.suite_cpu_seconds = self / n;
  }
  return out;
}

bool is_reproduce_string(const std::string& text, std::string* why) {
  try {
    (void)rc::detail::stringToReproduceMap(text);
    return true;
  } catch (const std::exception& e) {
    if (why) *why = e.what();
    return false;
  }
}

std::string reproduce_command(const Verdict& v) {
  std::ostringstream os;
  os << "build/bin/geomech check --subject " << v.subject << " --property " << v.property << " --scalar " << v.scalar
     << " --reproduce '" << v.reproduce << "'";
  return os.str();
}

std::string format_verdict(const Verdict& v) {
  std::ostringstream os;
  char eps_buf[64] = "";
  if (v.checks > 0) std::snprintf(eps_buf, sizeof eps_buf, "%.3g", v.worst_eps_units);
  os << outcome_name(v.outcome) << "  " << v.property << "  [" << v.scalar
     << (v.integrator.empty() ? "" : ", " + v.integrator) << "]  spec " << v.spec;
  if (v.outcome == Outcome::Pass) {
    os << "  (" << v.cases << " cases";
    if (v.cases_planned > v.cases) os << " of " << v.cases_planned << " planned: the time budget was spent";
    if (v.discarded > 0) os << ", " << v.discarded << " discarded";
    if (v.scalar != "exact" && v.checks > 0) os << ", worst residual " << eps_buf << " eps";
    os << ")";
    for (const auto& n : v.notes) os << "\n  note: " << n;
    return os.str();
  }
  os << "\n  " << v.title;
  if (!v.message.empty()) {
    std::istringstream lines(v.message);
    for (std::string line; std::getline(lines, line);) os << "\n  | " << line;
  }
  if (!v.counterexample.empty() && !inputs_in_message(v)) {
    os << "\n  " << counterexample_heading(v);
    for (const auto& [type, value] : v.counterexample) os << "\n    " << type << " = " << value;
  }
  if (v.outcome == Outcome::Fail) {
    os << "\n  after " << v.cases << " passing cases; seed " << v.seed;
    os << "\n  reproduce: RC_PARAMS=\"reproduce=" << v.reproduce << "\"";
    os << "\n         or: " << reproduce_command(v);
  }
  return os.str();
}

}  // namespace gm
