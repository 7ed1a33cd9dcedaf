// The spec catalogue (spec/catalogue.json): what the notes claim, one entry per statement.
// Loading validates the file; traceability() cross-checks it against the property registry;
// markdown() renders the entry -> properties -> status table (spec/CATALOGUE.md).
#pragma once

#include "properties/registry.hpp"

#include <optional>
#include <string>
#include <vector>

namespace gm {

struct Erratum {
  std::string literal;          // the statement as printed
  std::string corrected;        // what holds
  std::string property;         // property that checks the corrected statement
  std::string literal_variant;  // subject variant implementing the literal statement: must fail `property`
};

struct SpecEntry {
  std::string id;
  std::string section;
  std::string place;
  int line = 0;
  std::string anchor;
  std::string kind;    // algebraic | dynamic | variational
  std::string status;  // checked | pending | erratum
  std::optional<int> issue;
  std::string statement;
  std::string note;
  std::optional<Erratum> erratum;
};

struct Catalogue {
  std::string path;
  std::string source;  // the notes, relative to the catalogue's directory
  std::vector<SpecEntry> entries;

  const SpecEntry* find(std::string_view id) const;
};

// Throws std::runtime_error naming the file and the offending entry/field.
Catalogue load_catalogue(const std::string& path);

// The default catalogue path (the source tree's spec/catalogue.json), overridable with
// $GEOMECH_CATALOGUE.
std::string default_catalogue_path();

// Problems found when the catalogue, the notes and the registry are compared: an empty list
// means traceable. `mutant_names` are the negative controls that exist (tests/mutants), or
// nullptr to skip that check.
std::vector<std::string> traceability_problems(const Catalogue& c, const std::vector<Property>& props,
                                               const std::vector<std::string>* mutant_names);

// The generated Markdown table.
std::string catalogue_markdown(const Catalogue& c, const std::vector<Property>& props);

// Properties that name this entry.
std::vector<const Property*> properties_for(const std::string& spec_id, const std::vector<Property>& props);

}  // namespace gm
