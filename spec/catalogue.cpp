#include "spec/catalogue.hpp"

#include "core/data_path.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace gm {

using nlohmann::json;

const SpecEntry* Catalogue::find(std::string_view id) const {
  for (const auto& e : entries)
    if (e.id == id) return &e;
  return nullptr;
}

std::string default_catalogue_path() {
  if (const char* p = std::getenv("GEOMECH_CATALOGUE"); p && *p) return p;
  return suite_data_path("spec/catalogue.json");  // installed beside the tool, or in the source tree
}

namespace {

std::string req_string(const json& j, const char* field, const std::string& where) {
  if (!j.contains(field) || !j[field].is_string() || j[field].get<std::string>().empty())
    throw std::runtime_error(where + ": field '" + field + "' must be a non-empty string");
  return j[field].get<std::string>();
}

std::string opt_string(const json& j, const char* field, const std::string& where) {
  if (!j.contains(field)) return {};
  if (!j[field].is_string()) throw std::runtime_error(where + ": field '" + field + "' must be a string");
  return j[field].get<std::string>();
}

}  // namespace

Catalogue load_catalogue(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the spec catalogue");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number past double's range (1e999)
    throw std::runtime_error(path + ": not valid JSON: " + e.what());
  }
  Catalogue c;
  c.path = path;
  if (!j.is_object() || j.value("format", "") != "geomech-spec-catalogue 1")
    throw std::runtime_error(path + ": expected an object with \"format\": \"geomech-spec-catalogue 1\"");
  c.source = req_string(j, "source", path);
  if (!j.contains("entries") || !j["entries"].is_array())
    throw std::runtime_error(path + ": missing \"entries\" array");
  std::set<std::string> ids;
  int index = 0;
  for (const auto& je : j["entries"]) {
    const std::string where = path + ": entry #" + std::to_string(index++);
    if (!je.is_object()) throw std::runtime_error(where + ": not an object");
    SpecEntry e;
    e.id = req_string(je, "id", where);
    const std::string w = path + ": entry '" + e.id + "'";
    if (!ids.insert(e.id).second) throw std::runtime_error(w + ": duplicate id");
    e.section = req_string(je, "section", w);
    e.place = req_string(je, "place", w);
    if (!je.contains("line") || !je["line"].is_number_integer() || je["line"].get<int>() < 1)
      throw std::runtime_error(w + ": field 'line' must be a positive integer");
    e.line = je["line"].get<int>();
    e.anchor = req_string(je, "anchor", w);
    e.kind = req_string(je, "kind", w);
    if (e.kind != "algebraic" && e.kind != "dynamic" && e.kind != "variational")
      throw std::runtime_error(w + ": kind must be algebraic, dynamic or variational, not '" + e.kind + "'");
    e.status = req_string(je, "status", w);
    if (je.contains("issue") && !je["issue"].is_null()) {
      if (!je["issue"].is_number_integer()) throw std::runtime_error(w + ": field 'issue' must be an integer or null");
      e.issue = je["issue"].get<int>();
    }
    e.statement = req_string(je, "statement", w);
    e.note = opt_string(je, "note", w);
    if (je.contains("erratum")) {
      const auto& er = je["erratum"];
      if (!er.is_object()) throw std::runtime_error(w + ": 'erratum' must be an object");
      Erratum x;
      x.literal = req_string(er, "literal", w + " erratum");
      x.corrected = req_string(er, "corrected", w + " erratum");
      x.property = req_string(er, "property", w + " erratum");
      x.literal_variant = req_string(er, "literal_variant", w + " erratum");
      e.erratum = x;
    }
    c.entries.push_back(std::move(e));
  }
  return c;
}

std::vector<const Property*> properties_for(const std::string& spec_id, const std::vector<Property>& props) {
  std::vector<const Property*> out;
  for (const auto& p : props)
    if (p.spec == spec_id) out.push_back(&p);
  return out;
}

