#include "harness/submissions/check_submission.hpp"

#include "harness/isolation/inert_text.hpp"
#include "harness/isolation/isolate.hpp"
#include "harness/isolation/private_copy.hpp"
#include "harness/isolation/process.hpp"
#include "harness/isolation/sandbox.hpp"
#include "harness/isolation/sandboxed_interpreter.hpp"
#include "harness/isolation/submission_intake.hpp"
#include "harness/languages/language.hpp"
#include "harness/languages/notebook.hpp"
#include "harness/languages/starts_in_sandbox.hpp"
#include "harness/program/library_flags.hpp"
#include "harness/program/student_registry.hpp"
#include "harness/remote/remote_subject.hpp"
#include "harness/reports/report.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

namespace gm::harness {
namespace {

// The build options a replay of a C++ file's check needs to build the same program: its libraries
// (--pkg, --cxxflags, --ldflags), " --pkg ode" and the like; "" when none.
std::string replay_build_options(const BuildOptions& bo) {
  std::string out;
  for (const auto& a : library_args(bo.libraries)) out += " " + a;
  return out;
}

// `geomech check FILE.cpp`: compile only the student's file against the prebuilt library, then
// run its check program (which isolates every property in a child process).
int run_student_check(const SubmissionRequest& r, SubmissionOutcome& out) {
  const std::string& file = r.file;
  CheckCliOptions o = r.check;
  const BuildOptions& bo = r.build;
  const auto t0 = std::chrono::steady_clock::now();
  const Toolchain tc = load_toolchain(default_toolchain_path());
  const std::string reproduce = r.reproduce_prefix.empty()
                                    ? r.front_door + " check " + shell_quote(file) + replay_build_options(bo)
                                    : r.reproduce_prefix;
  const bool narrowed_run = o.narrowed() || o.definitions_only;
  // The first look: from an empty cache the pieces of the file take 11-20 s of compiles. The
  // double slots alone compile first, in two pieces on two cores, and their program checks every
  // slot's own definition in double, its failures printed as they come, while the integrators and
  // the 50-digit and exact instantiations compile; the full check follows. When the double program
  // is up to date there is nothing to wait for, and no first look. A file that does not compile is
  // said so by the first look's build, not compiled again.
  std::thread first_look;
  std::optional<BuildResult> not_compiled;
  std::string one_precision_program;  // the first look's program, which can say whether every step states one
  if (r.first_look && !narrowed_run && bo.mp50 && bo.exact) {
    BuildOptions quick = bo;
    quick.mp50 = quick.exact = quick.integrators = false;
    quick.fast_link = true;
    quick.program_name = "check-double";
    BuildResult q = build_student(file, tc, quick);
    if (q.ok) one_precision_program = q.program;
    if (q.ok && !q.cached) {
      std::cerr << "geomech: compiled the double slots in " << std::fixed << std::setprecision(1) << q.seconds
                << " s: a first look at every slot in double while the rest compiles\n";
      std::vector<std::string> argv{
          q.program,    "--definitions",      "--jobs", "1", "--name", q.name, "--source", file, "--build-notes",
          q.notes_file, "--reproduce-prefix", reproduce};
      first_look = std::thread([argv] { run_process(ProcessSpec{argv, {}, true}); });
    }
    if (q.does_not_compile) not_compiled = std::move(q);
  }
  // A file that fills no slot and whose every integrator states its precision (an engine's wrapper,
  // `precision = "float"` or "double") runs its steps in double only: its 50-digit and exact compiles,
  // each through the engine's headers, would register nothing to check. The first look's program
  // says so from its own registrations.
  BuildOptions full = bo;
  if (!one_precision_program.empty()) {
    const ProcessResult described =
        run_process(ProcessSpec{{one_precision_program, "--states-its-precision"}, {}, true});
    if (described.started && !described.signal && described.exit_code == 0) {
      full.mp50 = full.exact = false;
      full.scalars_left_out_because =
          "the file fills no slot and every integrator states its precision, so its steps run in double only";
      std::cerr << "geomech: every integrator states its precision and the file fills no slot: compiled for "
                   "double only\n";
    }
  }
  const BuildResult b = not_compiled ? std::move(*not_compiled) : build_student(file, tc, full);
  if (first_look.joinable()) first_look.join();
  for (const auto& line : b.log) std::cerr << "geomech: " << line << "\n";
  out.build_seconds = b.seconds;
  if (!b.ok) {
    std::cerr << "geomech check: " << file << ": " << b.message << "\n";
    if (!b.machine_fault.empty()) {
      out.machine_fault = b.machine_fault;
      return kExitMachine;
    }
    out.built = false;
    out.build_message = b.message;
    return 2;
  }
  std::cerr << "geomech: built " << b.name << (b.cached ? " (up to date)" : "") << " in " << std::fixed
            << std::setprecision(1) << b.seconds << " s\n";
  // A full check writes its report by default; a narrowed one (a replay, one property) only when asked,
  // so that replaying a failure never replaces the full report.
  if (o.report_dir.empty() && !o.narrowed()) o.report_dir = "geomech-reports/" + b.name;
  std::vector<std::string> argv{b.program};
  const auto args = to_args(o);
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(),
              {"--name", b.name, "--source", file, "--build-notes", b.notes_file, "--reproduce-prefix", reproduce});
  const ProcessResult pr = run_process(ProcessSpec{argv, {}, true});
  out.check_seconds = pr.seconds;
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cerr << "geomech: checked " << b.name << " in " << std::fixed << std::setprecision(1) << total << " s (build "
            << b.seconds << " s, check " << pr.seconds << " s)\n";
  if (!pr.started) {
    std::cerr << "geomech check: " << pr.output << "\n";
    return 2;
  }
  if (pr.signal) {
    std::cerr << "geomech check: the check program was " << describe_signal(pr.signal) << "\n";
    return 2;
  }
  return pr.exit_code;
}

// A notebook's code cells for its kernel's server: the notebook read as a stranger's file (within the
// intake's limits, never through a link) and as nbformat 4 (harness/languages/notebook.hpp), its
// cells file written in a private folder of ours, removed with this object. Throws NotebookError
// (what is wrong, naming the notebook by its file name) or RefusedEntry.
class NotebookCells {
 public:
  // `folder`: where the cells' imports are found ("" in the sandbox: nothing beside the notebook).
  NotebookCells(const std::string& file, const std::string& folder) {
    const std::string name = std::filesystem::path(file).filename().string();
    notebook_ = read_notebook(name, read_stranger_file(file));
    std::string pattern = (std::filesystem::temp_directory_path() / "geomech-notebook-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a folder in " + pattern);
    folder_ = pattern;
    cells_file_ = (std::filesystem::path(folder_) / (name + ".json")).string();
    write_file_atomically(cells_file_, cells_file_text(notebook_, name, folder));
  }
  ~NotebookCells() {
    std::error_code ec;
    std::filesystem::remove_all(folder_, ec);
  }
  NotebookCells(const NotebookCells&) = delete;
  NotebookCells& operator=(const NotebookCells&) = delete;
  const Notebook& notebook() const { return notebook_; }
  const Language& language() const { return *notebook_.language; }
  const std::string& cells_file() const { return cells_file_; }

