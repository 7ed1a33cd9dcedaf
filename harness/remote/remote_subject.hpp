// A subject implemented out of process: a child program (the Python or Octave server, or any
// program speaking docs/PROTOCOL.md) that the harness talks to over its stdin/stdout with one
// JSON object per line. To the properties it is a SubjectSet like any other.
//
// A connection belongs to one process: the harness forks a child per property, so each slot call
// checks getpid() and, in a new process, starts its own copy of the implementation (lazily, on the
// first call). A crash or hang of the implementation therefore ends only the check that was using
// it (the harness's per-check timeout and process-group kill apply to it).
#pragma once

#include "harness/checking/check.hpp"
#include "harness/isolation/work_limit.hpp"
#include "harness/remote/call_memo.hpp"

#include <nlohmann/json.hpp>

#include <sys/types.h>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace gm::protocol {

using nlohmann::json;

inline constexpr const char* kProtocolName = "geomech-slots";
inline constexpr int kProtocolVersion = 2;
inline constexpr int kMaxWorkers = 256;  // the isolation's --jobs limit

// The implementation's process failed (could not start, died, wrote something that is not the
// protocol). The message names the slot and includes what the program wrote to stderr, if known.
class RemoteError : public ProcessFailure {
 public:
  using ProcessFailure::ProcessFailure;
};

// The grader's machine, not the implementation, stopped it: the sandbox did not start its process,
// or the kernel's accounting says the machine starved the task a reply waited on.
class RemoteMachineFault : public RemoteError {
 public:
  using RemoteError::RemoteError;
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
  // An integrator's step taken this many times in a row, the state of each step the next one's
  // (docs/PROTOCOL.md, "repeat"); the reply is the list of the states. 0: one plain call.
  int repeat = 0;
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

// One running copy of the implementation's program and its pipes.
struct ServerProcess {
  pid_t pid = -1;
  int to = -1;              // its standard input: requests
  int replies = -1;         // its descriptor 3: the protocol's replies
  int output = -1;          // its standard output and error: what the implementation prints
  std::string buffer;       // reply bytes read but not yet taken
  std::string output_tail;  // the end of what it printed
  bool running() const { return pid > 0; }
};

// The implementation's program, started as child processes that speak docs/PROTOCOL.md.
//
// Checks run in forked processes (harness/isolation/isolate.hpp), up to one per worker slot at a time. The
// process that creates the Connection keeps one server per slot (prepare_worker); a check's process
// opens a session on its slot's server (the server forks a fresh copy of the loaded implementation
// for it), so a check starts in milliseconds from the state the handshake saw and leaves nothing
// behind for the next (worker_done ends the session, or restarts the server when the check ended
// abnormally or left the protocol in an unknown state). A server that does not offer sessions is
// started afresh in each check's process instead (protocol version 1's way).
class Connection {
 public:
  explicit Connection(std::vector<std::string> argv, std::string language = "");
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // The handshake (starts the program in this process if needed). Throws RemoteError when the
  // program does not answer within `handshake_seconds` or answers out of protocol.
  const json& hello();
  // One request with many calls, one reply per call in order. Throws RemoteError when the
  // program dies or answers out of protocol; that program is then not used again (a later call
  // starts a fresh copy).
  std::vector<Reply> call_batch(const std::vector<Call>& calls);
  // One call: the result, or RemoteCallError carrying the implementation's traceback.
  json call(const Call& c);
  // Stops every program this process started (they are started again when needed).
  void stop();

  // The isolation's worker hooks (harness/isolation/isolate.hpp), in the process that created this.
  void prepare_worker(int w);
  // The CPU and run-queue delay of the server of worker slot w (or this process's own copy) and
  // everything it started, so far (a check's limit counts the code's CPU; the delay tells starved
  // from asleep).
  harness::TreeTimes server_times(int w) const;
  void worker_done(int w, bool ended_normally);

