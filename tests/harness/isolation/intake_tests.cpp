// Reading a stranger's folder (harness/isolation/submission_intake.hpp), the inert and bounded
// texts (harness/isolation/inert_text.hpp), the gradebook's cells and the children's input and output
// (harness/isolation/process.hpp). Each refusal test has its control: the naive read the harness used to do
// (std::ifstream, following everything) shows the attack is real on the same folder.
#include "harness/class/gradebook.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/isolation/process.hpp"
#include "harness/isolation/submission_intake.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <sstream>
#include <thread>
#include <vector>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

namespace gm::harness {
namespace {

namespace fs = std::filesystem;

struct Scratch {
  fs::path dir;
  Scratch() {
    std::string t = (fs::temp_directory_path() / "geomech-intake-XXXXXX").string();
    EXPECT_NE(::mkdtemp(t.data()), nullptr);
    dir = t;
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  void write(const std::string& rel, const std::string& text) const {
    fs::create_directories((dir / rel).parent_path());
    std::ofstream(dir / rel, std::ios::binary) << text;
  }
};

std::string naive_read(const fs::path& p) {  // what the harness used to do
  std::ifstream f(p, std::ios::binary);
  std::ostringstream os;
  os << f.rdbuf();
  return os.str();
}

constexpr const char* kSecret = "moodle_token: not-for-students";

TEST(Intake, ASymbolicLinkIsNeverFollowedAndSaysSo) {
  Scratch s;
  s.write("secret/token", kSecret);
  fs::create_directory(s.dir / "class");
  fs::create_symlink(s.dir / "secret" / "token", s.dir / "class" / "leak.py");
  ASSERT_EQ(naive_read(s.dir / "class" / "leak.py"), kSecret);  // control: the link reaches the secret
  const StrangerFolder folder((s.dir / "class").string());
  try {
    (void)folder.read("leak.py", 1 << 20);
    FAIL() << "a link was read";
  } catch (const RefusedEntry& e) {
    EXPECT_EQ(e.path(), "leak.py");
    EXPECT_NE(e.why().find("a symbolic link"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("not-for-students"), std::string::npos);
  }
  EXPECT_THROW((void)read_stranger_file((s.dir / "class" / "leak.py").string()), RefusedEntry);
  EXPECT_EQ(folder.look("leak.py").kind, EntryKind::Link);
}

TEST(Intake, ALinkInsideAPathIsNotFollowedEither) {
  Scratch s;
  s.write("secret/token", kSecret);
  fs::create_directory(s.dir / "class");
  fs::create_directory_symlink(s.dir / "secret", s.dir / "class" / "bob");  // a folder that is a link
  ASSERT_EQ(naive_read(s.dir / "class" / "bob" / "token"), kSecret);
  const StrangerFolder folder((s.dir / "class").string());
  try {
    (void)folder.read("bob/token", 1 << 20);
    FAIL() << "a path through a link was read";
  } catch (const RefusedEntry& e) {
    EXPECT_EQ(e.path(), "bob");
    EXPECT_NE(e.why().find("a symbolic link"), std::string::npos);
  }
  EXPECT_THROW((void)folder.list("bob"), RefusedEntry);
  EXPECT_THROW((void)folder.read("../secret/token", 1 << 20), RefusedEntry);
}

TEST(Intake, AFifoIsRefusedWithoutBeingOpened) {
  Scratch s;
  ASSERT_EQ(::mkfifo((s.dir / "fifo.py").c_str(), 0644), 0);
  // Control: a naive open of a FIFO waits for a writer (the class run hung there). Asked in a
  // thread with a deadline; a writer is then opened to release it.
  auto naive = std::async(std::launch::async, [&] { return naive_read(s.dir / "fifo.py"); });
  EXPECT_EQ(naive.wait_for(std::chrono::milliseconds(300)), std::future_status::timeout);
  { std::ofstream release(s.dir / "fifo.py"); }
  naive.get();
  const StrangerFolder folder(s.dir.string());
  try {
    (void)folder.read("fifo.py", 1 << 20);
    FAIL() << "a FIFO was read";
  } catch (const RefusedEntry& e) {
    EXPECT_NE(e.why().find("a FIFO"), std::string::npos);  // told by its type: never opened, so never waited on
  }
}

TEST(Intake, SocketsDevicesAndHardLinksAreRefused) {
  Scratch s;
  s.write("a.py", "x = 1\n");
  // A socket.
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string sock = (s.dir / "sock").string();
  ASSERT_LT(sock.size(), sizeof addr.sun_path);
  std::copy(sock.begin(), sock.end(), addr.sun_path);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  ::close(fd);
  // A second name of a file.
  fs::create_hard_link(s.dir / "a.py", s.dir / "b.py");
  const StrangerFolder folder(s.dir.string());
  EXPECT_EQ(folder.look("sock").kind, EntryKind::Socket);
  EXPECT_THROW((void)folder.read("sock", 1 << 20), RefusedEntry);
  try {
    (void)folder.read("b.py", 1 << 20);
    FAIL() << "a hard link was read";
  } catch (const RefusedEntry& e) {
    EXPECT_NE(e.why().find("2 names"), std::string::npos) << e.what();
  }
  // A device (the system's /dev/zero would read without end).
  const StrangerFolder dev("/dev");
  EXPECT_EQ(dev.look("zero").kind, EntryKind::Device);
  EXPECT_THROW((void)dev.read("zero", 1 << 20), RefusedEntry);
}

TEST(Intake, ARegularFileIsReadWithinItsCap) {
  Scratch s;
  s.write("ok.py", "def hat(v):\n    pass\n");
  s.write("big.py", std::string(5000, 'x'));
  const StrangerFolder folder(s.dir.string());
  EXPECT_EQ(folder.read("ok.py", 1 << 20), "def hat(v):\n    pass\n");
  EXPECT_EQ(read_stranger_file((s.dir / "ok.py").string()), "def hat(v):\n    pass\n");
  try {
    (void)folder.read("big.py", 4096);
    FAIL() << "a file beyond the cap was read";
  } catch (const RefusedEntry& e) {
    EXPECT_NE(e.why().find("larger than"), std::string::npos);
  }
}

TEST(Intake, ASubmissionIsReadWhole_WithinItsLimits_AndRefusedByItsFirstSpecialEntry) {
  Scratch s;
  s.write("bob/rigid.cpp", "// bob\n");
  s.write("bob/so3.hpp", "// so3\n");
  s.write("bob/.git/config", "[core]\n");  // hidden: left out, never opened
  s.write("bob/src/more.hpp", "// more\n");
  const StrangerFolder folder(s.dir.string());
  const SubmissionTree t = read_submission(folder, "bob");
  ASSERT_EQ(t.files.size(), 3u);
  EXPECT_EQ(t.files[0].first, "rigid.cpp");
  EXPECT_EQ(t.files[1].first, "so3.hpp");
  EXPECT_EQ(t.files[2].first, "src/more.hpp");
  EXPECT_EQ(read_submission(folder, "bob/rigid.cpp").files.at(0).first, "rigid.cpp");

  IntakeLimits few;
  few.entries = 2;
  EXPECT_THROW((void)read_submission(folder, "bob", few), RefusedEntry);
  IntakeLimits shallow;
  shallow.depth = 0;
  EXPECT_THROW((void)read_submission(folder, "bob", shallow), RefusedEntry);
  IntakeLimits small;
  small.total_bytes = 10;
  EXPECT_THROW((void)read_submission(folder, "bob", small), RefusedEntry);

  fs::create_symlink("/etc/shadow", s.dir / "bob" / "src" / "evil.hpp");
  try {
    (void)read_submission(folder, "bob");
    FAIL() << "a submission holding a link was read";
  } catch (const RefusedEntry& e) {
    EXPECT_EQ(e.path(), "bob/src/evil.hpp");
  }
}

TEST(Intake, ASnapshotRewritesOnlyWhatChangedAndDropsWhatIsGone) {
  Scratch s;
  SubmissionTree t;
  t.files = {{"a.cpp", "int a;\n"}, {"inc/b.hpp", "int b;\n"}};
  write_tree(t, s.dir / "snap");
  const auto before = fs::last_write_time(s.dir / "snap" / "a.cpp");
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  t.files = {{"a.cpp", "int a;\n"}, {"c.hpp", "int c;\n"}};
  write_tree(t, s.dir / "snap");
  EXPECT_EQ(fs::last_write_time(s.dir / "snap" / "a.cpp"), before);  // unchanged: not recompiled
  EXPECT_FALSE(fs::exists(s.dir / "snap" / "inc" / "b.hpp"));
  EXPECT_FALSE(fs::exists(s.dir / "snap" / "inc"));
  EXPECT_EQ(naive_read(s.dir / "snap" / "c.hpp"), "int c;\n");
}

TEST(Intake, ImplementationNamesThatCannotNameAReportAreRefused) {
  for (const std::string bad : std::vector<std::string>{"", ".", "..", "a/b", "a\\b", "new\nline", "esc\x1b[31m", "-rf",
                                                        "\xff\xfe", std::string(101, 'a')})
    EXPECT_FALSE(bad_implementation_name(bad).empty()) << "accepted: " << bad;
  for (const std::string good : {"alice", "=1+1", "O'Brien", "bob.v2", "Jörg", "a b"})
    EXPECT_TRUE(bad_implementation_name(good).empty()) << good << ": " << bad_implementation_name(good);
}

// ---- texts from a submission ------------------------------------------------------------------

TEST(InertText, AMessageOfAnySizeIsShownBoundedWithTheCutSaid) {
  const std::string flood = "BEGIN" + std::string(20 << 20, 'x') + "END";
  const std::string b = bounded_text(flood);
  EXPECT_LE(b.size(), kMessageCap + 200);
  EXPECT_EQ(b.rfind("BEGIN", 0), 0u);
  EXPECT_EQ(b.substr(b.size() - 3), "END");
  EXPECT_NE(b.find("bytes cut"), std::string::npos);
  EXPECT_EQ(bounded_text("short"), "short");
  // Never half a character: a cut inside a run of two-byte characters keeps UTF-8 valid.
  const std::string umlauts = [] {
    std::string u;
    for (int i = 0; i < 10000; ++i) u += "\xc3\xa4";
    return u;
  }();
  EXPECT_EQ(inert_text(bounded_text(umlauts, 1001)).find("\xEF\xBF\xBD"), std::string::npos);
}

TEST(InertText, MarkdownFromASubmissionCannotOpenHtmlLinksCellsOrFences) {
  const std::string forge = "x | **FORGED PASS** |\n<img src=x onerror=alert(1)> [click](http://evil) `code`\x1b[31m";
  const std::string cell = md_inline(forge);
  EXPECT_EQ(cell.find('<' + std::string("img")), std::string::npos);
  EXPECT_EQ(cell.find("[click](http"), std::string::npos);  // "[click\\](http": no link
  EXPECT_NE(cell.find("[click\\](http"), std::string::npos);
  EXPECT_EQ(cell.find('\n'), std::string::npos);
  EXPECT_EQ(cell.find('\x1b'), std::string::npos);
  for (std::size_t i = cell.find('|'); i != std::string::npos; i = cell.find('|', i + 1)) EXPECT_EQ(cell[i - 1], '\\');
  // A fence longer than any run of backticks inside: the text cannot close it.
  const std::string block = md_fenced("```\n| FORGED |\n``````\n");
  EXPECT_EQ(block.rfind("```````\n", 0), 0u);
  EXPECT_EQ(block.substr(block.size() - 8), "```````\n");
  EXPECT_EQ(md_link_target("a b(1)/report.md"), "a%20b%281%29/report.md");
}

TEST(Gradebook, ACellThatASpreadsheetWouldComputeIsMadeText) {
  for (const std::string f : {"=1+1", "+1+1", "-1+1", "@SUM(A1)", "\tx", "\rx", "=HYPERLINK(\"http://evil\")"})
    EXPECT_EQ(spreadsheet_safe(f), "'" + f) << f;
  for (const std::string keep : {"92.31", "-1.5", "alice", "", "100.00"}) EXPECT_EQ(spreadsheet_safe(keep), keep);
}

// ---- what a child reads and writes ------------------------------------------------------------

TEST(Process, AChildReadsNothingOfOurInputAndItsOutputIsBounded) {
  // Our input holds what a lecturer typed (a pipe standing for the terminal).
  int p[2];
  ASSERT_EQ(::pipe(p), 0);
  ASSERT_EQ(::write(p[1], "TYPED\n", 6), 6);
  ::close(p[1]);
  const int saved = ::dup(0);
  ::dup2(p[0], 0);
  ::close(p[0]);
  const ProcessResult r = run_process(ProcessSpec{{"/bin/cat"}, {}, false}, 10);
  char buf[16] = {};
  const ssize_t n = ::read(0, buf, sizeof buf);  // control: the input really held it, still unread
  ::dup2(saved, 0);
  ::close(saved);
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0), "TYPED\n");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output, "");
  const ProcessResult big =
      run_process(ProcessSpec{{"/bin/sh", "-c", "head -c 8000000 /dev/zero | tr '\\0' x"}, {}, false}, 60);
  EXPECT_LT(big.output.size(), 2u << 20);
  EXPECT_NE(big.output.find("bytes of output cut"), std::string::npos);
}

// The compile in double is decisive: when it fails, the other scalars' compiles are stopped (what
// they started with them: a driver's compiler proper) and those not started never start.
TEST(Process, ADecisiveFailureStopsTheOthersAndWhatTheyStarted) {
  char marker[] = "/tmp/geomech-decisive-XXXXXX";
  const int fd = ::mkstemp(marker);
  ASSERT_GE(fd, 0);
  ::close(fd);
  ::unlink(marker);
  ProcessSpec fails{{"/bin/sh", "-c", "sleep 0.2; exit 1"}, {}, false};
  fails.decisive = true;
  // A driver whose child (the compiler proper, here a sleep) would write the marker after 3 s.
  const ProcessSpec driver{{"/bin/sh", "-c", std::string("(sleep 3; touch ") + marker + ") & wait"}, {}, false};
  const ProcessSpec queued{{"/bin/sh", "-c", std::string("touch ") + marker}, {}, false};
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run_processes({fails, driver, queued}, 2, 60);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r[0].exit_code, 1);
  EXPECT_FALSE(r[0].cancelled);
  EXPECT_TRUE(r[1].cancelled && r[2].cancelled);
  EXPECT_LT(took, 2.5) << "the running one was waited for";
  std::this_thread::sleep_for(std::chrono::milliseconds(3500));
  EXPECT_FALSE(std::filesystem::exists(marker)) << "the driver's child outlived it, or the queued one started";
  // The control: without a decisive failure every process runs to its end.
  const auto all = run_processes({ProcessSpec{{"/bin/sh", "-c", "exit 1"}, {}, false}, queued}, 2, 60);
  EXPECT_FALSE(all[1].cancelled);
  EXPECT_TRUE(std::filesystem::exists(marker));
  std::filesystem::remove(marker);
}

}  // namespace
}  // namespace gm::harness
