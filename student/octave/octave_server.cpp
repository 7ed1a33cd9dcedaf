// geomech-octave-server: the slot protocol's server for Octave/MATLAB-style code (docs/PROTOCOL.md,
// version 2) with Octave's interpreter linked in (liboctinterp), built when liboctave-dev is
// installed. It answers exactly as student/octave/geomech_server.m does: same handshake, same
// values, same error texts and tracebacks, sessions and runs of steps. What differs is where the
// work of a call is done: the request is read, its arguments are made into Octave values, and the
// result is written, in C++; only the student's function runs in the interpreter. In the script
// server that codec is interpreted, 150-300 us a call against 10-60 us for the student's own
// function (docs/DEVELOPING.md, "Where a remote check's time goes").
//
//   geomech-octave-server mine.m        (one file of functions)
//   geomech-octave-server folder/       (one .m file per function)
//
// Requests on stdin, replies on $GEOMECH_REPLY_FD (3), the slot table in $GEOMECH_SLOT_TABLE; the
// implementation's printf and disp go to stdout, never to the reply channel.
#include <octave/interpreter.h>
#include <octave/oct-map.h>
#include <octave/oct.h>
#include <octave/ov-struct.h>
#include <octave/parse.h>
#include <octave/quit.h>
#include <octave/version.h>

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

// ---- the kinds of a slot's signature (docs/PROTOCOL.md: the type names before `<`) -------------

std::string kind_of(std::string text) {
  for (auto at = text.find("const"); at != std::string::npos; at = text.find("const")) text.erase(at, 5);
  std::size_t b = text.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  std::size_t e = b;
  while (e < text.size() && (std::isalnum(static_cast<unsigned char>(text[e])) || text[e] == '_')) ++e;
  return text.substr(b, e - b);
}

struct Kinds {
  std::string result;
  std::vector<std::string> args;
};

// 'R(const A<T>& a, int n)' -> result 'R', args {'A', 'int'}.
Kinds kinds_of(const std::string& signature) {
  Kinds k;
  k.result = kind_of(signature);
  const auto open = signature.find('(');
  const auto close = signature.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close <= open) return k;
  const std::string inner = signature.substr(open + 1, close - open - 1);
  if (inner.find_first_not_of(" \t") == std::string::npos) return k;
  std::size_t from = 0;
  for (;;) {
    const auto comma = inner.find(',', from);
    k.args.push_back(kind_of(inner.substr(from, comma == std::string::npos ? std::string::npos : comma - from)));
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return k;
}

bool is_pair(const std::string& kind) { return kind == "Vec3Pair" || kind == "MatXPair"; }

// ---- arguments: JSON -> Octave values, as the script server's gm_decode reads them --------------

// A decimal number as Octave's str2double reads it; false when the text is not one ('so3').
bool read_number(const std::string& s, double& v) {
  const char* b = s.data();
  const char* e = b + s.size();
  if (b != e && *b == '+') ++b;
  auto [p, ec] = std::from_chars(b, e, v);
  if (ec == std::errc() && p == e) return true;
  if (ec == std::errc::result_out_of_range) {  // from_chars leaves v alone: strtod's overflow or underflow
    v = std::strtod(s.c_str(), nullptr);
    return true;
  }
  return false;
}

double number_in(const json& j) {
  double v;
  if (j.is_string())
    return read_number(j.get_ref<const std::string&>(), v) ? v : std::numeric_limits<double>::quiet_NaN();
  if (j.is_number()) return j.get<double>();
  throw std::runtime_error("an argument entry that is neither a number nor a decimal string: " + j.dump());
}