  const std::vector<std::string>& argv() const { return argv_; }
  const std::string& language() const { return language_; }
  bool sessions() const { return sessions_; }
  // The handshake's limit, judged like a check's (harness/isolation/work_limit.hpp): the CPU time of
  // the implementation's process tree, a wall guard for one that sleeps, and the machine's fault
  // only when the kernel's accounting says it starved the task the handshake waits on. `reply_limit`
  // holds the guard's factors of every deadline on a reply (its CPU seconds are each deadline's).
  double handshake_seconds = 60;
  harness::WorkLimit reply_limit;

 private:
  // Per worker slot, shared between the process that started the servers and the checks' processes
  // (anonymous shared memory): whether a session is open and whether a request is unanswered.
  struct SlotState {
    int session_open;
    int in_flight;
  };
  void start(ServerProcess& s);
  void kill_server(ServerProcess& s);
  ServerProcess& server_for_this_process();
  json request(ServerProcess& s, const json& req, const std::string& what, double deadline_seconds);
  json request_text(ServerProcess& s, const std::string& text, long id, const std::string& what,
                    double deadline_seconds);
  // call_batch with each call's arguments already written as JSON text (args_texts[i] for calls[i]).
  std::vector<Reply> exchange(const std::vector<Call>& calls, const std::vector<std::string>& args_texts);
  std::string read_reply(ServerProcess& s, const std::string& what, double deadline_seconds);
  std::string died(ServerProcess& s, const std::string& otherwise);

  std::vector<std::string> argv_;
  std::string language_;
  std::string table_;  // $GEOMECH_SLOT_TABLE for the child (slot_table_json())
  std::mutex mutex_;
  pid_t owner_;                      // the process that created this (and owns `pool_`)
  std::vector<ServerProcess> pool_;  // per worker slot, started by the owner
  std::vector<bool> prepared_;       // per worker slot: prepare_worker ran and worker_done not yet
  SlotState* slots_ = nullptr;       // per worker slot (kMaxWorkers), shared memory
  ServerProcess own_;                // a server started in this process (no sessions, or a check's own)
  pid_t own_pid_ = 0;                // the process that started `own_`
  pid_t session_pid_ = 0;            // the process whose session is open on its slot's server
  pid_t abandoned_pid_ = 0;          // the process whose session failed (it uses a copy of its own since)
  json hello_;
  CallMemo memo_;  // this process's replies, by call (under memo_mutex_)
  std::mutex memo_mutex_;
  bool sessions_ = false;
  long next_id_ = 1;
};

// What the handshake said, checked and turned into the harness's terms.
struct RemoteDescription {
  std::string language;
  std::string language_version;  // the interpreter's version ("3.11.7")
  std::string interpreter;       // the interpreter's program, as the server says ("/usr/bin/python3")
  std::string description;
  std::map<std::string, std::set<std::string>> slots;  // scalar -> slots
  struct Integrator {
    std::string name;
    std::vector<std::string> steps;
    std::vector<std::string> scalars;
    bool has_claims = false;
    IntegratorClaims claims;  // with the stated precision and its reason, if any
    StateForm form;           // "state": the form its rigid_body_step keeps the state in (core/state_form.hpp)
  };
  std::vector<Integrator> integrators;
  std::map<std::string, std::map<std::string, std::string>> notes;  // scalar -> slot -> reason
  std::vector<std::string> warnings;
  std::vector<std::string> unchecked;                     // written but not checkable (fails the check)
  std::map<std::string, std::string> scalar_unavailable;  // scalar -> why nothing is provided there
  bool repeat = false;  // the server takes "repeat" on an integrator's step (a run of steps in one call)
};

// Throws RemoteError for a handshake that is not this protocol (wrong name or version, bad fields).
RemoteDescription parse_hello(const json& hello);

// The SubjectSet whose slots call the program. `info` receives the slot notes and warnings of the
// handshake. The handshake is done here, in the calling process; the program is then stopped and
// each process that calls a slot starts its own.
SubjectSet remote_subject(const std::shared_ptr<Connection>& conn, const std::string& name, harness::SubjectInfo& info);

// Writes all of `text` to `fd` (retrying short writes and EINTR); false if the descriptor is gone.
// The client's requests and the C++ server's replies (harness/remote/protocol_server.cpp) both use it.
bool write_all(int fd, const std::string& text);

}  // namespace gm::protocol
