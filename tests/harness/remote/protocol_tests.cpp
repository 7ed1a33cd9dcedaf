// The slot protocol's client (harness/remote/remote_subject, protocol_codec) against the Python, Octave
// and JavaScript servers: exact round trips in all three scalars, shape validation naming the slot, an error reply
// carrying the Python traceback; sessions (each check starts from the handshake's state, on one
// server per worker), a crash failing its check alone with how it died, printing that neither
// blocks nor breaks the protocol, a hang while loading caught by the handshake's deadline, which is
// judged by the kernel's accounting (a starved handshake is the machine's); the per-call round-trip cost.
#include "harness/isolation/isolate.hpp"
#include "harness/languages/language.hpp"
#include "harness/languages/rows.hpp"
#include "harness/remote/protocol_codec.hpp"
#include "harness/remote/remote_subject.hpp"
#include "tests/harness/harness_support.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace gm::protocol {
namespace {

using harness::octave_server_program;
using harness::server_command;

std::shared_ptr<Connection> connect(const std::string& path) {
  std::string language, why;
  auto cmd = server_command(std::string(GM_SOURCE_DIR) + "/" + path, &language, &why);
  return std::make_shared<Connection>(cmd, language);
}

std::shared_ptr<Connection> python(const std::string& example) { return connect("examples/students/" + example); }

// Tasks run as the harness runs checks: forked, `jobs` at once, with the subject's worker hooks.
std::vector<harness::TaskResult> run_as_checks(const harness::SubjectInfo& info,
                                               const std::vector<std::function<std::string()>>& tasks, int jobs) {
  harness::IsolationOptions o;
  o.jobs = jobs;
  o.timeout_seconds = 120;
  o.prepare_worker = info.prepare_worker;
  o.worker_done = info.worker_done;
  return harness::run_isolated(tasks, o);
}

std::string call_text(const std::function<double()>& f) {
  try {
    return std::to_string(static_cast<long long>(f()));
  } catch (const std::exception& e) {
    return std::string("error: ") + e.what();
  }
}

TEST(ProtocolCodec, ScalarsRoundTripExactly) {
  const double d = 0.1 + 0.2;
  EXPECT_EQ(decode_scalar<double>(json(encode_scalar(d)), "x"), d);
  const Real50 r = Real50(1) / 3;
  EXPECT_EQ(decode_scalar<Real50>(json(encode_scalar(r)), "x"), r);
  const Rational q = Rational(-7) / 12;
  EXPECT_EQ(encode_scalar(q), "-7/12");
  EXPECT_EQ(decode_scalar<Rational>(json(encode_scalar(q)), "x"), q);
}

// A step's state may hold what the step computed, NaN or an infinity, in each language's spelling;
// a slot's result may not, and an overflowing decimal is a number, refused as not finite.
TEST(ProtocolCodec, AStepsStateCarriesNaNAndInfinitiesASlotsResultDoesNot) {
  for (const char* word : {"nan", "NaN", "-nan", "inf", "-inf", "+inf", "Inf", "-Inf", "Infinity"}) {
    EXPECT_FALSE(std::isfinite(decode_scalar<double>(json(word), "x", Values::any))) << word;
    EXPECT_FALSE(boost::multiprecision::isfinite(decode_scalar<Real50>(json(word), "x", Values::any))) << word;
    EXPECT_THROW(decode_scalar<double>(json(word), "x"), ProtocolValueError) << word;
    EXPECT_THROW(decode_scalar<Real50>(json(word), "x"), ProtocolValueError) << word;
  }
  EXPECT_TRUE(std::isnan(decode_scalar<double>(json("nan"), "x", Values::any)));
  EXPECT_EQ(decode_scalar<double>(json("-Inf"), "x", Values::any), -std::numeric_limits<double>::infinity());
  EXPECT_THROW(decode_scalar<double>(json("1e999"), "x", Values::any), ProtocolValueError);
  EXPECT_THROW(decode_scalar<double>(json("nano"), "x", Values::any), ProtocolValueError);
  const auto x = decode<double, RigidBodyState<double>>(
      json{{"Pi", {"1", "nan", "2"}}, {"O", {{"1", "0", "0"}, {"0", "inf", "0"}, {"0", "0", "1"}}}}, "r", Values::any);
  EXPECT_TRUE(std::isnan(x.Pi(1)) && std::isinf(x.O(1, 1)));
  EXPECT_THROW((decode<double, RigidBodyState<double>>(
                   json{{"Pi", {"1", "nan", "2"}}, {"O", {{"1", "0", "0"}, {"0", "1", "0"}, {"0", "0", "1"}}}}, "r")),
               ProtocolValueError);
}

TEST(ProtocolCodec, ShapesAreValidatedWithTheirPlace) {
  try {
    decode<double, Vec3<double>>(json::array({"1", "2"}), "the result of python function 'euler_3_8' (double)");
    FAIL();
  } catch (const ProtocolValueError& e) {
    EXPECT_NE(std::string(e.what()).find("euler_3_8"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("3 entries"), std::string::npos);
  }
  EXPECT_THROW((decode<double, Vec3<double>>(json::array({"1", "nan", "2"}), "r")), ProtocolValueError);
  EXPECT_THROW((decode<double, MatX<double>>(json::array({json::array({"1", "2"}), json::array({"1"})}), "r")),
               ProtocolValueError);
  EXPECT_THROW((decode<Real50, Real50>(json(0.1), "r")), ProtocolValueError);  // a JSON float cannot carry 50 digits
  // An entry that does not decode is named by its place, although the place's text is built only
  // then (decode_entry).
  for (const json& bad : {json::array({json::array({"1", "2"}), json::array({"3", "x"})}),
                          json::array({json::array({"1", "2"}), json::array({"3", "1e999"})})}) {
    try {
      decode<double, MatX<double>>(bad, "the result of f");
      ADD_FAILURE() << bad.dump();
    } catch (const ProtocolValueError& e) {
      EXPECT_NE(std::string(e.what()).find("the result of f[1][1]"), std::string::npos) << e.what();
    }
  }
}

// The harness writes a double as its shortest round-trip decimal (std::to_chars); every double,
// the subnormal and the largest among them, reads back the same, whether written that way, as
// "%.17g" (what the Octave server sends), or as a fraction.
TEST(ProtocolCodec, EveryDoubleRoundTripsInTheShortestText) {
  EXPECT_EQ(encode_scalar(0.1), "0.1");
  EXPECT_EQ(encode_scalar(-2.0), "-2");
  std::vector<double> xs = {0.0,
                            -0.0,
                            0.1 + 0.2,
                            1.0 / 3.0,
                            std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::min(),
                            std::numeric_limits<double>::max(),
                            -std::numeric_limits<double>::max()};
  std::uint64_t bits = 0x9E3779B97F4A7C15ull;  // a fixed sequence of bit patterns (xorshift)
  while (xs.size() < 20000) {
    bits ^= bits << 13, bits ^= bits >> 7, bits ^= bits << 17;
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (std::isfinite(x)) xs.push_back(x);
  }
  for (const double x : xs) {
    const std::string text = encode_scalar(x);
    const double back = decode_scalar<double>(json(text), "x");
    ASSERT_EQ(std::memcmp(&back, &x, sizeof x), 0) << text;
    ASSERT_LE(text.size(), 24u) << text;
    char printed[40];
    std::snprintf(printed, sizeof printed, "%.17g", x);
    const double from_printf = decode<double, Vec3<double>>(json::array({printed, text, "1/4"}), "v")(0);
    ASSERT_EQ(std::memcmp(&from_printf, &x, sizeof x), 0) << printed;
  }
}

TEST(RemoteSubject, PythonCorrectAllScalars) {
  harness::SubjectInfo info;
  const SubjectSet s = remote_subject(python("correct.py"), "correct", info);
  ASSERT_TRUE(s.d && s.mp && s.q);
  const Vec3<Rational> I(Rational(2), Rational(1), Rational(1, 2)), P(Rational(1, 4), Rational(-3, 2), Rational(3));
  const Vec3<Rational> want(P.cross(P.cwiseQuotient(I)));
  EXPECT_EQ(s.q->euler_3_8(I, P), want);
  const Vec3<Real50> got = s.mp->euler_3_8(I.cast<Real50>(), P.cast<Real50>());
  EXPECT_EQ(got, want.unaryExpr([](const Rational& x) { return convert<Real50>(x); }).eval());
  EXPECT_FALSE(s.d->integrators.empty());
}

TEST(RemoteSubject, ErrorReplyCarriesTheTraceback) {
  harness::SubjectInfo info;
  const SubjectSet s = remote_subject(python("bug_exception.py"), "bug_exception", info);
  try {
    s.d->spatial_momentum(Mat3<double>::Identity(), Vec3<double>(1, 2, 3));
    FAIL();
  } catch (const RemoteCallError& e) {
    EXPECT_NE(std::string(e.what()).find("IndexError"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("spatial_momentum"), std::string::npos) << e.what();
  }
}

// A process forked outside the harness's worker pool (not prepared by run_isolated) starts a copy
// of its own; the parent's server goes on answering.
TEST(RemoteSubject, AForkOutsideTheWorkerPoolStartsItsOwnServer) {
  harness::SubjectInfo info;
  const SubjectSet s = remote_subject(python("correct.py"), "correct", info);
  EXPECT_EQ(s.d->hamiltonian_3_4(Vec3<double>(2, 1, 1), Vec3<double>(2, 0, 0)), 1.0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const double h = s.d->hamiltonian_3_4(Vec3<double>(2, 1, 1), Vec3<double>(0, 2, 0));
    ::_exit(h == 2.0 ? 0 : 1);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(s.d->hamiltonian_3_4(Vec3<double>(2, 1, 1), Vec3<double>(0, 0, 2)), 2.0);
}

// Sessions. Every check sees the implementation as its handshake left it (a module-level
// counter starts at 0 in each), and all checks of a worker reach the same server (one interpreter
// start per worker, not per check). The control: without the hooks each forked check starts its own
// server, a different process each time.
TEST(RemoteSubject, EachCheckStartsFromTheHandshakeStateOnItsWorkersServer) {
  harness::SubjectInfo info;
  auto conn = connect("tests/remote/stateful.py");
  const SubjectSet s = remote_subject(conn, "stateful", info);
  ASSERT_TRUE(conn->sessions());
  const Vec3<double> I(1, 2, 3), P(1, 0, 0), P2(0, 1, 0);
  auto task = [&] {
    // Two arguments: a repeated call would be answered from memory (call_memo.hpp).
    const double first = s.d->casimir(P), second = s.d->casimir(P2);
    return std::to_string(static_cast<long long>(first)) + " " + std::to_string(static_cast<long long>(second)) + " " +
           std::to_string(static_cast<long long>(s.d->hamiltonian_3_4(I, P)));
  };
  const auto r = run_as_checks(info, std::vector<std::function<std::string()>>(4, task), 1);
  // The handshake itself calls casimir (the server probes which scalar kinds each slot accepts), so
  // a check sees the count the handshake left, k, and calls k + 1 and k + 2: the same in every check.
  std::set<std::string> counts, servers;
  for (const auto& t : r) {
    ASSERT_EQ(t.status, harness::TaskResult::Status::Ok) << t.detail << t.output;
    std::istringstream in(t.payload);
    long long first = 0, second = 0;
    in >> first >> second;
    EXPECT_EQ(second, first + 1) << t.payload;
    counts.insert(std::to_string(first));
    servers.insert(t.payload.substr(t.payload.rfind(' ') + 1));
  }
  EXPECT_EQ(counts.size(), 1u) << "each check starts from the handshake's state, not the previous check's";
  EXPECT_EQ(servers.size(), 1u) << "one server for the worker's four checks";
  harness::SubjectInfo no_hooks = info;
  no_hooks.prepare_worker = nullptr;
  no_hooks.worker_done = nullptr;
  const auto own = run_as_checks(no_hooks, std::vector<std::function<std::string()>>(2, task), 1);
  ASSERT_EQ(own.size(), 2u);
  EXPECT_NE(own[0].payload.substr(own[0].payload.rfind(' ')), own[1].payload.substr(own[1].payload.rfind(' ')))
      << "without sessions, a server per check";
}

// A crash of the implementation inside a check fails that check with how the process died (the
// call's error names it); the next check of the same worker runs normally on a server started afresh.
TEST(RemoteSubject, ACrashInACheckFailsThatCheckAloneAndSaysHowItDied) {
  harness::SubjectInfo info;
  const SubjectSet s = remote_subject(connect("tests/remote/stateful.py"), "stateful", info);
  const Vec3<double> P(1, 0, 0);
  auto vee_with = [&](double marker) {
    return [&s, marker] {
      Mat3<double> m = Mat3<double>::Zero();
      m(0, 1) = marker;
      return call_text([&] { return s.d->vee(m)(0); });
    };
  };
  auto counter = [&] { return call_text([&] { return s.d->casimir(P); }); };
  const auto r = run_as_checks(info, {vee_with(1), counter, vee_with(2), counter, vee_with(0)}, 1);
  ASSERT_EQ(r.size(), 5u);
  EXPECT_NE(r[0].payload.find("killed by signal SIGSEGV"), std::string::npos) << r[0].payload;
  EXPECT_NE(r[0].payload.find("vee"), std::string::npos) << "names the call: " << r[0].payload;
  EXPECT_EQ(r[1].payload, "1");
  EXPECT_NE(r[2].payload.find("exited with status 3"), std::string::npos) << r[2].payload;
  EXPECT_EQ(r[3].payload, "1");
  EXPECT_EQ(r[4].payload, "0");
}

// A call repeated with the same arguments is answered from memory, without a round trip
// (the server's counter does not move), and one repeat in CallMemo::kRecheckEvery is asked again:
// a slot that answers differently (here a counter, as a persistent variable would) is an error
// naming the slot, the arguments and both answers. The control: a slot that is a function of its
// arguments is asked again at the same cadence and passes.
TEST(RemoteSubject, ARepeatedCallIsAnsweredFromMemoryAndAnAnswerThatChangesIsNamed) {
  harness::SubjectInfo info;
  const SubjectSet s = remote_subject(connect("tests/remote/stateful.py"), "stateful", info);
  const Vec3<double> P(1, 0, 0), P2(0, 0, 1);
  const double first = s.d->casimir(P);
  for (long i = 1; i < CallMemo::kRecheckEvery; ++i) ASSERT_EQ(s.d->casimir(P), first) << "repeat " << i;
  EXPECT_EQ(s.d->casimir(P2), first + 1) << "the repeats made no round trip";
  try {
    s.d->casimir(P);
    ADD_FAILURE() << "the recheck did not notice the changed answer";
  } catch (const RemoteCallError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("function 'casimir' (double) answered the same arguments twice, differently"), std::string::npos)
        << m;
    EXPECT_NE(m.find("persistent or global variable"), std::string::npos) << m;
    EXPECT_NE(m.find("the first time: \"" + std::to_string(static_cast<long long>(first))), std::string::npos) << m;
  }
  const SubjectSet c = remote_subject(python("correct.py"), "correct", info);
  const Vec3<double> I(2, 1, 0.5);
  const double h = c.d->hamiltonian_3_4(I, P);
  for (long i = 0; i < 2 * CallMemo::kRecheckEvery; ++i) ASSERT_EQ(c.d->hamiltonian_3_4(I, P), h);
}

TEST(CallMemo, RemembersAndAsksAgainOnceInEveryCadence) {
  CallMemo m;
  bool recheck = true;
  EXPECT_EQ(m.find("a", &recheck), nullptr);
  m.remember("a", json("1"));
  int asked = 0;
  for (long i = 0; i < 3 * CallMemo::kRecheckEvery; ++i) {
    const json* r = m.find("a", &recheck);
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(*r, json("1"));
    asked += recheck;
  }
  EXPECT_EQ(asked, 3);
  EXPECT_EQ(CallMemo::compare(json("1"), json("1")), "");
  EXPECT_NE(CallMemo::compare(json("1"), json("2")).find("the second time: \"2\""), std::string::npos);
}

// 200 kB printed to stdout and stderr during one call: the call answers (the harness reads what
// the implementation prints while it waits), and the printing is not taken for a reply.
TEST(RemoteSubject, PrintingALotNeitherBlocksNorBreaksTheProtocol) {
  harness::SubjectInfo info;
  const SubjectSet s = remote_subject(connect("tests/remote/stateful.py"), "stateful", info);
  const Vec3<double> v(1, 2, 3);
  EXPECT_EQ(s.d->hat(v)(0, 1), -3.0);
  const auto r = run_as_checks(info, {[&] { return call_text([&] { return s.d->hat(v)(2, 1); }); }}, 1);
  EXPECT_EQ(r.at(0).payload, "1");
}

// An implementation that computes for a long time when it is loaded fails its handshake within the
// deadline, with a message that says what to look for; the control: loaded promptly, it answers.
TEST(RemoteSubject, AnImplementationThatHangsWhenLoadedFailsItsHandshakeInTime) {
  ::setenv("GEOMECH_TEST_SLOW_IMPORT", "30", 1);
  auto conn = connect("tests/remote/stateful.py");
  conn->handshake_seconds = 2;
  try {
    conn->hello();
    ADD_FAILURE() << "a handshake arrived";
  } catch (const RemoteError& e) {
    EXPECT_NE(std::string(e.what()).find("did not answer its handshake within 2 s"), std::string::npos) << e.what();
  }
  ::unsetenv("GEOMECH_TEST_SLOW_IMPORT");  // (without the deadline the handshake arrives after 30 s: a failure above)
  auto prompt = connect("tests/remote/stateful.py");
  prompt->handshake_seconds = 20;
  EXPECT_NO_THROW(prompt->hello());
}

// The handshake's limit is judged as a check's (harness/isolation/work_limit.hpp): its CPU time,
// and the machine's fault only when the kernel's accounting says the machine starved it. A
// handshake that needs 1.5 s of CPU, under a limit of 2 s: on a core crowded by eight processes
// outside it, it gets a ninth of the core and is still queued at the busy limit (6 s here), the
// machine's (RemoteMachineFault; before: "did not answer its handshake within 60 s", a NOT CHECKED
// the next run kept); alone, it answers. The sleeping handshake above stays the code's.
TEST(RemoteSubject, AStarvedHandshakeIsTheMachinesNotTheCodes) {
  if (!harness::tree_times(::getpid()).queued_known) GTEST_SKIP() << "this kernel keeps no schedstat";
  ::setenv("GEOMECH_TEST_HEAVY_IMPORT", "1.5", 1);
  auto limited = [](std::shared_ptr<Connection> c) {
    c->handshake_seconds = 2;
    c->reply_limit = harness::WorkLimit{2, 1, 1, 2};  // the wall guard at 3 s, the busy limit at 6 s
    return c;
  };
  {
    harness::harness_testing::CrowdedCore crowded(8);
    auto conn = limited(connect("tests/remote/stateful.py"));
    try {
      conn->hello();
      ADD_FAILURE() << "a starved handshake arrived: the core was not crowded, the test shows nothing";
    } catch (const RemoteMachineFault& e) {
      EXPECT_NE(std::string(e.what()).find("the machine starved it"), std::string::npos) << e.what();
    } catch (const RemoteError& e) {
      ADD_FAILURE() << "a starved handshake was called the code's: " << e.what();
    }
  }
  // Alone, it answers. On a machine busy with other work the kernel's accounting may starve this
  // one too, rightly the machine's: it is asked again, as the fault's own fix says, up to three
  // times; any other error, or a fourth starved handshake, fails the test.
  std::string starved;
  bool answered = false;
  for (int attempt = 0; attempt < 4 && !answered; ++attempt) {
    auto alone = limited(connect("tests/remote/stateful.py"));
    try {
      alone->hello();
      answered = true;
    } catch (const RemoteMachineFault& e) {
      starved = e.what();
    }
  }
  EXPECT_TRUE(answered) << "alone, the handshake was starved four times: " << starved;
  ::unsetenv("GEOMECH_TEST_HEAVY_IMPORT");
}

// The two Octave servers: the script in octave-cli (student/octave/geomech_server.m) and, where
// liboctave-dev was installed at build time, geomech-octave-server with the interpreter linked in,
// which `geomech check mine.m` then uses. Each test that talks to Octave runs against both.
struct OctaveServer {
  std::string name;
  std::vector<std::string> command;
};

std::vector<OctaveServer> octave_servers(const std::string& file) {
  const std::string path = std::string(GM_SOURCE_DIR) + "/" + file;
  std::string language, why;
  std::vector<OctaveServer> out;
  ::setenv("GEOMECH_OCTAVE_SERVER", "script", 1);
  out.push_back({"the script server", server_command(path, &language, &why)});
  ::unsetenv("GEOMECH_OCTAVE_SERVER");
  if (octave_server_program().empty()) return out;  // built without liboctave-dev
  const auto deflt = server_command(path, &language, &why);
  EXPECT_NE(deflt.front().find("geomech-octave-server"), std::string::npos)
      << "geomech-octave-server was built but is not what `geomech check " << file << "` runs";
  out.push_back({"geomech-octave-server", deflt});
  return out;
}

// The Octave servers through live pipes (the client sends an empty line after each request: Octave's
// fgetl waits for the byte after a line's end), against the Python implementation.
TEST(RemoteSubject, OctaveCorrectMatchesPython) {
  ASSERT_EQ(std::system("command -v octave-cli > /dev/null 2>&1"), 0)
      << "octave-cli is not installed: apt-get install -y octave (./geomech installs it; CI has it)";
  for (const auto& server : octave_servers("examples/students/correct.m")) {
    SCOPED_TRACE(server.name);
    harness::SubjectInfo oi, pi;
    auto oc = std::make_shared<Connection>(server.command, "octave");
    const SubjectSet o = remote_subject(oc, "correct_m", oi);
    const SubjectSet p = remote_subject(python("correct.py"), "correct_py", pi);
    ASSERT_TRUE(o.d);
    EXPECT_FALSE(o.mp);
    EXPECT_FALSE(o.q);
    const Vec3<double> I(2, 1, 0.5), P(0.25, -1.5, 3), Q(1, 2, 3);
    EXPECT_EQ(o.d->euler_3_8(I, P), p.d->euler_3_8(I, P));
    const auto a = o.d->clebsch_3_21(I, Q, P), b = p.d->clebsch_3_21(I, Q, P);
    EXPECT_EQ(a.first, b.first);
    EXPECT_EQ(a.second, b.second);
    ASSERT_EQ(o.d->integrators.size(), 1u);
    const RigidBodyState<double> x{P, Mat3<double>::Identity()};
    const auto y = o.d->integrators[0].rigid_body_step(I, x, 0.01);
    const auto z = p.d->integrators[0].rigid_body_step(I, x, 0.01);
    EXPECT_LT((y.Pi - z.Pi).norm(), 1e-14);
    EXPECT_LT((y.O - z.O).norm(), 1e-14);
  }
}

// A reply with its numbers as numbers: the script server writes "%.17g", geomech-octave-server the
// shortest text that reads back exactly; both read back to the same doubles.
json numbers_read(const json& j) {
  if (j.is_string()) {
    const std::string& t = j.get_ref<const std::string&>();
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    return end && *end == '\0' && !t.empty() ? json(v) : j;
  }
  json out = j;
  if (j.is_array() || j.is_object())
    for (auto& [k, v] : out.items()) v = numbers_read(v);
  return out;
}

// Both Octave servers answer alike: the same handshake, the same values, and the same error texts
// and tracebacks for every way a reply can go wrong (tests/remote/octave_faults.m).
TEST(RemoteSubject, OctaveServersAnswerAlike) {
  ASSERT_EQ(std::system("command -v octave-cli > /dev/null 2>&1"), 0)
      << "octave-cli is not installed: apt-get install -y octave (./geomech installs it; CI has it)";
  const json v3 = json::array({"0.25", "-1.5", "3"}), I = json::array({"2", "1", "0.5"});
  const json m3 = json::array(
      {json::array({"0", "-3", "-1.5"}), json::array({"3", "0", "-0.25"}), json::array({"1.5", "0.25", "0"})});
  struct Case {
    std::string file;
    Call call;
  };
  const std::vector<Case> cases = {
      {"tests/remote/octave_faults.m", {"hat", "double", json::array({v3}), ""}},
      {"tests/remote/octave_faults.m", {"vee", "double", json::array({m3}), ""}},
      {"tests/remote/octave_faults.m", {"pairing", "double", json::array({m3, m3}), ""}},
      {"tests/remote/octave_faults.m", {"euler_3_8", "double", json::array({I, v3}), ""}},
      {"tests/remote/octave_faults.m", {"lagrangian_2_5", "double", json::array({I, v3}), ""}},
      {"tests/remote/octave_faults.m", {"lie_hat", "double", json::array({"so3", v3}), ""}},
      {"tests/remote/octave_faults.m", {"lie_vee", "double", json::array({"so3", m3}), ""}},
      {"tests/remote/octave_faults.m", {"hat_n", "double", json::array({v3, 3}), ""}},
      {"tests/remote/octave_faults.m", {"vee_n", "double", json::array({m3}), ""}},
      {"tests/remote/octave_faults.m", {"ad_star", "double", json::array({"so3", v3, v3}), ""}},
      {"examples/students/correct.m", {"euler_3_8", "double", json::array({I, v3}), ""}},
      {"examples/students/correct.m",
       {"hat_n", "double", json::array({json::array({"1", "2", "3", "4", "5", "6"}), 4}), ""}},
      {"examples/students/correct.m", {"lie_hat", "double", json::array({"sl2", v3}), ""}},
      {"examples/students/correct.m", {"clebsch_3_21", "double", json::array({I, v3, I}), ""}},
      {"examples/students/correct.m",
       {"rigid_body_step", "double", json::array({I, json{{"Pi", v3}, {"O", m3}}, "0.125"}), "midpoint"}},
  };
  std::map<std::string, std::vector<json>> seen;  // file -> [handshake, replies...] of the first server
  for (const std::string file : {"tests/remote/octave_faults.m", "examples/students/correct.m"}) {
    for (const auto& server : octave_servers(file)) {
      SCOPED_TRACE(server.name + " on " + file);
      Connection conn(server.command, "octave");
      json hello = conn.hello();
      std::vector<json> got{json{{"slots", hello["slots"]},
                                 {"integrators", hello["integrators"]},
                                 {"description", hello["description"]},
                                 {"language", hello["language"]}}};
      for (const auto& c : cases) {
        if (c.file != file) continue;
        const auto r = conn.call_batch({c.call});
        ASSERT_EQ(r.size(), 1u);
        got.push_back(
            json{{"slot", c.call.slot}, {"ok", r[0].ok}, {"result", numbers_read(r[0].result)}, {"error", r[0].error}});
      }
      auto [it, first] = seen.emplace(file, got);
      if (first) continue;
      ASSERT_EQ(it->second.size(), got.size());
      for (std::size_t k = 0; k < got.size(); ++k) EXPECT_EQ(it->second[k].dump(1), got[k].dump(1));
    }
  }
  // What the faults say, in either server (the first one's replies).
  const auto& f = seen["tests/remote/octave_faults.m"];
  auto error_of = [&](const std::string& slot) {
    for (const auto& r : f)
      if (r.value("slot", "") == slot) return r.at("error").get<std::string>();
    return std::string("(no reply)");
  };
  EXPECT_NE(error_of("hat").find("a complex number where a real was expected"), std::string::npos) << error_of("hat");
  EXPECT_NE(error_of("vee").find("vee_helper: refused a 3x3 matrix"), std::string::npos) << error_of("vee");
  EXPECT_NE(error_of("vee").find("at vee_helper, line 15 ("), std::string::npos) << error_of("vee");
  EXPECT_NE(error_of("vee").find("octave_faults.m)"), std::string::npos) << error_of("vee");
  EXPECT_NE(error_of("pairing").find("expected a scalar, got a 3x3 array"), std::string::npos) << error_of("pairing");
  EXPECT_NE(error_of("lagrangian_2_5").find("expected numbers, got a value of class char"), std::string::npos)
      << error_of("lagrangian_2_5");
  EXPECT_NE(error_of("lie_hat").find("expected numbers, got a value of class cell"), std::string::npos)
      << error_of("lie_hat");
  EXPECT_NE(error_of("hat_n").find("expected a matrix, got an array of 3 dimensions"), std::string::npos)
      << error_of("hat_n");
  EXPECT_FALSE(error_of("euler_3_8").empty());
}

// A run of steps ("repeat", docs/PROTOCOL.md) gives exactly the states of the calls one by one, in
// every server that offers it: Python (double and 50 digits) and Octave.
TEST(RemoteSubject, ARunOfStepsIsTheStepsOneByOne) {
  harness::SubjectInfo pi;
  const SubjectSet p = remote_subject(python("correct.py"), "correct_py", pi);
  auto check = [](const auto& in, const auto& I, auto x, const auto& h) {
    ASSERT_TRUE(in.rigid_body_run) << in.name;
    const auto run = in.rigid_body_run(I, x, h, 5);
    ASSERT_EQ(run.size(), 5u);
    for (int k = 0; k < 5; ++k) {
      x = in.rigid_body_step(I, x, h);
      EXPECT_EQ(run[k].Pi, x.Pi) << in.name << " step " << k + 1;
      EXPECT_EQ(run[k].O, x.O) << in.name << " step " << k + 1;
    }
  };
  const Vec3<double> I(2, 1, 0.5), P(0.25, -1.5, 3);
  for (const auto& in : p.d->integrators) check(in, I, RigidBodyState<double>{P, Mat3<double>::Identity()}, 0.125);
  for (const auto& in : p.mp->integrators)
    check(in, I.cast<Real50>().eval(), RigidBodyState<Real50>{P.cast<Real50>(), Mat3<Real50>::Identity()},
          Real50(1) / 8);
  ASSERT_EQ(std::system("command -v octave-cli > /dev/null 2>&1"), 0)
      << "octave-cli is not installed: apt-get install -y octave (./geomech installs it; CI has it)";
  for (const auto& server : octave_servers("examples/students/correct.m")) {
    SCOPED_TRACE(server.name);
    harness::SubjectInfo oi;
    auto oc = std::make_shared<Connection>(server.command, "octave");
    const SubjectSet o = remote_subject(oc, "correct_m", oi);
    ASSERT_FALSE(o.d->integrators.empty());
    for (const auto& in : o.d->integrators) check(in, I, RigidBodyState<double>{P, Mat3<double>::Identity()}, 0.125);
  }
}

// A JavaScript implementation on Node (student/javascript/geomech_server.mjs), in double only: the
// same values as the Python one, a run of steps the steps one by one.
TEST(RemoteSubject, JavaScriptCorrectMatchesPython) {
  ASSERT_EQ(std::system("command -v node > /dev/null 2>&1"), 0)
      << "node is not installed: apt-get install -y nodejs (./geomech installs it; CI has it)";
  harness::SubjectInfo ji, pi;
  const SubjectSet j = remote_subject(connect("examples/students/correct.mjs"), "correct_mjs", ji);
  const SubjectSet p = remote_subject(python("correct.py"), "correct_py", pi);
  ASSERT_TRUE(j.d);
  EXPECT_FALSE(j.mp) << "JavaScript numbers are doubles";
  EXPECT_FALSE(j.q);
  EXPECT_NE(ji.scalar_unavailable["mp50"].find("JavaScript numbers are doubles"), std::string::npos);
  const Vec3<double> I(2, 1, 0.5), P(0.25, -1.5, 3), Q(1, 2, 3);
  EXPECT_EQ(j.d->euler_3_8(I, P), p.d->euler_3_8(I, P));
  EXPECT_EQ(j.d->hat(Q), p.d->hat(Q));
  const auto a = j.d->clebsch_3_21(I, Q, P), b = p.d->clebsch_3_21(I, Q, P);
  EXPECT_LT((a.first - b.first).norm(), 1e-14 * b.first.norm());
  EXPECT_LT((a.second - b.second).norm(), 1e-14 * b.second.norm());
  ASSERT_FALSE(j.d->integrators.empty());
  const RigidBodyState<double> x{P, Mat3<double>::Identity()};
  const auto& in = j.d->integrators[0];
  ASSERT_TRUE(in.rigid_body_run);
  auto y = x;
  const auto run = in.rigid_body_run(I, x, 0.125, 5);
  ASSERT_EQ(run.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    y = in.rigid_body_step(I, y, 0.125);
    EXPECT_EQ(run[k].Pi, y.Pi) << "step " << k + 1;
    EXPECT_EQ(run[k].O, y.O) << "step " << k + 1;
  }
}

// Every way a JavaScript reply goes wrong (tests/remote/javascript_faults.mjs): a step's NaN and
// infinities cross as what they are (JSON.stringify would write null), a slot's NaN is refused with
// its place, a throw carries its name, message and the student's stack, a missing return is said,
// and a vector in a WebAssembly memory's Float64Array is a vector.
TEST(RemoteSubject, JavaScriptRepliesCarryWhatTheCodeComputed) {
  ASSERT_EQ(std::system("command -v node > /dev/null 2>&1"), 0)
      << "node is not installed: apt-get install -y nodejs (./geomech installs it; CI has it)";
  harness::SubjectInfo info;
  const SubjectSet s = remote_subject(connect("tests/remote/javascript_faults.mjs"), "faults", info);
  ASSERT_TRUE(s.d);
  const Vec3<double> I(2, 1, 0.5), P(0.25, -1.5, 3);
  EXPECT_EQ(s.d->euler_3_8(I, P), Vec3<double>(P.cross(P.cwiseQuotient(I))));
  ASSERT_EQ(s.d->integrators.size(), 1u);
  const auto y = s.d->integrators[0].rigid_body_step(I, RigidBodyState<double>{P, Mat3<double>::Identity()}, 0.01);
  EXPECT_EQ(y.Pi[0], std::numeric_limits<double>::infinity());
  EXPECT_EQ(y.Pi[1], std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(y.Pi[2]));
  auto error_of = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string hat = error_of([&] { s.d->hat(P); });
  EXPECT_NE(hat.find("RangeError: hat is not written yet"), std::string::npos) << hat;
  EXPECT_NE(hat.find("javascript_faults.mjs:8"), std::string::npos) << "the student's own line: " << hat;
  EXPECT_EQ(hat.find("geomech_server.mjs"), std::string::npos) << "the server's frames are not the student's: " << hat;
  const std::string vee = error_of([&] { s.d->vee(Mat3<double>::Identity()); });
  EXPECT_NE(vee.find("not finite"), std::string::npos) << vee;
  EXPECT_NE(vee.find("[2]"), std::string::npos) << vee;
  const std::string casimir = error_of([&] { s.d->casimir(P); });
  EXPECT_NE(casimir.find("undefined (a function that returns nothing?)"), std::string::npos) << casimir;
}

TEST(RemoteSubject, RoundTripCost) {
  auto conn = python("correct.py");
  conn->hello();
  const Call c{"euler_3_8", "double", json::array({json::array({"2", "1", "0.5"}), json::array({"0.25", "-1.5", "3"})}),
               ""};
  const int n = 200;
  auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) conn->call_batch({c});  // call() would answer the repeats from memory
  const double one = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / n;
  t0 = std::chrono::steady_clock::now();
  conn->call_batch(std::vector<Call>(n, c));
  const double batched = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / n;
  std::printf("python euler_3_8 (double): %.1f us per call one at a time, %.1f us per call batched\n", one * 1e6,
              batched * 1e6);
  EXPECT_LT(batched, one * 2);
}

}  // namespace
}  // namespace gm::protocol
