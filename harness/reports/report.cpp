#include "harness/reports/report.hpp"

#include "harness/checking/integrator_verdicts.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/reports/report_formats.hpp"

#include "harness/checking/verdict_io.hpp"
#include "harness/checking/work_precision.hpp"
#include "harness/isolation/inert_text.hpp"
#include "harness/reports/svg.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

#include <unistd.h>

#include "harness/reports/report_parts.hpp"

namespace gm::harness {

namespace fs = std::filesystem;
using namespace report_parts;
using nlohmann::json;

const std::vector<std::string>& area_names() {
  static const std::vector<std::string> names = {"sec. 1", "sec. 2", "sec. 3", "momentum maps", "integrators"};
  return names;
}

std::string area_of(const Verdict& v, const Catalogue* c) {
  if (!v.integrator.empty()) return "integrators";
  if (const Property* p = property_of(v); p && p->scope == Scope::Integrator) return "integrators";
  std::string section;
  if (c)
    if (const SpecEntry* e = c->find(v.spec)) section = e->section;
  if (section.empty()) section = v.spec.substr(0, v.spec.find('.'));
  if (section == "1" || section == "s1") return "sec. 1";
  if (section == "2" || section == "s2") return "sec. 2";
  if (section == "3" || section == "s3") return "sec. 3";
  return "momentum maps";
}

std::vector<ClaimRow> claim_rows(const CheckResult& r, const IntegratorInfo& integrator) {
  // The decisions of the check (harness/checking/integrator_verdicts.hpp), made once; a result assembled
  // without them (a test's) is decided here by the same function.
  const std::vector<ClaimDecision> decisions =
      integrator.decisions.empty() ? decide_claims(r, integrator) : integrator.decisions;
  std::vector<ClaimRow> rows;
  for (const auto& d : decisions) {
    ClaimRow row;
    row.claim = d.claim;
    row.claimed = d.claimed;
    row.status = d.word;
    row.measured = d.measured;
    row.why = d.why;
    row.fails = fails_check(d);
    for (const auto& e : d.evidence) row.evidence += (row.evidence.empty() ? "" : "\n") + e;
    rows.push_back(row);
  }
  return rows;
}

std::vector<Figure> report_figures(const CheckResult& r) {
  struct Group {
    std::string title, integrator;
    std::vector<Series> series;
  };
  std::vector<std::pair<std::string, Group>> groups;  // file name -> group, in first-seen order
  auto add = [&](const std::string& owner, const Verdict& v) {
    for (const auto& s : v.series) {
      const std::string file =
          "figures/" + file_safe(owner + (v.integrator.empty() ? "" : "-" + v.integrator) + "-" + s.figure) + ".svg";
      auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == file; });
      if (it == groups.end()) {
        Group g;
        g.title = s.figure + (v.integrator.empty() ? "" : " - " + v.integrator) + " (" + owner + ")";
        g.integrator = v.integrator;
        groups.push_back({file, g});
        it = groups.end() - 1;
      }
      Series copy = s;
      if (copy.name.find(v.scalar) == std::string::npos) copy.name += " (" + v.scalar + ")";
      it->second.series.push_back(std::move(copy));
    }
  };
  for (const auto& p : r.portraits) add(p.property, p);
  for (const auto& v : r.verdicts) add(v.property, v);
  std::vector<Figure> out;
  for (const auto& [file, g] : groups) out.push_back(Figure{file, svg_plot(g.title, g.series), g.integrator});
  return out;
}

std::string slot_named(const SubjectInfo& info, const std::string& slot, const char* quote) {
  const std::string q(quote), name = q + slot + q;
  const std::string file = std::filesystem::path(info.source).filename().string();
  const Language& l = *info.language;
  if (l.function_noun.empty()) return "slot " + name;
  // In a notebook, the cell that defines it and the line there, as the notebook shows them.
  const std::string where = info.cells.empty() ? std::string() : where_defined(info.cells, l, slot);
  return l.function_noun + " " + name + (file.empty() ? "" : " in " + file) + (where.empty() ? "" : " (" + where + ")");
}

