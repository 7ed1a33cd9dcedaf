// A subject implemented out of process: a child program (the Python or Octave server, or any
// program speaking docs/PROTOCOL.md) that the harness talks to over its stdin/stdout with one
// JSON object per line. To the properties it is a SubjectSet like any other.
//
// A connection belongs to one process: the harness forks a child per property, so each slot call
// checks getpid() and, in a new process, starts its own copy of the implementation (lazily, on the
// first call). A crash or hang of the implementation therefore ends only the check that was using
// it (the harness's per-check timeout and process-group kill apply to it).
#pragma once

#include "harness/check.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <memory>
#include <set>
#include <mutex>
#include <string>
#include <sys/types.h>
#include <vector>

namespace gm::protocol {

using nlohmann::json;

inline constexpr const char* kProtocolName = "geomech-slots";
inline constexpr int kProtocolVersion = 1;

// The implementation's process failed (could not start, died, wrote something that is not the
// protocol). The message names the slot and includes what the program wrote to stderr, if known.
class RemoteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The implementation's own code raised an error for a call: the message carries its traceback.
class RemoteCallError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One call of a batch: a slot, or an integrator's step ({"slot": "rigid_body_step", "integrator": name}).
struct Call {
  std::string slot;
  std::string scalar;  // "double", "mp50", "exact"
  json args;           // an array
  std::string integrator;
};

// A reply to one call: the encoded result, or the implementation's error text.
struct Reply {
  bool ok = false;
  json result;
  std::string error;
};

// The slot table handed to the child in $GEOMECH_SLOT_TABLE: protocol, version, mp50_bits, and
// every slot {name, signature, place, meaning} of GM_SUBJECT_SLOTS, plus the integrator steps.
std::string slot_table_json();

// The child program and its pipes, for the current process.
class Connection {
 public:
  explicit Connection(std::vector<std::string> argv, std::string language = "");
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // The handshake (starts the program in this process if needed).
  const json& hello();
  // One request with many calls, one reply per call in order. Throws RemoteError when the
  // program dies or answers out of protocol.
  std::vector<Reply> call_batch(const std::vector<Call>& calls);
  // One call: the result, or RemoteCallError carrying the implementation's traceback.
  json call(const Call& c);
  // Stops the program (it is started again on the next call).
  void stop();
  const std::vector<std::string>& argv() const { return argv_; }
  const std::string& language() const { return language_; }

 private:
  void ensure_started();
  std::string read_line();
  std::string stderr_tail();
  std::string how_it_ended(const std::string& otherwise);  // "exited with status 0", ...

  std::vector<std::string> argv_;
  std::string language_;
  std::string table_;  // $GEOMECH_SLOT_TABLE for the child (slot_table_json())
  std::mutex mutex_;
  pid_t owner_ = 0;  // the process that started the child
  pid_t child_ = -1;
  int to_child_ = -1, from_child_ = -1, child_err_ = -1;
  std::string buffer_;
  json hello_;
  long next_id_ = 1;
};

// What the handshake said, checked and turned into the harness's terms.
struct RemoteDescription {
  std::string language;
  std::string description;
  std::map<std::string, std::set<std::string>> slots;  // scalar -> slots
  struct Integrator {
    std::string name;
    std::vector<std::string> steps;
    std::vector<std::string> scalars;
    bool has_claims = false;
    IntegratorClaims claims;
  };
  std::vector<Integrator> integrators;
  std::map<std::string, std::map<std::string, std::string>> notes;  // scalar -> slot -> reason
  std::vector<std::string> warnings;
  std::vector<std::string> unchecked;                      // written but not checkable (fails the check)
  std::map<std::string, std::string> scalar_unavailable;  // scalar -> why nothing is provided there
};

// Throws RemoteError for a handshake that is not this protocol (wrong name or version, bad fields).
RemoteDescription parse_hello(const json& hello);

// The SubjectSet whose slots call the program. `info` receives the slot notes and warnings of the
// handshake. The handshake is done here, in the calling process; the program is then stopped and
// each process that calls a slot starts its own.
SubjectSet remote_subject(const std::shared_ptr<Connection>& conn, const std::string& name, harness::SubjectInfo& info);

// How to start the server for an implementation file, from its extension (.py, .m, or a folder of
// .m files); empty when the extension is not one of these. `why` says what is missing.
std::vector<std::string> server_command(const std::string& file, std::string* language, std::string* why);

}  // namespace gm::protocol
