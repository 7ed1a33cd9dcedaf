// `geomech mutants`: runs the properties on every mutant of mutation/catalogue.hpp, twice (in the
// full reference, and with the mutated slot alone), and reports the kill score per slot and per
// spec entry. Equivalent mutants (spec/equivalent_mutants.json, each with its argument in
// writing) are left out of the denominator.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace gm::mutation {

struct MutantsOptions {
  double case_factor = 0.3;
  std::uint64_t seed = 20261123;
  std::string slot;      // only mutants of this slot
  std::string mutant;    // only this mutant
  bool verbose = false;  // every property's verdict, no early stop
  int jobs = 2;
  double timeout_seconds = 900;
  double min_score = 0.98;
  std::string report_dir;
  std::string equivalent_file;  // default: spec/equivalent_mutants.json in the source tree
  bool alone = true;            // also run the "alone" mode
  std::string front_door = "geomech";
  // The kill matrix. Every property and scalar runs on every mutant in the full
  // reference (no stop at the first kill), timed; the report gains the matrix and the quick
  // profile chosen from it (mutation/kill_matrix.hpp), written to `quick_profile_out` if set.
  bool matrix = false;
  std::string quick_profile_out;
  // The 50-digit runs an implementation behind the protocol leaves to `geomech check --thorough`
  // (choose_thorough_only), written to this file if set.
  std::string thorough_only_out;
  // A mutants.json written by an earlier `--matrix --report` run: its matrix is read instead of
  // running the mutants again (28 minutes on 2 cores), to choose the profiles from it anew.
  std::string from_report;
  // The protocol, measured too: each mutant is also served out of process by the C++ protocol server
  // (`program serve-mutant NAME`, mutation/served_mutant.hpp) and checked through the protocol,
  // as an untrusted submission is; the score through the protocol is reported beside the other.
  bool through_protocol = false;
  std::string program;  // the geomech program that serves mutants (default: this one)
};

struct ModeResult {
  bool ran = false;
  bool killed = false;
  std::string killed_by;                // "property [scalar] OUTCOME: first line of the message"
  std::vector<std::string> properties;  // properties that ran (not NOT PROVIDED)
  std::vector<std::string> undeclared;  // properties that called a slot they do not declare (alone mode)
  std::vector<std::string> log;         // verbose: one line per verdict
  std::string error;
  // With --matrix: "property/scalar" -> (killed there, seconds it took).
  std::map<std::string, std::pair<bool, double>> cells;
  int matrix_skipped = 0;  // cells not started: the mutant's matrix budget was spent
};

struct MutantResult {
  std::string name, slot, op, op_class, description, integrator;
  bool equivalent = false;
  // Equivalent with the mutated slot alone only (a negated hat_n is another valid
  // convention of so(n) coordinates on its own, and wrong beside the reference's vee_n).
  bool equivalent_alone_only = false;
  std::string equivalence_argument;
  // Whether the mutant is out of the denominator in the mode `alone` (or the full reference).
  bool equivalent_in(bool alone) const { return equivalent && (alone || !equivalent_alone_only); }
  // Survives in a mode where it is not equivalent.
  bool survives() const {
    return (!equivalent_in(false) && full.ran && !full.killed) || (!equivalent_in(true) && alone.ran && !alone.killed);
  }
  std::vector<std::string> spec_entries;  // spec entries of the properties that apply to it
  ModeResult full, alone;
  ModeResult protocol;  // the full reference's mutant served through the protocol (through_protocol)
  double seconds = 0;
};

struct Equivalence {
  std::string argument;
  bool alone_only = false;
};

struct Tally {
  int mutants = 0, killed = 0, equivalent = 0, survived = 0;
  double score() const { return mutants - equivalent > 0 ? double(killed) / (mutants - equivalent) : 1.0; }
};

struct MutantsRun {
  std::vector<MutantResult> results;
  std::vector<std::string> baseline_failures;     // properties failing on the reference itself (left out)
  std::map<std::string, Equivalence> equivalent;  // name -> argument
  std::vector<std::string> unknown_equivalents;   // names in the file that are no mutant
  double seconds = 0;
  MutantsOptions options;
};

// Equivalent mutants: name -> argument, and whether only with the mutated slot alone ("alone_only":
// true in the file). Throws on a malformed file.
std::map<std::string, Equivalence> load_equivalent(const std::string& path);
std::string default_equivalent_path();

MutantsRun run_mutants(const MutantsOptions& o);
// The run recorded in a mutants.json (json_report); throws std::runtime_error naming the file.
MutantsRun load_mutants_report(const std::string& path);
Tally tally(const MutantsRun& r, bool alone, const std::string& slot = "", const std::string& spec = "");
// The score through the protocol (MutantResult::protocol), and the mutants whose verdict there
// differs from the in-process one (killed in one and not the other).
Tally tally_protocol(const MutantsRun& r);
std::vector<std::string> protocol_differences(const MutantsRun& r);
std::string console_table(const MutantsRun& r);
std::string markdown_report(const MutantsRun& r);
std::string json_report(const MutantsRun& r);

// The command's whole behaviour: run, print, write the report; returns the exit code.
int mutants_command(const MutantsOptions& o);

}  // namespace gm::mutation
