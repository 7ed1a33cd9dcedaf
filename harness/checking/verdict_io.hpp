// Verdicts as JSON: how a forked child hands its verdicts back to the harness, and the
// machine-readable part of a report (verdicts.json, read back by class mode).
// Doubles that are not finite (an infinite residual in eps units, a NaN in a data series) are
// written as the strings "inf", "-inf" and "nan", which JSON itself cannot hold.
#pragma once

#include "properties/runner.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace gm::harness {

nlohmann::json to_json(const Verdict& v);
Verdict verdict_from_json(const nlohmann::json& j);  // throws nlohmann::json::exception on bad input

std::string verdicts_to_string(const std::vector<Verdict>& vs);
std::vector<Verdict> verdicts_from_string(const std::string& s);

nlohmann::json number_to_json(double x);
double number_from_json(const nlohmann::json& j);

Outcome outcome_from_name(const std::string& name);  // inverse of outcome_name; throws on unknown

}  // namespace gm::harness