octave_value decode(const json& j) {
  if (j.is_string()) {
    double v;
    if (read_number(j.get_ref<const std::string&>(), v)) return octave_value(v);
    return octave_value(j.get<std::string>());  // 'so3', 'so4', 'sl2'
  }
  if (j.is_number()) return octave_value(j.get<double>());
  if (j.is_boolean()) return octave_value(j.get<bool>());
  if (j.is_null()) return octave_value(Matrix());
  if (j.is_object()) {
    octave_scalar_map m;
    for (const auto& [name, v] : j.items()) m.assign(name, decode(v));
    return octave_value(m);
  }
  // an array: empty, a vector (a column), or rows (a matrix)
  if (j.empty()) return octave_value(ColumnVector(0));
  if (j.front().is_array()) {
    const octave_idx_type rows = j.size(), cols = j.front().size();
    Matrix m(rows, cols);
    for (octave_idx_type r = 0; r < rows; ++r) {
      const json& row = j[r];
      if (!row.is_array() || static_cast<octave_idx_type>(row.size()) != cols)
        throw std::runtime_error("a matrix argument whose rows differ in length");
      for (octave_idx_type c = 0; c < cols; ++c) m(r, c) = number_in(row[c]);
    }
    return octave_value(m);
  }
  ColumnVector v(j.size());
  for (octave_idx_type k = 0; k < v.numel(); ++k) v(k) = number_in(j[k]);
  return octave_value(v);
}

octave_value decode_kind(const std::string& kind, const json& j) {
  if (!is_pair(kind)) return decode(j);
  if (!j.is_array() || j.size() != 2) throw std::runtime_error("a pair argument that is not [a, b]");
  Cell pair(1, 2);
  pair(0) = decode(j[0]);
  pair(1) = decode(j[1]);
  return octave_value(pair);
}

// ---- results: Octave values -> JSON text, as the script server's gm_encode writes them ----------

void put_number(std::string& out, double x) {
  out += '"';
  if (std::isnan(x))
    out += "NaN";  // as Octave's sprintf('%.17g') spells them
  else if (std::isinf(x))
    out += x > 0 ? "Inf" : "-Inf";
  else {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);  // shortest text that reads back exactly
    out.append(buf, r.ptr);
  }
  out += '"';
}

NDArray real_array(const octave_value& x) {
  if (!(x.isnumeric() || x.islogical()))
    throw std::runtime_error("expected numbers, got a value of class " + x.class_name());
  if (x.iscomplex()) throw std::runtime_error("a complex number where a real was expected");
  return x.array_value();
}

void put_vector(std::string& out, const octave_value& x) {
  const NDArray a = real_array(x);
  if (a.isempty()) {
    out += "[]";
    return;
  }
  out += '[';
  for (octave_idx_type k = 0; k < a.numel(); ++k) {
    if (k) out += ',';
    put_number(out, a(k));
  }
  out += ']';
}

void put_matrix(std::string& out, const octave_value& x) {
  const NDArray a = real_array(x);
  if (a.ndims() > 2)
    throw std::runtime_error("expected a matrix, got an array of " + std::to_string(a.ndims()) + " dimensions");
  const octave_idx_type rows = a.rows(), cols = a.columns();
  if (rows == 0 || cols == 0) {
    out += "[]";
    return;
  }
  out += '[';
  for (octave_idx_type r = 0; r < rows; ++r) {
    out += r ? ",[" : "[";
    for (octave_idx_type c = 0; c < cols; ++c) {
      if (c) out += ',';
      put_number(out, a(r, c));
    }
    out += ']';
  }
  out += ']';
}

octave_value field_of(const octave_value& x, const char* name, const char* kind) {
  const octave_scalar_map m = x.scalar_map_value();
  if (!m.isfield(name)) throw std::runtime_error(std::string("a ") + kind + " without the field " + name);
  return m.getfield(name);
}

void put(std::string& out, const std::string& kind, const octave_value& x) {
  if (kind == "T") {
    if (x.numel() != 1) {
      const dim_vector d = x.dims();
      throw std::runtime_error("expected a scalar, got a " + std::to_string(d(0)) + "x" + std::to_string(d(1)) +
                               " array");
    }
    put_number(out, real_array(x)(0));
  } else if (kind == "Vec3" || kind == "Vec6" || kind == "VecX") {
    put_vector(out, x);
  } else if (kind == "Mat3" || kind == "MatX") {
    put_matrix(out, x);
  } else if (is_pair(kind)) {
    if (!x.iscell() || x.numel() != 2) throw std::runtime_error("expected a pair as a cell {a, b}");
    const Cell c = x.cell_value();
    const std::string part = kind == "Vec3Pair" ? "Vec3" : "MatX";
    out += '[';
    put(out, part, c(0));
    out += ',';
    put(out, part, c(1));
    out += ']';
  } else if (kind == "RigidBodyState" || kind == "ManakovState") {
    const char* body = kind == "RigidBodyState" ? "Pi" : "M";
    octave_value b, o;
    if (x.iscell() && x.numel() == 2) {
      const Cell c = x.cell_value();
      b = c(0);
      o = c(1);
    } else if (x.isstruct() && x.numel() == 1) {
      b = field_of(x, body, "state");
      o = field_of(x, "O", "state");
    } else {
      throw std::runtime_error(std::string("expected a state as a struct with fields ") + body + " and O, or a cell {" +
                               body + ", O}");
    }
    out += "{\"";
    out += body;
    out += "\":";
    if (kind == "RigidBodyState")
      put_vector(out, b);
    else
      put_matrix(out, b);
    out += ",\"O\":";
    put_matrix(out, o);
    out += '}';
  } else {
    throw std::runtime_error("unknown result kind " + kind);
  }
}