 private:
  Notebook notebook_;
  std::string folder_, cells_file_;
};

// `geomech check mine.py` / `mine.m` / a folder of .m files: the implementation runs as a child
// process speaking docs/PROTOCOL.md; the check runs here, with the remote subject.
bool is_remote_file(const std::string& file) {
  const Language* l = language_of(file);
  return l && l->route == Route::Served;
}

// The check of an implementation that runs as its own process (`cmd`, speaking the protocol).
// `build_notes` is what compiling it found (C++ in untrusted mode), `how` the reproduce command's options.
// `notebook`: the notebook whose cells the server runs, when the implementation is one.
int run_protocol_check(const SubmissionRequest& r, const std::vector<std::string>& cmd, const std::string& language,
                       const nlohmann::json& build_notes, const std::string& how,
                       std::chrono::steady_clock::time_point t0, SubmissionOutcome& out,
                       const std::string& name_in = "", const Notebook* notebook = nullptr) {
  const std::string& file = r.file;
  CheckCliOptions o = r.check;
  auto conn = std::make_shared<protocol::Connection>(cmd, language);
  SubjectInfo info;
  info.source = file;
  info.reproduce_prefix =
      r.reproduce_prefix.empty() ? r.front_door + " check " + shell_quote(file) + how : r.reproduce_prefix;
  const std::string name = !name_in.empty() ? name_in
                           : std::filesystem::path(file).lexically_normal().stem().string().empty()
                               ? std::filesystem::path(file).lexically_normal().parent_path().filename().string()
                               : std::filesystem::path(file).lexically_normal().stem().string();
  student::apply_build_notes(info, build_notes);  // what the compiler found
  if (notebook) {
    info.language = notebook->language;
    info.cells = notebook->cells;
    info.notebook = set_aside_in_words(*notebook, file);
  }
  SubjectSet s;
  try {
    s = protocol::remote_subject(conn, name, info);
  } catch (const protocol::RemoteMachineFault& e) {  // the sandbox, or a starved handshake: the machine's
    std::cerr << "geomech check: " << file << ": " << inert_text(bounded_text(e.what())) << "\n";
    out.machine_fault = inert_text(bounded_text(e.what()));
    return kExitMachine;
  } catch (const std::exception& e) {
    // What the implementation said when it could not start is a stranger's text.
    std::cerr << "geomech check: " << file << ": " << inert_text(bounded_text(e.what())) << "\n";
    if (notebook)  // a cell that failed when run, named by the server
      std::cerr << "(a cell that only shows something, a plot, can carry the tag skip-execution: the suite, as "
                   "Jupyter's nbclient, does not run it)\n";
    return 2;
  }
  std::cerr << "geomech: " << language << " implementation " << file << " started and described itself in "
            << std::fixed << std::setprecision(2)
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
  if (o.report_dir.empty() && !o.narrowed()) o.report_dir = "geomech-reports/" + name;
  const auto check_start = std::chrono::steady_clock::now();
  const int status = run_check_cli(s, info, o);
  out.check_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - check_start).count();
  std::cerr << "geomech: checked " << name << " in " << std::fixed << std::setprecision(1)
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
  return status;
}

