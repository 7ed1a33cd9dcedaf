#include "properties/verdict.hpp"

namespace gm {

const char* outcome_name(Outcome o) {
  switch (o) {
    case Outcome::Pass:
      return "PASS";
    case Outcome::Fail:
      return "FAIL";
    case Outcome::NotProvided:
      return "NOT PROVIDED";
    case Outcome::Crash:
      return "CRASH";
    case Outcome::Timeout:
      return "TIMEOUT";
    case Outcome::Error:
      return "ERROR";
    case Outcome::NotCharacterised:
      return "NOT CHARACTERISED";
  }
  return "?";
}

std::string Verdict::key() const {
  std::string k = subject + "/" + property + "/" + scalar;
  if (!integrator.empty()) k += "/" + integrator;
  return k;
}

ProtocolCounts& protocol_counts() {
  static ProtocolCounts counts;  // per process: each check runs in a process of its own
  return counts;
}

}  // namespace gm