// A rigid-body state in its declared form (docs/PROTOCOL.md, "State forms"): the keys `a` (O or q)
// and `w` (Pi, Omega, omega or pi), from a struct with those fields or a cell {attitude, angular}.
void put_declared(std::string& out, const std::string& a, const std::string& w, const octave_value& x) {
  octave_value av, wv;
  if (x.iscell() && x.numel() == 2) {
    const Cell c = x.cell_value();
    av = c(0);
    wv = c(1);
  } else if (x.isstruct() && x.numel() == 1) {
    av = field_of(x, a.c_str(), "state");
    wv = field_of(x, w.c_str(), "state");
  } else {
    throw std::runtime_error("expected a state as a struct with fields " + a + " and " + w + ", or a cell {" + a +
                             ", " + w + "}");
  }
  out += "{\"" + a + "\":";
  if (a == "O")
    put_matrix(out, av);
  else
    put_vector(out, av);
  out += ",\"" + w + "\":";
  put_vector(out, wv);
  out += '}';
}

// ---- the server ----------------------------------------------------------------------------------

struct Integrator {
  std::string name;
  std::map<std::string, octave_value> steps;  // step slot -> function handle
  std::string state_a, state_w;               // a rigid_body_step kept in a declared form: its keys
};

struct Server {
  octave::interpreter* interp = nullptr;
  int out = 3;
  std::string target;
  // What was sourced: each copy's file, the name it stands for (the student's file, or a notebook
  // cell: "week3.ipynb, cell 4, In [3]") and the lines added at its top.
  struct Source {
    std::string file, name;
    int added = 0;
  };
  std::vector<Source> sources;
  std::map<std::string, Kinds> slot_kinds, step_kinds;
  std::vector<Integrator> integrators;
  std::string buffer;  // what stdin gave beyond the last line read

