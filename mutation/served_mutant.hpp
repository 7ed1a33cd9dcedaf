// The mutation score through the protocol (item 5): a mutant of the reference served out
// of process by the C++ protocol server, as untrusted mode serves a student's C++ file, and checked
// through remote_subject like any implementation in another language. A mutant the suite kills
// in-process but not through the protocol (or the reverse) would show the codec or the client
// changing what the properties see.
#pragma once

#include "core/subject.hpp"

#include <string>

namespace gm::mutation {

// `program serve-mutant NAME`: the mutant (of the full reference) behind the protocol, in this
// process. Throws std::runtime_error when the server cannot start or its handshake is not the
// protocol.
SubjectSet served_mutant(const std::string& program, const std::string& name);

// main() of `geomech serve-mutant NAME`: serves that mutant of the reference on stdin and the
// reply descriptor ($GEOMECH_REPLY_FD, docs/PROTOCOL.md) until the input ends. 2 for an unknown name.
int serve_mutant_command(const std::string& name);

}  // namespace gm::mutation
