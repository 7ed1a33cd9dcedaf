// The trajectory-file reader (format: docs/TRAJECTORY_FORMAT.md).
#include "harness/trajectories/trajectory_reader.hpp"

#include "core/scalar.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {

constexpr double kAbsurd = 1e12;  // larger magnitudes are rejected as absurd
constexpr std::size_t kMaxRows = 1000000;
const char* kSystems = "rigid_body";
const char* kColumns4 = "t Pi1 Pi2 Pi3";
const char* kColumns13 = "t Pi1 Pi2 Pi3 O11 O12 O13 O21 O22 O23 O31 O32 O33";

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
  return std::string(s.substr(a, b - a));
}

struct Field {
  std::string text;
  std::size_t column;  // 1-based
};

std::vector<Field> split_fields(const std::string& line, std::size_t offset = 0) {
  std::vector<Field> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == ',' || line[i] == '\r')) ++i;
    if (i >= line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != ',' && line[i] != '\r') ++i;
    out.push_back({line.substr(start, i - start), offset + start + 1});
  }
  return out;
}

std::string where(const std::string& name, std::size_t line, std::size_t column = 0) {
  if (line == 0) return name + ": ";  // a value from the command line
  std::string w = name + ":" + std::to_string(line);
  if (column) w += ":" + std::to_string(column);
  return w + ": ";
}

std::string printable(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (c >= 0x20 && c < 0x7f)
      out += static_cast<char>(c);
    else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  if (out.size() > 60) out = out.substr(0, 57) + "...";
  return out;
}

// A finite, sane double, or a TrajectoryError saying precisely why not.
double number(const Field& f, const std::string& name, std::size_t line, const char* what) {
  std::string lower;
  for (char c : f.text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string bare = (!lower.empty() && (lower[0] == '+' || lower[0] == '-')) ? lower.substr(1) : lower;
  if (bare == "nan" || bare.rfind("nan(", 0) == 0)
    throw TrajectoryError(
        where(name, line, f.column) + what +
        " is NaN: a trajectory must be finite (NaN usually means the method broke down before this row)");
  if (bare == "inf" || bare == "infinity")
    throw TrajectoryError(where(name, line, f.column) + what + " is infinite: a trajectory must be finite");
  const char* first = f.text.data();
  const char* last = first + f.text.size();
  if (*first == '+') ++first;  // from_chars does not take a leading '+'
  double x = 0;
  const auto [ptr, ec] = std::from_chars(first, last, x);
  if (ec == std::errc::result_out_of_range)
    throw TrajectoryError(where(name, line, f.column) + what + " '" + printable(f.text) +
                          "' is out of the range of a double");
  if (ec != std::errc() || ptr != last)
    throw TrajectoryError(where(name, line, f.column) + what + " is not a number: '" + printable(f.text) + "'");
  if (!std::isfinite(x))
    throw TrajectoryError(where(name, line, f.column) + what + " is not finite: '" + printable(f.text) + "'");
  if (std::abs(x) > kAbsurd)
    throw TrajectoryError(where(name, line, f.column) + what + " = " + printable(f.text) +
                          " is an absurd magnitude (larger than 1e12); check the units and the scaling");
  return x;
}

int significant_digits(const std::string& text) {
  int n = 0;
  bool leading = true;
  for (char c : text) {
    if (c == 'e' || c == 'E') break;
    if (c < '0' || c > '9') continue;
    if (leading && c == '0') continue;
    leading = false;
    ++n;
  }
  return n;
}

}  // namespace

namespace {

// The text's lines (a last line without its newline included).
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t nl = text.find('\n', start);
    if (nl == std::string::npos) {
      if (start < text.size()) lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, nl - start));
    start = nl + 1;
  }
  return lines;
}

// What a header says, with the line of each field (0: not in the file).
struct Header {
  std::optional<std::string> system, step_text, columns;
  std::optional<std::array<std::string, 3>> inertia;
  std::size_t system_line = 0, inertia_line = 0, step_line = 0;
};