  void send(std::string line) {
    line += '\n';
    const char* p = line.data();
    std::size_t left = line.size();
    while (left) {
      const ssize_t n = ::write(out, p, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        std::_Exit(3);  // the harness is gone
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
  }

  // The next line of stdin without its '\n'; false at the end of input.
  bool next_line(std::string& line) {
    for (;;) {
      const auto nl = buffer.find('\n');
      if (nl != std::string::npos) {
        line.assign(buffer, 0, nl);
        buffer.erase(0, nl + 1);
        return true;
      }
      char chunk[1 << 16];
      const ssize_t n = ::read(0, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        if (buffer.empty()) return false;
        line.swap(buffer);
        buffer.clear();
        return true;
      }
      buffer.append(chunk, static_cast<std::size_t>(n));
    }
  }

  // The traceback of an Octave error as the script server writes it: the message, then one
  // "    at NAME, line L (FILE)" per frame, the sourced copy's lines named in the student's file.
  std::string traceback(const octave::execution_exception& e) const {
    std::string tb = e.message();
    for (const auto& s : sources)  // a parse error names the copy
      for (std::size_t at = tb.find(s.file); at != std::string::npos; at = tb.find(s.file, at + s.name.size()))
        tb.replace(at, s.file.size(), s.name);
    for (const auto& f : e.stack_info()) {
      std::string file = f.file_name(), name = f.fcn_name();
      int line = f.line();
      for (const auto& s : sources)
        if (file == s.file) {
          // The copy's own code, outside any function: its frame is named after the copy.
          const std::string stem = file.substr(file.rfind('/') + 1, file.size() - file.rfind('/') - 3);
          if (name == file || name == stem) name.clear();
          file = s.name;
          line -= s.added;
        }
      tb += "\n    at " + (name.empty() ? std::string() : name + ", ") + "line " + std::to_string(line) + " (" + file +
            ")";
    }
    return tb;
  }

  // A copy of `code` in /tmp, sourced as a script, standing for `name` in messages; `added` lines at
  // its top. Throws octave::execution_exception for an error in it (a parse error with its line).
  void source_copy(const std::string& code, const std::string& name, int added) {
    char path[] = "/tmp/geomech_octave_XXXXXX.m";
    const int fd = ::mkstemps(path, 2);
    if (fd < 0) throw std::runtime_error("cannot write a temporary copy in /tmp");
    sources.push_back(Source{path, name, added});
    const bool written = ::write(fd, code.data(), code.size()) == static_cast<ssize_t>(code.size());
    ::close(fd);
    if (!written) throw std::runtime_error("cannot write a temporary copy in /tmp");
    struct Unlink {
      const char* p;
      ~Unlink() { ::unlink(p); }
    } unlink_it{path};
    if (name != target)  // a notebook cell: a syntax error's line, which sourcing does not say
      interp->feval("__parse_file__", octave_value_list(octave_value(std::string(path))), 0);
    interp->source_file(path);
  }

  octave_value call_one(const octave_value& f, const std::string& name, const octave_value_list& args) {
    const octave_value_list r = f.is_defined() ? interp->feval(f, args, 1) : interp->feval(name, args, 1);
    if (r.length() < 1 || r(0).is_undefined()) throw std::runtime_error(name + " returned no value");
    return r(0);
  }

  // One call of a request: its result as ',{"ok":...}' or ',{"error":...,"traceback":...}'.
  void answer_call(const json& call, std::string& out) {
    const std::size_t mark = out.size();
    try {
      const std::string& slot = call.at("slot").get_ref<const std::string&>();
      const bool stepping = call.contains("integrator") && call["integrator"].is_string() &&
                            !call["integrator"].get_ref<const std::string&>().empty();
      const auto& table = stepping ? step_kinds : slot_kinds;
      const auto kinds_it = table.find(slot);
      if (kinds_it == table.end()) throw std::runtime_error("no slot " + slot + " in the slot table");
      const Kinds& kinds = kinds_it->second;
      const json& a = call.at("args");
      octave_value_list args;
      for (std::size_t k = 0; k < a.size(); ++k)
        args(k) = decode_kind(k < kinds.args.size() ? kinds.args[k] : std::string(), a[k]);
      octave_value f;
      const Integrator* which = nullptr;
      // The result as its kind says, or a rigid-body state in the integrator's declared form.
      auto write = [&](std::string& o, const octave_value& v) {
        if (which && !which->state_a.empty() && slot == "rigid_body_step")
          put_declared(o, which->state_a, which->state_w, v);
        else
          put(o, kinds.result, v);
      };
      if (stepping) {
        const std::string& name = call["integrator"].get_ref<const std::string&>();
        for (const auto& i : integrators)
          if (i.name == name)
            if (auto s = i.steps.find(slot); s != i.steps.end()) f = s->second, which = &i;
        if (f.is_undefined()) throw std::runtime_error("no integrator " + name + " with a " + slot);
        if (call.contains("repeat")) {
          // A run of steps (docs/PROTOCOL.md): each step's state, written as its reply would be, is
          // read back as the next step's argument, as if the harness had made the calls one by one.
          const json& n = call["repeat"];
          if (!n.is_number() || n.get<double>() < 1 || a.size() != 3)
            throw std::runtime_error(
                "\"repeat\" needs an integrator's step, its three arguments and a count of at least 1");
          out += ",{\"ok\":[";
          const long count = n.get<long>();
          for (long s = 0; s < count; ++s) {
            std::string state;
            write(state, call_one(f, slot, args));
            args(1) = decode_kind(kinds.args[1], json::parse(state));
            if (s) out += ',';
            out += state;
          }
          out += "]}";
          return;
        }
      }
      const octave_value r = call_one(f, slot, args);
      out += ",{\"ok\":";
      write(out, r);
      out += '}';
    } catch (const octave::execution_exception& e) {
      interp->recover_from_exception();
      out.resize(mark);
      out += ",{\"error\":" + json(e.message()).dump() + ",\"traceback\":" + json(traceback(e)).dump() + "}";
    } catch (const octave::exit_exception& e) {
      throw;
    } catch (const std::exception& e) {
      out.resize(mark);
      out += ",{\"error\":" + json(e.what()).dump() + ",\"traceback\":" + json(e.what()).dump() + "}";
    }
  }

  std::string answer(const json& req) {
    std::string results;
    for (const auto& call : req.at("calls")) answer_call(call, results);
    std::string reply = "{\"id\":" + req.at("id").dump() + ",\"results\":[";
    if (!results.empty()) reply.append(results, 1, std::string::npos);  // each result begins with its comma
    reply += "]}";
    return reply;
  }

  // $GEOMECH_PROFILE=dir: the session's time by function (Octave's profiler), as the script server
  // writes it to dir/session-PID.txt, most costly first.
  void write_profile(const std::string& where) {
    interp->feval("profile", octave_value_list(octave_value("off")), 0);
    const octave_value info = interp->feval("profile", octave_value_list(octave_value("info")), 1)(0);
    const octave_map t = info.scalar_map_value().getfield("FunctionTable").map_value();
    struct Row {
      double seconds;
      double calls;
      std::string name;
    };
    std::vector<Row> rows;
    const Cell total = t.contents("TotalTime"), calls = t.contents("NumCalls"), names = t.contents("FunctionName");
    for (octave_idx_type k = 0; k < t.numel(); ++k)
      rows.push_back({total(k).double_value(), calls(k).double_value(), names(k).string_value()});
    std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.seconds > b.seconds; });
    std::ofstream f(where + "/session-" + std::to_string(::getpid()) + ".txt");
    char line[512];
    std::snprintf(line, sizeof line, "%10s %9s  %s\n", "seconds", "calls", "function");
    f << line;
    for (const auto& r : rows) {
      std::snprintf(line, sizeof line, "%10.3f %9d  %s\n", r.seconds, static_cast<int>(r.calls), r.name.c_str());
      f << line;
    }
  }