std::string first_line(const std::string& s) {
  std::size_t at = 0;
  std::string lead;  // "python function 'x' (mp50) raised an error:" says what follows, not what it is
  for (;;) {
    const auto n = s.find('\n', at);
    const std::string line = n == std::string::npos ? s.substr(at) : s.substr(at, n - at);
    if (n == std::string::npos) return lead.empty() ? line : lead + " " + line;
    if (line != "Exception thrown with message:" && !line.empty()) {
      if (line.back() != ':' || !lead.empty()) return lead.empty() ? line : lead + " " + line;
      lead = line;
    }
    at = n + 1;
  }
}

bool is_engine_wrapper(const CheckResult& r) {
  for (const auto& [scalar, slots] : r.provided)
    if (!slots.empty()) return false;
  return !r.integrators.empty();
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const fs::path p(path);
  const fs::path tmp = p.parent_path() / ("." + p.filename().string() + ".tmp." + std::to_string(::getpid()));
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + tmp.string());
    f << content;
    f.flush();
    if (!f) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  std::error_code ec;
  fs::rename(tmp, p, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot rename " + tmp.string() + " to " + path);
  }
}

void write_report_dir(const CheckResult& r, const std::string& dir, const Catalogue* c) {
  fs::path target = fs::absolute(dir).lexically_normal();
  while (target.has_relative_path() && target.filename().empty()) target = target.parent_path();  // "dir/" -> "dir"
  if (!target.has_relative_path() || target.filename() == "." || target.filename() == "..")
    throw std::runtime_error("cannot write a report into " + dir + ": give a directory of its own");
  const fs::path parent = target.parent_path();
  std::error_code ec;
  // Only a previous report (or an empty directory) is ever replaced: never someone's own files.
  if (fs::exists(target, ec)) {
    if (!fs::is_directory(target, ec))
      throw std::runtime_error("cannot write a report into " + target.string() + ": it is a file");
    if (!fs::is_empty(target, ec) && !fs::exists(target / "verdicts.json", ec))
      throw std::runtime_error(
          "refusing to replace " + target.string() +
          ": it is not empty and not a geomech report (no verdicts.json); choose another --report");
  }
  fs::create_directories(parent, ec);
  if (ec) throw std::runtime_error("cannot create " + parent.string() + ": " + ec.message());
  const std::string pid = std::to_string(::getpid());
  const fs::path tmp = parent / ("." + target.filename().string() + ".tmp." + pid);
  fs::remove_all(tmp, ec);
  fs::create_directories(tmp / "figures", ec);
  if (ec) throw std::runtime_error("cannot create " + tmp.string() + ": " + ec.message());
  auto put = [&](const std::string& name, const std::string& content) {
    std::ofstream f(tmp / name, std::ios::binary | std::ios::trunc);
    f << content;
    f.flush();
    if (!f) throw std::runtime_error("cannot write " + (tmp / name).string());
  };
  try {
    for (const ReportFormat& f : report_formats()) put(f.file, f.render(r, c));
    for (const auto& f : report_figures(r)) put(f.file, f.svg);
    if (const std::string csv = work_precision_csv(r); !csv.empty()) put("figures/work-precision.csv", csv);
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
  // Swap in: the old report (if any) moves aside, the new one takes its name, the old one goes.
  const fs::path old = parent / ("." + target.filename().string() + ".old." + pid);
  const bool had_old = fs::exists(target);
  if (had_old) {
    fs::rename(target, old, ec);
    if (ec) {
      fs::remove_all(tmp, ec);
      throw std::runtime_error("cannot replace " + target.string() + ": " + ec.message());
    }
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    const std::string why = ec.message();
    if (had_old) fs::rename(old, target, ec);
    fs::remove_all(tmp, ec);
    throw std::runtime_error("cannot move the new report into " + target.string() + ": " + why);
  }
  if (had_old) fs::remove_all(old, ec);
}

}  // namespace gm::harness
