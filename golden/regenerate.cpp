#include "golden/regenerate.hpp"

#include "golden/catalogue.hpp"
#include "golden/generate.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

namespace gm::golden {

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

bool read_file(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  text = ss.str();
  return !in.bad();
}

// Holds SIGINT, SIGTERM and SIGHUP back while alive; a signal that arrived meanwhile is
// delivered when it ends.
class SignalHold {
 public:
  SignalHold() {
    sigemptyset(&set_);
    sigaddset(&set_, SIGINT);
    sigaddset(&set_, SIGTERM);
    sigaddset(&set_, SIGHUP);
    sigprocmask(SIG_BLOCK, &set_, &old_);
  }
  ~SignalHold() { sigprocmask(SIG_SETMASK, &old_, nullptr); }
  SignalHold(const SignalHold&) = delete;
  SignalHold& operator=(const SignalHold&) = delete;

 private:
  sigset_t set_, old_;
};

// Says how long a fixture took to generate, method by method, and how closely its checks agree.
void report_generation(const std::string& name, const GenerationReport& rep, std::ostream& err) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f s", rep.seconds);
  err << name << ": " << buf << " (";
  for (std::size_t i = 0; i < rep.timings.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.2f s", rep.timings[i].seconds);
    err << (i ? ", " : "") << rep.timings[i].method << " " << buf;
  }
  err << "); checks agree to " << rep.max_abs_diff << " (required <= " << rep.allowed << ")\n";
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  const std::string tmp = (dir / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()))).string();
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(tmp + ": cannot create: " + std::strerror(errno));
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      const std::string why = std::strerror(errno);
      ::close(fd);
      ::unlink(tmp.c_str());
      throw std::runtime_error(tmp + ": write failed: " + why);
    }
    done += static_cast<std::size_t>(w);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw std::runtime_error(tmp + ": cannot flush to disk: " + why);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw std::runtime_error(path + ": cannot replace: " + why);
  }
}

std::vector<std::string> fixture_differences(const std::string& path, const std::string& committed,
                                             const std::string& regenerated) {
  std::vector<std::string> out;
  if (committed == regenerated) return out;
  Fixture c, g;
  try {
    c = parse_fixture(committed, path);
  } catch (const InputError& e) {
    out.push_back(std::string(e.what()) + " (the committed fixture is malformed)");
    return out;
  }
  g = parse_fixture(regenerated, path + " (regenerated)");
  // Header and comment lines: everything that is not a data row, in order.
  const auto cl = lines_of(committed), gl = lines_of(regenerated);
  std::vector<std::pair<int, std::string>> ch, gh;
  auto collect = [](const std::vector<std::string>& lines, const std::vector<int>& row_lines,
                    std::vector<std::pair<int, std::string>>& h) {
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (std::find(row_lines.begin(), row_lines.end(), static_cast<int>(i + 1)) == row_lines.end())
        h.emplace_back(static_cast<int>(i + 1), lines[i]);
  };
  collect(cl, c.row_lines, ch);
  collect(gl, g.row_lines, gh);
  for (std::size_t i = 0; i < std::max(ch.size(), gh.size()); ++i) {
    if (i < ch.size() && i < gh.size() && ch[i].second == gh[i].second) continue;
    const int line = i < ch.size() ? ch[i].first : (cl.empty() ? 0 : static_cast<int>(cl.size()));
    out.push_back(path + ":" + std::to_string(line) +
                  ": header differs\n    committed:   " + (i < ch.size() ? ch[i].second : std::string("(missing)")) +
                  "\n    regenerated: " + (i < gh.size() ? gh[i].second : std::string("(missing)")));
  }
  // Values, matched by sample time and column name.
  for (std::size_t i = 0; i < g.times.size(); ++i) {
    const auto it = std::find(c.times.begin(), c.times.end(), g.times[i]);
    if (it == c.times.end()) {
      out.push_back(path + ": the sample at t = " + g.times[i] + " is missing from the committed fixture");
      continue;
    }
    const std::size_t ci = static_cast<std::size_t>(it - c.times.begin());
    for (std::size_t k = 0; k < g.columns.size(); ++k) {
      const auto col = std::find(c.columns.begin(), c.columns.end(), g.columns[k]);
      if (col == c.columns.end()) continue;  // reported with the columns header line
      const std::string& cv = c.rows[ci][static_cast<std::size_t>(col - c.columns.begin())];
      const std::string& gv = g.rows[i][k];
      if (cv == gv) continue;
      Rational d = parse_decimal(cv) - parse_decimal(gv);
      if (d < 0) d = -d;
      out.push_back(path + ":" + std::to_string(c.row_lines[ci]) + ": t = " + g.times[i] + ", " + g.columns[k] +
                    ": committed " + cv + ", regenerated " + gv + " (|difference| " + format_significant(d, 2) + ")");
    }
  }
  for (std::size_t i = 0; i < c.times.size(); ++i)
    if (std::find(g.times.begin(), g.times.end(), c.times[i]) == g.times.end())
      out.push_back(path + ":" + std::to_string(c.row_lines[i]) + ": the committed sample at t = " + c.times[i] +
                    " is no longer generated");
  if (out.empty()) out.push_back(path + ": the texts differ (line endings or spacing)");
  return out;
}