  // Answers requests until the input ends (0) or, in a session, until {"session": "end"} (1).
  int serve(bool in_session) {
    std::string line;
    while (next_line(line)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // the empty line after each request
      json req;
      try {
        req = json::parse(line);
      } catch (const std::exception& e) {
        send("{\"id\":null,\"fatal\":" + json(std::string("not a request: ") + e.what()).dump() + "}");
        std::_Exit(2);
      }
      if (req.contains("session")) {
        const std::string what = req["session"].is_string() ? req["session"].get<std::string>() : "";
        const std::string id = req.value("id", json()).dump();
        if (what == "end" && in_session) {
          send("{\"id\":" + id + ",\"session\":\"ended\"}");
          return 1;
        }
        if (what == "begin" && !in_session) {
          std::fflush(nullptr);
          const pid_t pid = ::fork();
          if (pid == 0) {
            send("{\"id\":" + id + ",\"session\":\"begun\",\"pid\":" + std::to_string(::getpid()) + "}");
            const char* where = std::getenv("GEOMECH_PROFILE");
            if (where && *where) interp->feval("profile", octave_value_list(octave_value("on")), 0);
            try {
              serve(true);
            } catch (const octave::exit_exception& e) {
              std::fflush(nullptr);
              std::_Exit(e.exit_status());  // the student's exit(): the server reports it below
            }
            if (where && *where) write_profile(where);
            std::fflush(nullptr);
            std::_Exit(
                77);  // ended by request or at the end of input; 77, so that the student's exit(0) is not taken for it
          }
          buffer.clear();  // the copy read what followed the request; it is not this process's to answer
          int status = 0;
          if (pid < 0 || ::waitpid(pid, &status, 0) < 0) {
            send("{\"id\":null,\"died\":" + json(std::string("could not be started (fork failed)")).dump() + "}");
            continue;
          }
          if (!(WIFEXITED(status) && WEXITSTATUS(status) == 77)) {
            const std::string how = WIFSIGNALED(status) ? "was killed by signal " + std::to_string(WTERMSIG(status))
                                                        : "exited with status " + std::to_string(WEXITSTATUS(status)) +
                                                              " (exit() called in the implementation?)";
            send("{\"id\":null,\"died\":" + json(how).dump() + "}");
          }
          continue;
        }
        send("{\"id\":" + id + ",\"fatal\":\"unexpected session request\"}");
        continue;
      }
      send(answer(req));
    }
    return 0;
  }