// The header's fields after the format line, from line i on; i is left at the first line that is
// not a header line. The method goes to tr.
Header read_header_fields(const std::vector<std::string>& lines, std::size_t& i, const std::string& name,
                          Trajectory& tr) {
  Header h;
  auto& [system, step_text, columns, inertia, system_line, inertia_line, step_line] = h;
  for (++i; i < lines.size(); ++i) {
    const std::string l = trim(lines[i]);
    if (l.empty()) continue;
    if (l[0] != '#') break;
    const std::string body = trim(std::string_view(l).substr(1));
    if (body.empty() || body[0] == '#') continue;  // "#" alone, or a "## free comment"
    const auto colon = body.find(':');
    const std::size_t key_col = lines[i].find(body) + 1;
    if (colon == std::string::npos)
      throw TrajectoryError(where(name, i + 1, key_col) +
                            "a header line must be '# key: value' (or a '## comment'), got '" + printable(body) + "'");
    const std::string key = trim(std::string_view(body).substr(0, colon));
    const std::string value = trim(std::string_view(body).substr(colon + 1));
    const std::size_t value_col = key_col + body.find(value, colon + 1);
    if (value.empty()) throw TrajectoryError(where(name, i + 1, key_col) + "header field '" + key + "' has no value");
    auto once = [&](bool seen) {
      if (seen) throw TrajectoryError(where(name, i + 1, key_col) + "header field '" + key + "' is given twice");
    };
    if (key == "system") {
      once(system.has_value());
      system = value;
      system_line = i + 1;
    } else if (key == "inertia") {
      once(inertia.has_value());
      const auto f = split_fields(value, value_col - 1);
      if (f.size() != 3)
        throw TrajectoryError(where(name, i + 1, value_col) + "inertia needs 3 numbers (I1 I2 I3), got " +
                              std::to_string(f.size()));
      inertia = std::array<std::string, 3>{f[0].text, f[1].text, f[2].text};
      for (const auto& x : f) number(x, name, i + 1, "a moment of inertia");
      inertia_line = i + 1;
    } else if (key == "step") {
      once(step_text.has_value());
      const auto f = split_fields(value, value_col - 1);
      if (f.size() != 1)
        throw TrajectoryError(where(name, i + 1, value_col) + "step needs one number, the step size h");
      number(f[0], name, i + 1, "the step size");
      step_text = f[0].text;
      step_line = i + 1;
    } else if (key == "method") {
      once(!tr.method.empty());
      tr.method = value;
    } else if (key == "columns") {
      once(columns.has_value());
      std::string norm;
      for (const auto& f : split_fields(value)) norm += (norm.empty() ? "" : " ") + f.text;
      if (norm != kColumns4 && norm != kColumns13)
        throw TrajectoryError(where(name, i + 1, value_col) + "columns must be '" + kColumns4 + "' or '" + kColumns13 +
                              "', got '" + printable(value) + "'");
      columns = norm;
    } else {
      throw TrajectoryError(where(name, i + 1, key_col) + "unknown header field '" + printable(key) +
                            "' (known: system, inertia, step, method, columns; free comments start with ##)");
    }
  }
  return h;
}

// Command-line parameters fill in what the header lacks and must agree with what it says; the
// system, the inertia (positive, and a body's unless --allow-nonphysical) and the step, into tr.
void settle_parameters(Header h, const TrajectoryParams& params, const std::string& name, Trajectory& tr) {
  auto& [system, step_text, columns, inertia, system_line, inertia_line, step_line] = h;
  auto merge = [&](auto& field, const auto& given, const char* what, std::size_t line) {
    if (!given) return;
    if (field && *field != *given)
      throw TrajectoryError(where(name, line) + std::string(what) + " in the file differs from --" + what +
                            " on the command line");
    field = given;
  };
  merge(system, params.system, "system", system_line);
  merge(inertia, params.inertia, "inertia", inertia_line);
  merge(step_text, params.step, "step", step_line);
  if (!system)
    throw TrajectoryError(name + ": no system: give '# system: rigid_body' in the header or --system rigid_body");
  if (*system != kSystems)
    throw TrajectoryError((system_line ? where(name, system_line) : name + ": ") + "unknown system '" +
                          printable(*system) + "' (known: " + kSystems + ")");
  if (!inertia)
    throw TrajectoryError(name + ": no inertia: give '# inertia: I1 I2 I3' in the header or --inertia I1,I2,I3");
  if (!step_text) throw TrajectoryError(name + ": no step size: give '# step: h' in the header or --step h");
  tr.system = *system;
  tr.inertia = *inertia;
  for (int k = 0; k < 3; ++k) {
    const double Ik = number({tr.inertia[k], 0}, name, inertia_line, "a moment of inertia");
    if (!(Ik > 0))
      throw TrajectoryError((inertia_line ? where(name, inertia_line) : name + ": ") +
                            "the moments of inertia must be positive, got I" + std::to_string(k + 1) + " = " +
                            printable(tr.inertia[k]));
  }
  {
    // No mass distribution has a moment larger than the sum of the other two (the notes' example
    // I = diag(1, 1/2, 1/3) is of that kind): refused unless --allow-nonphysical says otherwise.
    double I[3];
    for (int k = 0; k < 3; ++k) I[k] = number({tr.inertia[k], 0}, name, inertia_line, "a moment of inertia");
    for (int k = 0; k < 3; ++k)
      if (I[k] > I[(k + 1) % 3] + I[(k + 2) % 3]) {
        const std::string what = "I" + std::to_string(k + 1) +
                                 " is larger than the sum of the other two moments: no "
                                 "rigid body has this inertia";
        if (!params.allow_nonphysical)
          throw TrajectoryError((inertia_line ? where(name, inertia_line) : name + ": ") + what +
                                " (give --allow-nonphysical to check Euler's equations for it anyway)");
        tr.warnings.push_back(what + " (Euler's equations are checked anyway, --allow-nonphysical)");
      }
  }
  tr.step = number({*step_text, 0}, name, step_line, "the step size");
  if (!(tr.step > 0))
    throw TrajectoryError((step_line ? where(name, step_line) : name + ": ") + "the step size must be positive, got " +
                          printable(*step_text));
}

