// main() of the C++ protocol server (untrusted mode): linked with the student's objects,
// the part registry and the protocol's server code only; no property, reference implementation or
// verdict is in this program. It answers docs/PROTOCOL.md on stdin and the reply descriptor.
#include "harness/program/student_registry.hpp"
#include "harness/remote/protocol_server.hpp"

#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <iostream>

int main() {
  // Replies go to the descriptor the harness names ($GEOMECH_REPLY_FD, docs/PROTOCOL.md), so that
  // the student's printing (printf, std::cout) can never be taken for one; without it, to the
  // original standard output, and the student's printing to stderr.
  const char* reply_fd = std::getenv("GEOMECH_REPLY_FD");
  int protocol_out = reply_fd && *reply_fd ? std::atoi(reply_fd) : ::dup(1);
  if (!(reply_fd && *reply_fd)) ::dup2(2, 1);
  std::ios::sync_with_stdio(true);
  gm::harness::SubjectInfo info;
  const gm::SubjectSet s = gm::student::assemble("", info, nlohmann::json());
  return gm::protocol::serve(s, info, "c++", 0, protocol_out);
}