std::vector<std::string> traceability_problems(const Catalogue& c, const std::vector<Property>& props,
                                               const std::vector<std::string>* mutant_names) {
  std::vector<std::string> problems;
  auto problem = [&](std::string s) { problems.push_back(std::move(s)); };

  // The notes: each entry's anchor text must be on its line.
  // `source` is relative to the project root, the directory holding spec/.
  const auto notes_path = (std::filesystem::absolute(c.path).parent_path().parent_path() / c.source).lexically_normal();
  std::vector<std::string> lines;
  {
    std::ifstream in(notes_path);
    if (!in) problem("cannot read the notes at " + notes_path.string() + " to check the entries' places");
    for (std::string l; std::getline(in, l);) lines.push_back(l);
  }
  for (const auto& e : c.entries) {
    if (!lines.empty()) {
      if (e.line > static_cast<int>(lines.size()))
        problem(e.id + ": line " + std::to_string(e.line) + " is past the end of the notes");
      else if (lines[e.line - 1].find(e.anchor) == std::string::npos)
        problem(e.id + ": anchor '" + e.anchor + "' is not on line " + std::to_string(e.line) + " of the notes");
    }
    const auto checking = properties_for(e.id, props);
    if (e.status == "checked") {
      if (checking.empty()) problem(e.id + ": marked checked, but no property names it");
      if (e.erratum) problem(e.id + ": has an erratum block but is marked checked (use status erratum)");
    } else if (e.status == "pending") {
      if (!checking.empty())
        problem(e.id + ": marked pending, but property '" + checking.front()->id + "' checks it (mark it checked)");
    } else if (e.status == "erratum") {
      if (!e.erratum) {
        problem(e.id + ": marked erratum without an erratum block (literal, corrected, property, literal_variant)");
      } else {
        const Property* p = find_property(e.erratum->property);
        if (!p)
          problem(e.id + ": erratum evidence property '" + e.erratum->property + "' is not registered");
        else {
          if (p->spec != e.id)
            problem(e.id + ": erratum evidence property '" + p->id + "' names entry '" + p->spec + "' instead");
          if (std::find(p->negative_controls.begin(), p->negative_controls.end(), e.erratum->literal_variant) ==
              p->negative_controls.end())
            problem(e.id + ": the literal variant '" + e.erratum->literal_variant + "' is not a negative control of '" +
                    p->id + "', so no test shows the literal statement failing");
        }
      }
    } else {
      problem(e.id + ": status '" + e.status + "' is neither checked, pending nor erratum");
    }
  }
  std::set<std::string> mutants;
  if (mutant_names) mutants.insert(mutant_names->begin(), mutant_names->end());
  for (const auto& p : props) {
    if (!c.find(p.spec))
      problem("property '" + p.id + "' names spec entry '" + p.spec + "', which is not in the catalogue");
    if (p.negative_controls.empty()) problem("property '" + p.id + "' has no negative control");
    if (mutant_names)
      for (const auto& m : p.negative_controls)
        if (!mutants.count(m))
          problem("property '" + p.id + "': negative control '" + m + "' is not a registered mutant");
    for (const auto& n : p.needs)
      if (!is_slot_name(n)) problem("property '" + p.id + "' needs '" + n + "', which is not a subject slot");
    if (p.title.empty()) problem("property '" + p.id + "' has no title");
  }
  // Every slot is checked on its own by a property that needs that slot alone, so that
  // an implementation providing any subset of the slots has each of them checked.
  for (const auto& slot : subject_slots()) {
    const bool alone = std::any_of(props.begin(), props.end(), [&](const Property& p) {
      return p.needs.size() == 1 && p.needs.front() == slot.name;
    });
    if (!alone) problem(std::string("slot '") + slot.name + "' has no property that needs it alone (a direct check)");
  }
  return problems;
}

namespace {

std::string md_escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '|')
      out += "\\|";
    else if (ch == '\n')
      out += ' ';
    else if (ch == '*' || ch == '_') {
      out += '\\';
      out += ch;
    } else
      out += ch;
  }
  return out;
}

std::string scalars_of(const Property& p) {
  std::string s;
  if (p.runs_in(ScalarKind::Double)) s += "double";
  if (p.runs_in(ScalarKind::MP50)) s += std::string(s.empty() ? "" : ", ") + "mp50";
  if (p.runs_in(ScalarKind::Exact)) s += std::string(s.empty() ? "" : ", ") + "exact";
  return s;
}

}  // namespace

std::string catalogue_markdown(const Catalogue& c, const std::vector<Property>& props) {
  std::ostringstream os;
  std::map<std::string, int> by_status;
  for (const auto& e : c.entries) ++by_status[e.status];
  os << "# Spec catalogue: statements of the notes and the properties that check them\n\n"
     << "Generated from `spec/catalogue.json` and the property registry by `build/bin/geomech catalogue "
        "--markdown`; do not edit by hand (a test fails when this file is stale).\n\n"
     << c.entries.size() << " entries: " << by_status["checked"] << " checked, " << by_status["erratum"]
     << " erratum (the corrected statement is checked), " << by_status["pending"] << " pending; " << props.size()
     << " properties.\n\n"
     << "| entry | place in the notes | kind | status | properties (tolerance class; scalars; file) |\n"
     << "|---|---|---|---|---|\n";
  for (const auto& e : c.entries) {
    os << "| `" << e.id << "` | " << md_escape(e.place) << " (line " << e.line << ") | " << e.kind << " | " << e.status;
    if (e.status == "pending" && e.issue) os << " (issue " << *e.issue << ")";
    os << " | ";
    bool first = true;
    for (const Property* p : properties_for(e.id, props)) {
      if (!first) os << "<br>";
      first = false;
      os << "`" << p->id << "` (" << tolerance_name(p->tolerance) << "; " << scalars_of(*p);
      if (!p->file.empty()) os << "; [" << p->file.substr(p->file.find('/') + 1) << "](../" << p->file << ")";
      os << ")";
    }
    os << " |\n";
  }
  os << "\n## Statements\n\n";
  for (const auto& e : c.entries) {
    os << "- **`" << e.id << "`** (" << md_escape(e.place) << "): " << md_escape(e.statement);
    if (!e.note.empty()) os << " *Note:* " << md_escape(e.note);
    os << "\n";
  }
  os << "\n## Errata\n\n";
  bool any = false;
  for (const auto& e : c.entries) {
    if (!e.erratum) continue;
    any = true;
    os << "- **`" << e.id << "`** (" << md_escape(e.place) << ")\n"
       << "  - printed: " << md_escape(e.erratum->literal) << "\n"
       << "  - holds: " << md_escape(e.erratum->corrected) << "\n"
       << "  - evidence: property `" << e.erratum->property << "` passes on the reference implementation and fails on `"
       << e.erratum->literal_variant << "`, the subject that implements the printed statement.\n";
  }
  if (!any) os << "None recorded yet.\n";
  return os.str();
}

}  // namespace gm