namespace {

// --check: compares each regenerated fixture with the committed one (and, when all are
// regenerated, looks for committed fixtures no longer generated); the exit status.
int check_against_committed(const RegenerateOptions& o, const std::string& dir,
                            const std::vector<std::pair<std::string, std::string>>& texts,
                            std::chrono::steady_clock::time_point start, std::ostream& out, std::ostream& err) {
  namespace fs = std::filesystem;
  std::error_code ec;
  int differing = 0;
  for (const auto& [path, text] : texts) {
    std::string committed;
    if (!read_file(path, committed)) {
      err << path << ": missing (run `./geomech golden regenerate` and commit the file)\n";
      ++differing;
      continue;
    }
    const auto diffs = fixture_differences(path, committed, text);
    for (const auto& m : diffs) err << m << "\n";
    if (!diffs.empty()) ++differing;
  }
  if (o.only.empty()) {
    // A committed fixture that is no longer generated is stale.
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const auto p = entry.path();
      if (p.extension() != ".golden") continue;
      if (!find_definition(p.stem().string())) {
        err << p.string() << ": not in the fixture set (golden/catalogue.cpp): remove it or add its definition\n";
        ++differing;
      }
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (differing) {
    err << "geomech golden regenerate --check: " << differing << " of " << texts.size()
        << " fixtures differ from their regeneration\n";
    return 1;
  }
  out << "geomech golden regenerate --check: " << texts.size() << " fixture" << (texts.size() == 1 ? "" : "s")
      << " identical to their regeneration, certificates included: every printed value proved within its "
         "certified radius ("
      << static_cast<int>(secs * 100 + 0.5) / 100.0 << " s)\n";
  return 0;
}

}  // namespace

int regenerate(const RegenerateOptions& o, std::ostream& out, std::ostream& err) {
  namespace fs = std::filesystem;
  const std::string dir = o.dir.empty() ? default_fixture_dir() : o.dir;
  std::vector<const FixtureDefinition*> selected;
  for (const auto& name : o.only) {
    const FixtureDefinition* d = find_definition(name);
    if (!d) {
      std::string known;
      for (const auto& x : fixture_definitions()) known += " " + x.name;
      err << "geomech golden regenerate: --only " << name << ": no fixture is named '" << name << "' (known:" << known
          << ")\n";
      return 2;
    }
    if (std::find(selected.begin(), selected.end(), d) == selected.end()) selected.push_back(d);
  }
  if (o.only.empty())
    for (const auto& d : fixture_definitions()) selected.push_back(&d);
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    if (o.check) {
      err << "geomech golden regenerate: " << dir << ": not a directory (no committed fixtures to check)\n";
      return 2;
    }
    fs::create_directories(dir, ec);
    if (ec) {
      err << "geomech golden regenerate: " << dir << ": cannot create: " << ec.message() << "\n";
      return 2;
    }
  }

  const auto start = std::chrono::steady_clock::now();
  std::vector<std::pair<std::string, std::string>> texts;  // path, text
  int status = 0;
  for (const FixtureDefinition* d : selected) {
    GenerationReport rep;
    try {
      Request rq = make_request(*d);
      rq.certify = !o.no_certify;
      const Fixture f = generate(rq, &rep);
      texts.emplace_back(fixture_path(dir, d->name), write_fixture(f));
    } catch (const std::exception& e) {
      err << "geomech golden regenerate: " << d->name << ": " << e.what() << "\n";
      status = 1;
      continue;
    }
    if (!o.quiet) report_generation(d->name, rep, err);
  }
  if (status != 0) {
    err << "geomech golden regenerate: nothing " << (o.check ? "checked" : "written")
        << ": a fixture could not be generated and verified\n";
    return status;
  }

  if (o.check) return check_against_committed(o, dir, texts, start, out, err);

  int written = 0;
  {
    SignalHold hold;
    for (const auto& [path, text] : texts) {
      std::string committed;
      if (read_file(path, committed) && committed == text) continue;
      try {
        write_file_atomically(path, text);
      } catch (const std::exception& e) {
        err << "geomech golden regenerate: " << e.what() << "\n";
        return 2;
      }
      ++written;
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << "geomech golden regenerate: " << texts.size() << " fixtures in " << dir << ", " << written << " written, "
      << texts.size() - written << " unchanged (" << static_cast<int>(secs * 100 + 0.5) / 100.0 << " s)\n";
  return 0;
}

}  // namespace gm::golden