  // exist(name) is 103 for a command-line function (a sourced file's), 2 for a file on the path.
  bool defined_here(const std::string& name, bool folder) {
    const double e = interp->feval("exist", octave_value_list(octave_value(name)), 1)(0).double_value();
    return e == 103 || (folder && e == 2);
  }

  std::string handshake_fatal(const std::string& why) const {
    return "{\"protocol\":\"geomech-slots\",\"version\":2,\"language\":\"octave\",\"fatal\":" + json(why).dump() + "}";
  }

  std::string jsonencode(const octave_value& v) {
    return interp->feval("jsonencode", octave_value_list(v), 1)(0).string_value();
  }

  // Loads the implementation and writes the handshake; false (after a fatal handshake) when it fails.
  bool start(std::vector<std::string>& slot_names) {
    bool folder = false;
    try {
      struct stat st {};
      folder = ::stat(target.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
      if (folder) {
        interp->feval("addpath", octave_value_list(octave_value(target)), 0);
      } else {
        std::ifstream in(target);
        if (!in) throw std::runtime_error("cannot read it");
        std::ostringstream text;
        text << in.rdbuf();
        if (target.size() > 5 && target.compare(target.size() - 5, 5, ".json") == 0) {
          // A notebook's code cells (docs/PROTOCOL.md, "Notebooks"), run in order as its kernel runs
          // them, each from a copy of its own: a frame in it, or a parse error, names the cell. Its
          // functions' names differ from the copy's, which is not worth a warning.
          const json nb = json::parse(text.str());
          if (nb.contains("folder") && !nb["folder"].get<std::string>().empty())
            interp->feval("addpath", octave_value_list(octave_value(nb["folder"].get<std::string>())), 0);
          interp->feval("warning", ovl(octave_value("off"), octave_value("Octave:function-name-clash")), 0);
          for (const auto& cell : nb.at("cells")) {
            const std::string name = cell.at("name").get<std::string>();
            try {
              // Sourced as a script: "1;" first, so that a cell that begins with a function defines
              // them all; on the cell's first line, so that its lines keep their numbers (but after
              // a block comment's %{, which must stand alone on its line).
              const std::string code = cell.at("code").get<std::string>();
              const std::size_t first = code.find_first_not_of(" \t");
              const bool block = first != std::string::npos &&
                                 (code.compare(first, 2, "%{") == 0 || code.compare(first, 2, "#{") == 0);
              source_copy((block ? "1;\n" : "1; ") + code, name, block ? 1 : 0);
            } catch (const octave::execution_exception& e) {
              interp->recover_from_exception();
              send(handshake_fatal(name + " failed when run (the cells before it ran): " + traceback(e)));
              return false;
            }
          }
        } else {
          // Sourced as a script: "1;" first, so that a file that begins with a function defines them all.
          source_copy("1;\n" + text.str() + "\n", target, 1);
        }
      }
    } catch (const octave::execution_exception& e) {
      send(handshake_fatal("loading " + target + " failed: " + e.message()));
      return false;
    } catch (const std::exception& e) {
      send(handshake_fatal("loading " + target + " failed: " + e.what()));
      return false;
    }
    std::string have, ijson, desc = "an Octave implementation";
    try {
      for (const auto& n : slot_names)
        if (defined_here(n, folder)) have += (have.empty() ? "\"" : ",\"") + n + "\"";
      // Integrators: geomech_integrators() returns a struct array with fields name, claims (a struct)
      // and function handles rigid_body_step / manakov_step / clebsch_step / manakov_clebsch_step.
      if (defined_here("geomech_integrators", true)) {
        const octave_map list = interp->feval("geomech_integrators", octave_value_list(), 1)(0).map_value();
        for (octave_idx_type k = 0; k < list.numel(); ++k) {
          const octave_scalar_map it = list.checkelem(k);
          Integrator in;
          in.name = it.getfield("name").string_value();
          std::string steps;
          for (const auto& [step, kinds] : step_kinds) {
            (void)kinds;
            if (!it.isfield(step)) continue;
            const octave_value h = it.getfield(step);
            if (h.isempty()) continue;
            in.steps[step] = h;
            steps += (steps.empty() ? "\"" : ",\"") + step + "\"";
          }
          std::string claims = "{}";
          if (it.isfield("claims") && !it.getfield("claims").isempty()) claims = jsonencode(it.getfield("claims"));
          // A declared state form ('quaternion_wxyz omega') and a stated precision with its reason.
          std::string extra;
          for (const char* key : {"state", "precision", "precision_reason"})
            if (it.isfield(key) && it.getfield(key).is_string() && !it.getfield(key).isempty())
              extra += std::string(",\"") + key + "\":" + json(it.getfield(key).string_value()).dump();
          if (it.isfield("state") && it.getfield("state").is_string() && !it.getfield("state").isempty()) {
            std::string words = it.getfield("state").string_value();
            std::replace(words.begin(), words.end(), ',', ' ');
            std::istringstream ws(words);
            std::string att, ang;
            if (ws >> att >> ang) in.state_a = att == "matrix" ? "O" : "q", in.state_w = ang;
          }
          std::string domain = "{}";  // where the step is meant to work
          if (it.isfield("domain") && !it.getfield("domain").isempty()) domain = jsonencode(it.getfield("domain"));
          ijson += std::string(ijson.empty() ? "" : ",") + "{\"name\":" + json(in.name).dump() + ",\"steps\":[" +
                   steps + "],\"scalars\":[\"double\"],\"claims\":" + claims + ",\"domain\":" + domain + extra + "}";
          integrators.push_back(std::move(in));
        }
      }
      if (defined_here("geomech_description", true))
        desc = interp->feval("geomech_description", octave_value_list(), 1)(0).string_value();
    } catch (const octave::execution_exception& e) {
      send(handshake_fatal("reading " + target + " failed: " + traceback(e)));
      return false;
    }
    send("{\"protocol\":\"geomech-slots\",\"version\":2,\"language\":\"octave\",\"language_version\":" +
         json(std::string(OCTAVE_VERSION)).dump() +
         ",\"interpreter\":\"geomech-octave-server (the system's Octave linked in)\",\"description\":" +
         json(desc).dump() + ",\"slots\":{\"double\":[" + have + "]},\"integrators\":[" + ijson +
         "],\"notes\":{},\"warnings\":[],\"sessions\":true,\"repeat\":true}");
    return true;
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: geomech-octave-server FILE.m | FOLDER (started by geomech check)\n");
    return 2;
  }
  Server s;
  s.target = argv[argc - 1];
  if (const char* fd = std::getenv("GEOMECH_REPLY_FD"); fd && *fd)
    s.out = std::atoi(fd);
  else
    s.out = 1;
  std::vector<std::string> slot_names;
  try {
    const char* table_text = std::getenv("GEOMECH_SLOT_TABLE");
    if (!table_text) throw std::runtime_error("$GEOMECH_SLOT_TABLE is not set (the harness sets it)");
    const json table = json::parse(table_text);
    for (const auto& slot : table.at("slots")) {
      slot_names.push_back(slot.at("name").get<std::string>());
      s.slot_kinds[slot_names.back()] = kinds_of(slot.at("signature").get<std::string>());
    }
    for (const auto& [step, signature] : table.at("steps").items())
      s.step_kinds[step] = kinds_of(signature.get<std::string>());
  } catch (const std::exception& e) {
    s.send(s.handshake_fatal(std::string("the slot table: ") + e.what()));
    return 1;
  }
  octave::interpreter interp;
  interp.initialize_history(false);
  interp.initialize();
  if (interp.execute() != 0) {
    s.send(s.handshake_fatal("Octave's interpreter did not start"));
    return 1;
  }
  s.interp = &interp;
  try {
    if (!s.start(slot_names)) std::_Exit(1);
    s.serve(false);
  } catch (const octave::exit_exception& e) {
    std::fflush(nullptr);
    std::_Exit(e.exit_status());
  }
  std::fflush(nullptr);
  std::_Exit(0);  // not the interpreter's teardown: nothing is left to do
}
