#include "golden/arguments.hpp"

#include <cctype>

namespace gm::golden {

namespace {

std::vector<std::string> split_values(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ',' || c == ' ' || c == '\t') {
      if (!cur.empty()) out.push_back(cur), cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

}  // namespace

NamedValues parse_block_argument(const std::string& option, const std::string& text) {
  const std::string where = option + " " + text;
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw InputError(where, 0, "expected NAME=v1,v2,... (e.g. I=2,1,2/3)");
  NamedValues nv;
  nv.name = text.substr(0, eq);
  nv.where = where;
  bool ident = !nv.name.empty() && nv.name.size() <= 16 && std::isalpha(static_cast<unsigned char>(nv.name[0]));
  for (char c : nv.name) ident = ident && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ident) throw InputError(where, 0, "'" + nv.name + "' is not a name (a letter, then letters, digits or _)");
  const auto values = split_values(text.substr(eq + 1));
  if (values.empty()) throw InputError(where, 0, "no values after '='");
  if (values.size() > 81) throw InputError(where, 0, "more than 81 values");
  for (std::size_t i = 0; i < values.size(); ++i) {
    try {
      nv.values.push_back(parse_exact(values[i]));
    } catch (const std::invalid_argument& e) {
      throw InputError(where, 0, "value " + std::to_string(i + 1) + ": " + e.what());
    }
  }
  return nv;
}

std::vector<Rational> parse_times_argument(const std::string& text) {
  const std::string where = "--times " + text;
  std::vector<Rational> times;
  auto number = [&](const std::string& s, const char* what) {
    try {
      return parse_decimal(s);
    } catch (const std::invalid_argument& e) {
      throw InputError(where, 0, std::string(what) + ": " + e.what());
    }
  };
  if (text.find(':') != std::string::npos) {
    std::vector<std::string> parts;
    std::size_t b = 0;
    while (true) {
      const auto c = text.find(':', b);
      parts.push_back(text.substr(b, c == std::string::npos ? std::string::npos : c - b));
      if (c == std::string::npos) break;
      b = c + 1;
    }
    if (parts.size() != 3) throw InputError(where, 0, "expected start:step:stop, e.g. 0:0.5:20");
    const Rational start = number(parts[0], "start"), step = number(parts[1], "step"), stop = number(parts[2], "stop");
    if (step <= 0) throw InputError(where, 0, "the step must be positive");
    if (stop < start) throw InputError(where, 0, "stop is before start");
    if ((stop - start) / step > Rational(static_cast<long long>(kMaxSamples)))
      throw InputError(where, 0, "more than " + std::to_string(kMaxSamples) + " sample times");
    for (Rational t = start; t <= stop; t += step) times.push_back(t);
  } else {
    const auto values = split_values(text);
    if (values.size() > kMaxSamples)
      throw InputError(where, 0, "more than " + std::to_string(kMaxSamples) + " sample times");
    for (std::size_t i = 0; i < values.size(); ++i)
      times.push_back(number(values[i], ("time " + std::to_string(i + 1)).c_str()));
  }
  validate_times(times, where);
  return times;
}

void validate_times(const std::vector<Rational>& times, const std::string& where) {
  if (times.empty()) throw InputError(where, 0, "no sample times");
  if (times.size() > kMaxSamples)
    throw InputError(where, 0, std::to_string(times.size()) + " sample times; at most " + std::to_string(kMaxSamples));
  for (std::size_t i = 0; i < times.size(); ++i) {
    const Rational& t = times[i];
    if (!is_finite_decimal(t)) throw InputError(where, 0, "time " + format_exact(t) + " is not a finite decimal");
    if (t < 0) throw InputError(where, 0, "time " + format_exact(t) + " is negative (trajectories start at t = 0)");
    if (t > kMaxRequestTime)
      throw InputError(where, 0, "time " + format_exact(t) + " is beyond " + std::to_string(kMaxRequestTime));
    if (i > 0 && !(t > times[i - 1]))
      throw InputError(where, 0,
                       "sample times must increase: " + format_exact(t) + " after " + format_exact(times[i - 1]));
  }
}

}  // namespace gm::golden