int run_remote_check(const SubmissionRequest& r, SubmissionOutcome& out) {
  const std::string& file = r.file;
  const auto t0 = std::chrono::steady_clock::now();
  std::string language, why;
  const auto cmd = server_command(file, &language, &why);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    std::cerr << "geomech check: " << file << ": no such file\n";
    return 2;
  }
  return run_protocol_check(r, cmd, language, nlohmann::json(), "", t0, out);
}

// `geomech check week3.ipynb`: its code cells, in order, served by the row its kernel names.
int run_notebook_check(const SubmissionRequest& r, SubmissionOutcome& out) {
  const auto t0 = std::chrono::steady_clock::now();
  std::error_code ec;
  if (!std::filesystem::exists(r.file, ec)) {
    std::cerr << "geomech check: " << r.file << ": no such file\n";
    return 2;
  }
  std::optional<NotebookCells> nb;
  try {
    const std::filesystem::path folder = std::filesystem::absolute(r.file, ec).parent_path();
    nb.emplace(r.file, folder.string());
  } catch (const RefusedEntry& e) {
    std::cerr << "geomech check: " << inert_text(e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {  // NotebookError: what is wrong in it
    std::cerr << "geomech check: " << e.what() << "\n";
    return 2;
  }
  return run_protocol_check(r, nb->language().server(nb->cells_file()), nb->language().id, nlohmann::json(), "", t0,
                            out, "", &nb->notebook());
}

// Untrusted mode: the implementation runs as its own process in the sandbox, behind the
// protocol; a C++ file is compiled (sandboxed too) into a protocol server that links the student's
// code and nothing of the judge. Verdicts are computed here alone.
// The packages a served file names (`// geomech: npm NAME`), each found under a folder the grader
// trusts (GEOMECH_LIBRARY_ROOTS: ROOT/node_modules/NAME, or ROOT/NAME when ROOT is itself such a
// folder) and shown read-only inside at /node_modules/NAME, where the interpreter looks from
// /submission. Never from the submission's own folder: a stranger's node_modules may link anywhere.
// False, with what is missing and its fix, when a named package is in no trusted folder: the
// grader's set-up, not the code.
bool show_named_packages(const Language& l, const std::string& source, SandboxSpec& spec, std::string& missing) {
  namespace fs = std::filesystem;
  const auto names = l.named_packages(source);
  if (names.empty()) return true;
  std::vector<std::string> roots;
  try {
    roots = trusted_library_roots();
  } catch (const std::invalid_argument& e) {
    missing = e.what();
    return false;
  }
  for (const auto& name : names) {
    std::string found;
    for (const auto& root : roots) {
      const fs::path r(root);
      for (const fs::path& candidate :
           {r / l.package_folder / name, r.filename() == l.package_folder ? r / name : fs::path()}) {
        std::error_code ec;
        if (!candidate.empty() && fs::is_regular_file(candidate / "package.json", ec)) {
          found = fs::weakly_canonical(candidate, ec).string();
          break;
        }
      }
      if (!found.empty()) break;
    }
    if (found.empty()) {
      std::string where;
      for (const auto& root : roots) where += (where.empty() ? "" : ", ") + root;
      missing = "the file names the npm package " + name + " (`// geomech: npm " + name +
                "`), which is in no folder the grader trusts (GEOMECH_LIBRARY_ROOTS: " +
                (where.empty() ? std::string("not set") : where) + "). Fix: `npm install " + name +
                " --prefix DIR` and GEOMECH_LIBRARY_ROOTS=DIR";
      return false;
    }
    const std::pair<std::string, std::string> mount(found, "/" + l.package_folder + "/" + name);
    if (std::find(spec.mounts.begin(), spec.mounts.end(), mount) == spec.mounts.end()) spec.mounts.push_back(mount);
  }
  return true;
}

// A submission the intake refused (an entry that is a link, a device, too large: RefusedEntry, whose
// words name it) or could not read: said, and the code's error (2).
int refused(const std::string& file, const std::exception& e) {
  if (dynamic_cast<const RefusedEntry*>(&e))
    std::cerr << "geomech check: " << inert_text(e.what()) << "\n";
  else
    std::cerr << "geomech check: " << file << ": " << e.what() << "\n";
  return 2;
}

// The files a served file names as its own (`geomech: beside NAME`, harness/languages/language.hpp),
// copied with it into /submission as a stranger's files are (never through a link, never a device,
// within the intake's limits); the paths here of each. A file named and not there, or a name that is
// a path, is the code's mistake: std::invalid_argument (RefusedEntry for an entry the intake refuses).
std::vector<std::string> add_beside_files(const Language& l, const std::string& file, PrivateCopy& copy) {
  namespace fs = std::filesystem;
  const fs::path p = fs::path(file).lexically_normal();
  const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::vector<std::string> added;
  for (const auto& name : beside_files(l, read_stranger_file(file))) {
    const fs::path beside = folder / name;
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(beside, ec)))
      throw std::invalid_argument("`geomech: beside " + name + "` names a file that is not beside it (no " +
                                  beside.string() + ")");
    (void)copy.add(beside.string(), "submission");
    added.push_back(beside.string());
  }
  return added;
}

