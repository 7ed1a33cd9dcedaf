// The fixture set: which golden trajectories exist, with their exact parameters, initial data
// and sample times. Add a fixture here, run `./geomech golden regenerate`, commit the new file.
#pragma once

#include "golden/generate.hpp"

#include <string>
#include <vector>

namespace gm::golden {

struct FixtureDefinition {
  std::string name;
  std::string title;
  std::string system;
  std::vector<NamedValues> parameters;
  std::vector<NamedValues> initial;
  std::vector<std::string> times;  // finite decimals
  int digits = kDefaultDigits;
};

const std::vector<FixtureDefinition>& fixture_definitions();
const FixtureDefinition* find_definition(std::string_view name);

// Validates the definition (InputError naming the fixture) and builds its request.
Request make_request(const FixtureDefinition& d);

// The directory of the committed fixtures (the source tree's golden/fixtures) and a file in it.
std::string default_fixture_dir();
std::string fixture_path(const std::string& dir, const std::string& name);

// The rotation (Id - S)^-1 (Id + S) for the skew S whose upper triangle (row-major) is `upper`:
// an exactly orthogonal rational matrix with det +1 (the Cayley transform), row-major.
std::vector<Rational> cayley_rotation(int n, const std::vector<Rational>& upper);

}  // namespace gm::golden
