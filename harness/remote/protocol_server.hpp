// The server side of the slot protocol (docs/PROTOCOL.md) for a SubjectSet: the handshake that
// describes it, and the answers to batches of calls. The C++ protocol server of untrusted mode
// (tools/student_server_main.cpp) is this, linked with the student's code alone: the
// properties, the reference implementation and the verdicts stay in the harness's process.
#pragma once

#include "core/subject.hpp"
#include "harness/checking/check.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace gm::protocol {

using nlohmann::json;

// The handshake: slots per scalar, integrators with their steps, scalars and claims, the notes on
// slots left out, the warnings, and what cannot be checked ("unchecked").
json hello_for(const SubjectSet& s, const harness::SubjectInfo& info, const std::string& language);

// The reply to one request {"id", "calls": [...]}: one {"ok": value} or {"error", "traceback"} per
// call, in order. A call of a slot the subject does not fill, or with arguments that do not decode,
// is an error result (the harness names it), never a crash of the server.
json answer(const SubjectSet& s, const json& request);

// Serves on the file descriptors until `in` ends: writes the handshake, then one reply line per
// request line. Returns 0 at the end of input, 2 after a line that is not a request (a fatal
// reply is written first).
int serve(const SubjectSet& s, const harness::SubjectInfo& info, const std::string& language, int in, int out);

}  // namespace gm::protocol