// What the sandbox is given for a served file (or a notebook's cells file, `notebook`): its
// interpreter shown read-only (a venv, pyenv: harness/isolation/sandboxed_interpreter.hpp), the server
// script and the file (or folder) copied (the last two arguments of `cmd`), the files it names beside
// it, the runtimes they need started once inside, and the packages each names. 0 when all is ready;
// else the exit status, said on stderr: the grader's machine (kExitMachine, out.machine_fault set)
// or the code's own mistake (2).
int prepare_served(const std::string& file, const Language* served, bool notebook, std::vector<std::string>& cmd,
                   SandboxSpec& spec, PrivateCopy& copy, SubmissionOutcome& out) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // Python or Octave: the interpreter and its libraries are in /usr, or shown read-only where they
  // are (a venv, pyenv: harness/isolation/sandboxed_interpreter.hpp); the server script and the student's
  // file (or folder) are the last two arguments.
  if (cmd.size() > 2 && served && served->for_sandbox) {
    const SandboxedInterpreter si = served->for_sandbox(cmd[0]);
    if (!si.error.empty()) {  // the grader's set-up, not the submission
      std::cerr << "geomech check: " << file << ": the grader's machine: " << si.error << "\n";
      out.machine_fault = "the grader's machine: " + si.error;
      return kExitMachine;
    }
    cmd[0] = si.program;
    spec.read_only.insert(spec.read_only.end(), si.read_only.begin(), si.read_only.end());
  }
  // A served file with the files it names beside it (a wrapper's Node server, a module it imports).
  std::vector<std::string> own;
  try {
    cmd[cmd.size() - 2] = copy.add(cmd[cmd.size() - 2], "geomech");
    cmd.back() = copy.add(cmd.back(), "submission");
    if (served && !notebook && fs::is_regular_file(file, ec)) {
      own = {file};
      for (auto& b : add_beside_files(*served, file, copy)) own.push_back(std::move(b));
    }
  } catch (const std::exception& e) {
    return refused(file, e);
  }
  // The runtimes they need start inside the sandbox (the served file's, and each own file's: a
  // Python wrapper's Node server), or the grader's machine is at fault, never the code.
  std::vector<const Language*> runtimes{served};
  for (const auto& f : own)
    if (const Language* l = language_of(f); l && l->route == Route::Served) runtimes.push_back(l);
  for (std::size_t i = 0; i < runtimes.size(); ++i) {
    if (!runtimes[i] || std::find(runtimes.begin(), runtimes.begin() + i, runtimes[i]) != runtimes.begin() + i)
      continue;
    if (const std::string problem = interpreter_start_problem(*runtimes[i]); !problem.empty()) {
      std::cerr << "geomech check: " << file << ": the grader's machine: " << problem << "\n";
      out.machine_fault = "the grader's machine: " + problem;
      return kExitMachine;
    }
    // Another runtime an own file needs is shown as the served one's is, and named to the wrapper
    // by its variable (GEOMECH_NODE=/usr/bin/node), as outside the sandbox.
    if (i > 0 && runtimes[i]->for_sandbox && runtimes[i]->interpreter) {
      const SandboxedInterpreter si = runtimes[i]->for_sandbox(runtimes[i]->interpreter());
      spec.read_only.insert(spec.read_only.end(), si.read_only.begin(), si.read_only.end());
      spec.env.emplace_back(runtimes[i]->interpreter_variable, si.program);
    }
  }
  // The packages each of them names, by its own language's row.
  for (const auto& f : own) {
    const Language* l = language_of(f);
    std::string missing;
    if (l && l->named_packages && !show_named_packages(*l, read_stranger_file(f), spec, missing)) {
      std::cerr << "geomech check: " << f << ": the grader's machine: " << missing << "\n";
      out.machine_fault = "the grader's machine: " + missing;
      return kExitMachine;
    }
  }
  return 0;
}

