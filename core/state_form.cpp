#include "core/state_form.hpp"

#include <vector>

namespace gm {

namespace {

constexpr const char* kAttitudeWords[] = {"matrix", "quaternion_wxyz", "quaternion_xyzw"};
constexpr const char* kAngularWords[] = {"Pi", "Omega", "omega", "pi"};

std::vector<std::string_view> words_of(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == ',' || text[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != ',' && text[j] != '\t') ++j;
    if (j > i) out.push_back(text.substr(i, j - i));
    i = j;
  }
  return out;
}

const std::string kWordList =
    "the attitude is one of matrix, quaternion_wxyz, quaternion_xyzw; the angular state one of Pi (body momentum), "
    "Omega (body angular velocity), omega (spatial angular velocity), pi (spatial momentum); e.g. "
    "\"quaternion_wxyz omega\"";

}  // namespace

StateForm parse_state_form(std::string_view text) {
  const auto w = words_of(text);
  if (w.size() != 2)
    throw std::invalid_argument("a state form is two words, the attitude and the angular state, not '" +
                                std::string(text) + "': " + kWordList);
  StateForm f;
  bool attitude = false, angular = false;
  for (int k = 0; k < 3; ++k)
    if (w[0] == kAttitudeWords[k]) f.attitude = static_cast<Attitude>(k), attitude = true;
  for (int k = 0; k < 4; ++k)
    if (w[1] == kAngularWords[k]) f.angular = static_cast<Angular>(k), angular = true;
  if (!attitude)
    throw std::invalid_argument("'" + std::string(w[0]) + "' is not an attitude of a state form: " + kWordList);
  if (!angular)
    throw std::invalid_argument("'" + std::string(w[1]) + "' is not an angular state of a state form: " + kWordList);
  return f;
}

std::string state_form_words(const StateForm& f) {
  return std::string(kAttitudeWords[static_cast<int>(f.attitude)]) + " " + kAngularWords[static_cast<int>(f.angular)];
}

const char* attitude_key(Attitude a) { return a == Attitude::matrix ? "O" : "q"; }
const char* angular_key(Angular a) { return kAngularWords[static_cast<int>(a)]; }

namespace {

const char* attitude_text(Attitude a) {
  switch (a) {
    case Attitude::quaternion_wxyz:
      return "a unit quaternion q = (w, x, y, z)";
    case Attitude::quaternion_xyzw:
      return "a unit quaternion q = (x, y, z, w)";
    case Attitude::matrix:
      break;
  }
  return "a rotation matrix O";
}

const char* angular_text(Angular a) {
  switch (a) {
    case Angular::Omega:
      return "the body angular velocity Omega";
    case Angular::omega:
      return "the spatial angular velocity omega";
    case Angular::pi:
      return "the spatial angular momentum pi";
    case Angular::Pi:
      break;
  }
  return "the body angular momentum Pi";
}

}  // namespace

std::string describe_state_form(const StateForm& f) {
  return std::string(attitude_text(f.attitude)) + " and " + angular_text(f.angular);
}

std::string your_attitude(const StateForm& f) {
  switch (f.attitude) {
    case Attitude::quaternion_wxyz:
      return "your quaternion q = (w, x, y, z)";
    case Attitude::quaternion_xyzw:
      return "your quaternion q = (x, y, z, w)";
    case Attitude::matrix:
      break;
  }
  return "your O";
}

std::string your_angular(const StateForm& f) {
  switch (f.angular) {
    case Angular::Omega:
      return "your Omega (the body angular velocity)";
    case Angular::omega:
      return "your omega (the spatial angular velocity)";
    case Angular::pi:
      return "your pi (the spatial angular momentum)";
    case Angular::Pi:
      break;
  }
  return "your Pi";
}

std::string state_form_conversion(const StateForm& f) {
  const bool q = f.has_quaternion();
  std::string O = q ? "O = R(q / |q|)" : "O = your O";
  const std::string inv = q ? "O^T" : "O^-1";
  switch (f.angular) {
    case Angular::Omega:
      return O + ", Pi = I Omega";
    case Angular::omega:
      return O + ", Pi = I " + inv + " omega";
    case Angular::pi:
      return O + ", Pi = " + inv + " pi";
    case Angular::Pi:
      break;
  }
  return O + ", Pi = your Pi";
}

int& quaternion_sign_given() {
  thread_local int sign = 1;
  return sign;
}

}  // namespace gm