// The data rows from line i on, into tr; checked as they are read. `columns` is the header's, if
// any.
void read_rows(const std::vector<std::string>& lines, std::size_t i, const std::string& name,
               const std::optional<std::string>& columns, Trajectory& tr) {
  auto blank = [](const std::string& l) { return trim(l).empty(); };
  std::size_t expected_fields = columns ? (*columns == kColumns13 ? 13 : 4) : 0;
  std::size_t first_row_line = 0;
  int max_digits = 1;
  for (; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (blank(l)) continue;
    if (trim(l)[0] == '#') continue;  // comments after the data (np.savetxt footers) are ignored
    const auto f = split_fields(l);
    if (expected_fields == 0) {
      if (f.size() != 4 && f.size() != 13)
        throw TrajectoryError(where(name, i + 1) + "a row has " + std::to_string(f.size()) + " fields; expected 4 (" +
                              kColumns4 + ") or 13 (" + kColumns13 + ")");
      expected_fields = f.size();
    } else if (f.size() != expected_fields) {
      throw TrajectoryError(where(name, i + 1) + "a row has " + std::to_string(f.size()) + " fields, expected " +
                            std::to_string(expected_fields) + " like the " +
                            (tr.rows.empty() ? "columns line" : "rows above") + " (" +
                            (expected_fields == 13 ? kColumns13 : kColumns4) + ")");
    }
    if (tr.rows.size() >= kMaxRows)
      throw TrajectoryError(where(name, i + 1) + "more than " + std::to_string(kMaxRows) +
                            " rows; write every k-th step only");
    TrajectoryRow row;
    row.t = number(f[0], name, i + 1, "t");
    for (int k = 0; k < 3; ++k) row.Pi[k] = number(f[1 + k], name, i + 1, ("Pi" + std::to_string(k + 1)).c_str());
    for (std::size_t k = 4; k < f.size(); ++k) {
      const std::string what = "O" + std::to_string((k - 4) / 3 + 1) + std::to_string((k - 4) % 3 + 1);
      row.O[k - 4] = number(f[k], name, i + 1, what.c_str());
    }
    if (!tr.rows.empty() && !(row.t > tr.rows.back().t))
      throw TrajectoryError(where(name, i + 1, f[0].column) + "t = " + printable(f[0].text) +
                            " does not increase (the row before has t = " + to_string_full(tr.rows.back().t) + ")");
    if (tr.rows.empty()) {
      for (const auto& x : f) tr.first_row.push_back(x.text);
      first_row_line = i + 1;
    }
    for (int k = 1; k < 4; ++k) max_digits = std::max(max_digits, significant_digits(f[k].text));
    tr.rows.push_back(row);
  }
  tr.has_O = expected_fields == 13;
  if (tr.rows.empty()) throw TrajectoryError(name + ": no data rows (a trajectory needs at least two)");
  if (tr.rows.size() < 2) throw TrajectoryError(name + ": only one data row (a trajectory needs at least two)");
  const auto& Pi0 = tr.rows.front().Pi;
  if (Pi0[0] == 0 && Pi0[1] == 0 && Pi0[2] == 0)
    throw TrajectoryError(where(name, first_row_line) +
                          "Pi(0) = 0: zero angular momentum, a body at rest; every invariant is 0 and its relative "
                          "error undefined, so there is no motion to check");
  tr.digits = std::clamp(max_digits, 1, 17);
}

}  // namespace

Trajectory parse_trajectory(const std::string& text, const std::string& name, const TrajectoryParams& params) {
  Trajectory tr;
  tr.path = name;
  if (text.find('\0') != std::string::npos)
    throw TrajectoryError(name + ": this is not a text file (it contains NUL bytes)");
  const std::vector<std::string> lines = lines_of(text);
  std::size_t i = 0;
  auto blank = [](const std::string& l) { return trim(l).empty(); };
  while (i < lines.size() && blank(lines[i])) ++i;
  if (i == lines.size()) throw TrajectoryError(name + ": the file is empty (no header and no data)");

  Header header;
  if (trim(lines[i]).rfind("# geomech-trajectory", 0) == 0) {
    const std::string magic = trim(lines[i]);
    if (magic != "# geomech-trajectory 1")
      throw TrajectoryError(where(name, i + 1) + "unsupported format line '" + printable(magic) +
                            "'; this version reads '# geomech-trajectory 1'");
    header = read_header_fields(lines, i, name, tr);
  } else if (trim(lines[i])[0] == '#') {
    // Comment lines before the data of a file without the format line are allowed.
    while (i < lines.size() && (blank(lines[i]) || trim(lines[i])[0] == '#')) ++i;
  }
  settle_parameters(header, params, name, tr);
  read_rows(lines, i, name, header.columns, tr);
  return tr;
}

Trajectory read_trajectory(const std::string& path, const TrajectoryParams& params) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw TrajectoryError(path + ": is a folder, not a trajectory file");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw TrajectoryError(path + ": cannot be read");
  std::ostringstream os;
  os << f.rdbuf();
  return parse_trajectory(os.str(), path, params);
}

}  // namespace gm::harness