// A compiled submission behind the sandbox: compiled (sandboxed too) into a protocol server that
// links the student's code and nothing of the judge, copied for the sandbox (`cmd`), with its
// libraries under a folder the grader trusts shown read-only. 0 when ready; else the exit status,
// said on stderr: a file that does not compile (2, out.built false), the grader's machine
// (kExitMachine).
int prepare_compiled(const std::string& file, const Language& l, BuildOptions& bo, std::vector<std::string>& cmd,
                     nlohmann::json& notes, std::string& language, SandboxSpec& spec, PrivateCopy& copy,
                     SubmissionOutcome& out) {
  const Toolchain tc = load_toolchain(default_toolchain_path());
  bo.server = true;
  bo.sandbox = true;
  const BuildResult b = build_student(file, tc, bo);
  for (const auto& line : b.log) std::cerr << "geomech: " << line << " (sandboxed)\n";
  out.build_seconds = b.seconds;
  if (!b.ok) {
    std::cerr << "geomech check: " << file << ": " << b.message << "\n";
    if (!b.machine_fault.empty()) {  // the sandbox could not start the compiler: the set-up's
      out.machine_fault = b.machine_fault;
      return kExitMachine;
    }
    out.built = false;
    out.build_message = b.message;
    return 2;
  }
  std::cerr << "geomech: built " << b.name << "'s protocol server" << (b.cached ? " (up to date)" : "") << " in "
            << std::fixed << std::setprecision(1) << b.seconds << " s\n";
  notes = b.notes;
  language = l.id;
  // Its libraries under a folder the grader trusts are loaded inside the sandbox (build_student vetted it).
  for (const auto& root : trusted_library_roots()) spec.read_only.push_back(root);
  try {
    cmd = {copy.add(b.program, "submission", IntakeLimits{}.program_bytes)};
  } catch (const std::exception& e) {
    std::cerr << "geomech check: " << file << ": " << e.what() << "\n";
    return 2;
  }
  for (const auto& f : tc.flags)
    if (f.find("-fsanitize=") == 0 && f.find("address") != std::string::npos) spec.limits.memory_mb = 0;
  return 0;
}

