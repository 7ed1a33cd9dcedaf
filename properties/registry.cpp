#include "properties/registry.hpp"

#include <algorithm>
#include <stdexcept>

namespace gm {

const char* tolerance_name(ToleranceClass t) {
  switch (t) {
    case ToleranceClass::Exact:
      return "exact";
    case ToleranceClass::Roundoff:
      return "roundoff";
    case ToleranceClass::Truncation:
      return "truncation";
  }
  return "?";
}

bool Property::runs_in(ScalarKind k) const {
  switch (k) {
    case ScalarKind::Double:
      return static_cast<bool>(d) || static_cast<bool>(int_d);
    case ScalarKind::MP50:
      return static_cast<bool>(mp) || static_cast<bool>(int_mp);
    case ScalarKind::Exact:
      return static_cast<bool>(q);
  }
  return false;
}

static std::vector<Property>& mutable_registry() {
  static std::vector<Property> r;
  return r;
}

std::string source_in_tree(std::string_view path) {
  // The last folder named properties: a checkout may itself lie in a folder of that name.
  for (std::size_t at = path.rfind("properties/"); at != std::string_view::npos;
       at = at == 0 ? std::string_view::npos : path.rfind("properties/", at - 1))
    if (at == 0 || path[at - 1] == '/') return std::string(path.substr(at));
  return std::string(path);
}

PropertyDef registered_as(PropertyDef def, std::string_view fn, std::string_view path) {
  if (!def.id.empty())
    throw std::logic_error("GM_PROPERTY(" + std::string(fn) + ", ...) in " + std::string(path) + " spells its id (\"" +
                           def.id + "\"): a property's id is its function's name, set by GM_PROPERTY; leave .id out");
  def.id = std::string(fn);
  def.file = source_in_tree(path);
  return def;
}

void register_property(Property p) {
  auto& r = mutable_registry();
  for (const auto& q : r)
    if (q.id == p.id) throw std::logic_error("property id registered twice: " + p.id);
  auto pos =
      std::lower_bound(r.begin(), r.end(), p.id, [](const Property& a, const std::string& id) { return a.id < id; });
  r.insert(pos, std::move(p));
}

const std::vector<Property>& properties() { return mutable_registry(); }

const Property* find_property(std::string_view id) {
  for (const auto& p : properties())
    if (p.id == id) return &p;
  return nullptr;
}

const char* step_name(StepKind k) {
  switch (k) {
    case StepKind::RigidBody:
      return "rigid_body_step";
    case StepKind::RigidBodyMatrix:
      return "rigid_body_step keeping its attitude as a matrix";
    case StepKind::RigidBodyQuaternion:
      return "rigid_body_step keeping its attitude as a quaternion";
    case StepKind::Manakov:
      return "manakov_step";
    case StepKind::Clebsch:
      return "clebsch_step";
    case StepKind::ManakovClebsch:
      return "manakov_clebsch_step";
    case StepKind::None:
      break;
  }
  return "step";
}

}  // namespace gm
