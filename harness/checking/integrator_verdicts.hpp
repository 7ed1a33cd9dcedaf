// One verdict per integrator, claim and scalar, decided once (DESIGN.md "A verdict is
// decided once"): a claims block, a table row, a JUnit case, a verdicts.json entry, a class summary
// and a gradebook cell are views of these records, never decisions of their own.
//
// A check of an integrator (an integrator-scoped property) judges one claim (PropertyDef::judges).
// Its row says what it found:
//   PASS, FAIL, CRASH, TIMEOUT, ERROR, NOT PROVIDED   as for any check;
//   NOT CHARACTERISED                                 nothing it judges was claimed and the step raised;
//   holds / does not hold / not established (not claimed)   a check of a claim nobody made.
// A claim is decided from every check that judges it, in every scalar the integrator has:
//   verified         claimed; every one of them ran all its planned cases and passed, with complete
//                    findings (a finding is complete when it is the measurement that verifies the
//                    claim: not a run shortened for an unclaimed row, not "not measurable");
//   FALSE CLAIM      claimed; a complete measurement contradicts it;
//   NOT VERIFIED     claimed; a check it rests on could not decide (the step raised, crashed, timed
//                    out, ran fewer cases than planned), with which and why;
//   holds / does not hold / not established   the same, for a claim nobody made;
//   the order, never claimed, is measured and shown ("order 1.00"), and DOES NOT CONVERGE when the
//   checks that ask every integrator to converge fail.
// A scalar in which no check of the claim ran (a selection, the 50-digit runs left to --thorough) is
// said in the word: "verified (double; mp50: left to --thorough)".
#pragma once

#include "harness/checking/check.hpp"

#include <string>
#include <vector>

namespace gm::harness {

// The word of a verdict whose not-pass is the machine's or the set-up's (Verdict::machine_fault).
inline constexpr const char* kMachineErrorWord = "ERROR (the machine's)";

// The claims a verdict's check judges: its property's `judges`, or, for checks that are not in the
// registry (trajectory files), the claims it reported findings on.
std::vector<std::string> judged_claims(const Verdict& v);

// The word of one verdict, from its outcome, its findings and the claims of its integrator (null:
// nothing claimed). For a verdict that is not an integrator's, its outcome's name.
std::string verdict_word(const Verdict& v, const IntegratorClaims* claims);

// Every claim an integrator can make (and any other a check reported on), decided.
std::vector<ClaimDecision> decide_claims(const CheckResult& r, const IntegratorInfo& integrator);

// Decides once, at the end of a check: Verdict::word of every verdict, IntegratorInfo::decisions of
// every integrator. Idempotent.
void decide_integrator_verdicts(CheckResult& r);

// "verified", "FALSE CLAIM", ...: a status's word without its qualifications.
const char* status_word(ClaimStatus s);

// Whether a decision fails the check (a false or unverified claim: something claimed is not shown
// true); decisions about claims nobody made never do.
bool fails_check(const ClaimDecision& d);

}  // namespace gm::harness