int run_untrusted_check(const SubmissionRequest& r, SubmissionOutcome& out) {
  const std::string& file = r.file;
  BuildOptions bo = r.build;
  const auto t0 = std::chrono::steady_clock::now();
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(file, ec)) {
    std::cerr << "geomech check: " << file << ": no such file\n";
    return 2;
  }
  if (const std::string why = sandbox_unavailable(); !why.empty()) {  // this machine's set-up, not the file
    std::cerr << "geomech check: " << why << "\n";
    out.machine_fault = why;
    return kExitMachine;
  }
  // A submission is a stranger's: never followed through a link, never a FIFO or device opened
  // (harness/isolation/submission_intake.hpp). A folder (Octave) is looked at whole, within the limits.
  try {
    const fs::path p = fs::path(file).lexically_normal();
    const std::string parent = p.has_parent_path() ? p.parent_path().string() : ".";
    const StrangerFolder folder(parent);
    const auto entry = folder.look(p.filename().string());
    if (entry.kind == EntryKind::Folder)
      (void)read_submission(folder, p.filename().string());
    else
      (void)read_stranger_file(file);
  } catch (const std::exception& e) {
    return refused(file, e);
  }
  SandboxSpec spec;
  // The sandbox clears the environment: what the harness sets for the server is passed again (the
  // reply descriptor itself, 3, is inherited through bubblewrap like 0, 1 and 2).
  spec.env = {{"GEOMECH_SLOT_TABLE", protocol::slot_table_json()}, {"GEOMECH_REPLY_FD", "3"}};
  // --memory-limit: the whole sandbox's memory (a cgroup's total as root; else each process's writable
  // memory, harness/isolation/sandbox.hpp). Whether the sandbox started the server is bubblewrap's word.
  spec.limits.memory_mb = r.check.memory_limit_mb;
  spec.report_start = true;
  std::string language, why;
  std::vector<std::string> cmd = server_command(file, &language, &why);
  // A notebook: its cells file, served by its kernel's row (nothing beside it is shown to the sandbox).
  std::optional<NotebookCells> nb;
  if (const Language* l = language_of(file); l && l->route == Route::Notebook) {
    try {
      nb.emplace(file, "");
    } catch (const std::exception& e) {  // NotebookError: what is wrong in it
      std::cerr << "geomech check: " << e.what() << "\n";
      return 2;
    }
    cmd = nb->language().server(nb->cells_file());
    language = nb->language().id;
  }
  nlohmann::json notes;
  // What the sandbox sees of this machine besides the system: a private copy of the submission
  // and of the suite's server, under neutral names (harness/isolation/private_copy.hpp).
  std::optional<PrivateCopy> copy;
  try {
    copy.emplace();
  } catch (const std::exception& e) {
    std::cerr << "geomech check: " << e.what() << "\n";
    return 2;
  }
  if (!cmd.empty()) {
    if (const int status =
            prepare_served(file, nb ? &nb->language() : language_of(file), nb.has_value(), cmd, spec, *copy, out))
      return status;
  } else if (const Language* l = language_of(file); l && l->route == Route::Compiled) {
    if (const int status = prepare_compiled(file, *l, bo, cmd, notes, language, spec, *copy, out)) return status;
  } else {
    std::cerr << "geomech check: " << file << ": not a " << extensions_in_words() << " file" << folder_in_words()
              << "\n";
    return 2;
  }
  const auto copies = copy->mounts();
  spec.mounts.insert(spec.mounts.begin(), copies.begin(), copies.end());
  return run_protocol_check(r, sandboxed(cmd, spec), language, notes, " --untrusted" + replay_build_options(bo), t0,
                            out, bo.name, nb ? &nb->notebook() : nullptr);
}

