#include "mutation/served_mutant.hpp"

#include "harness/remote/protocol_server.hpp"
#include "harness/remote/remote_subject.hpp"
#include "impl/reference_subject.hpp"
#include "mutation/catalogue.hpp"

#include <unistd.h>
#include <cstdlib>
#include <iostream>
#include <memory>

namespace gm::mutation {

SubjectSet served_mutant(const std::string& program, const std::string& name) {
  auto conn = std::make_shared<protocol::Connection>(std::vector<std::string>{program, "serve-mutant", name}, "c++");
  harness::SubjectInfo info;
  return protocol::remote_subject(conn, name, info);
}

int serve_mutant_command(const std::string& name) {
  const SubjectSet& ref = reference_subject();
  for (const auto& m : all_mutants(ref)) {
    if (m.name != name) continue;
    // Replies go to the descriptor the harness names, as in the untrusted C++ server
    // (tools/student_server_main.cpp); the reference prints nothing.
    const char* reply_fd = std::getenv("GEOMECH_REPLY_FD");
    const int out = reply_fd && *reply_fd ? std::atoi(reply_fd) : ::dup(1);
    harness::SubjectInfo info;
    return protocol::serve(m.full(ref), info, "c++", 0, out);
  }
  std::cerr << "geomech serve-mutant: no mutant is named '" << name << "' (see `geomech mutants --verbose`)\n";
  return 2;
}

}  // namespace gm::mutation
