// main() of the C++ protocol server (untrusted mode, issue 14): linked with the student's objects,
// the part registry and the protocol's server code only; no property, reference implementation or
// verdict is in this program. It answers docs/PROTOCOL.md on stdin/stdout; whatever the student's
// code prints goes to stderr, so it can never be taken for a reply.
#include "harness/protocol_server.hpp"
#include "harness/student_registry.hpp"

#include <cstdio>
#include <iostream>
#include <unistd.h>

int main() {
  const int protocol_out = ::dup(1);
  ::dup2(2, 1);  // the student's printing (printf, std::cout) lands on stderr
  std::ios::sync_with_stdio(true);
  gm::harness::SubjectInfo info;
  const gm::SubjectSet s = gm::student::assemble("", info, nlohmann::json());
  return gm::protocol::serve(s, info, "c++", 0, protocol_out);
}