int route(const SubmissionRequest& r, SubmissionOutcome& out) {
  std::error_code ec;
  if (!language_of(r.file) && std::filesystem::exists(r.file, ec)) {  // what no row of the table reads
    std::cerr << "geomech check: " << r.file << ": not a " << extensions_in_words() << " file" << folder_in_words()
              << "\n";
    return 2;
  }
  if (r.sandboxed) return run_untrusted_check(r, out);
  if (const Language* l = language_of(r.file); l && l->route == Route::Notebook) return run_notebook_check(r, out);
  if (is_remote_file(r.file)) return run_remote_check(r, out);
  return run_student_check(r, out);
}

}  // namespace

int check_submission(const SubmissionRequest& r) {
  SubmissionOutcome out;
  out.exit_code = route(r, out);
  if (!r.outcome_file.empty()) {
    const nlohmann::json j{{"format", "geomech-outcome 1"},
                           {"exit_code", out.exit_code},
                           {"built", out.built},
                           {"build_message", out.build_message},
                           {"build_seconds", out.build_seconds},
                           {"machine_fault", out.machine_fault},
                           {"check_seconds", out.check_seconds}};
    write_file_atomically(r.outcome_file, j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace));
  }
  return out.exit_code;
}

std::optional<SubmissionOutcome> read_outcome(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.at("format") != "geomech-outcome 1") return std::nullopt;
    SubmissionOutcome out;
    out.exit_code = j.at("exit_code");
    out.built = j.at("built");
    out.build_message = j.at("build_message");
    out.build_seconds = j.at("build_seconds");
    out.machine_fault = j.at("machine_fault");
    out.check_seconds = j.at("check_seconds");
    return out;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

int check_builtin_subject(const SubjectSet& subject, const std::string& name, const SubmissionRequest& r) {
  SubjectInfo info;
  info.reproduce_prefix = r.front_door + " check --subject " + name;
  return run_check_cli(subject, info, r.check);
}

}  // namespace gm::harness
