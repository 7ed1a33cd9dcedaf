// The parts a student's translation units registered through GEOMECH_STUDENT (one per scalar),
// assembled into one subject. Shared by the check program (harness/program/student_parts.cpp) and the C++
// protocol server of untrusted mode (tools/student_server_main.cpp), which links nothing else of the
// harness.
#include "harness/program/student_registry.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace gm::student {

namespace {

Registered& mutable_registered() {
  static Registered r;
  return r;
}

// A piece of one scalar's compile (PartInfo::slot_pieces != 1) merged into the pieces before it:
// its slots (each piece fills others), its integrators (one piece has them all, in their order),
// and what it noted.
template <class T>
std::shared_ptr<const Subject<T>> merged(const Subject<T>& into, const Subject<T>& piece) {
  auto m = std::make_shared<Subject<T>>(into);
#define GM_MERGE_SLOT(name, sig, place, meaning) \
  if (piece.name) m->name = piece.name;
  GM_SUBJECT_SLOTS(GM_MERGE_SLOT)
#undef GM_MERGE_SLOT
  m->integrators.insert(m->integrators.end(), piece.integrators.begin(), piece.integrators.end());
  return m;
}

void merge_notes(PartInfo& into, const PartInfo& piece) {
  into.slot_notes.insert(piece.slot_notes.begin(), piece.slot_notes.end());
  for (const auto& w : piece.warnings)
    if (std::find(into.warnings.begin(), into.warnings.end(), w) == into.warnings.end()) into.warnings.push_back(w);
  into.unchecked.insert(into.unchecked.end(), piece.unchecked.begin(), piece.unchecked.end());
}

// The pieces of each scalar seen so far (slot_piece, slot_pieces).
std::set<std::pair<int, int>>& pieces_seen(const void* scalar_slot) {
  static std::map<const void*, std::set<std::pair<int, int>>> seen;
  return seen[scalar_slot];
}

template <class P>
void store(std::shared_ptr<const P>& slot, std::optional<PartInfo>& info_slot, std::shared_ptr<const P> s,
           PartInfo info) {
  const std::pair<int, int> piece{info.slot_piece, info.slot_pieces};
  if (slot) {
    if (info.slot_pieces != 1 && info_slot->slot_pieces != 1 && info.registration == info_slot->registration &&
        pieces_seen(&slot).insert(piece).second) {
      slot = merged(*slot, *s);
      merge_notes(*info_slot, info);
      return;
    }
    // Two registrations for one scalar: keep the first and say so (GEOMECH_STUDENT used twice).
    info_slot->warnings.push_back("GEOMECH_STUDENT(" + info.registration +
                                  ") is a second registration and was ignored; use the macro once");
    return;
  }
  pieces_seen(&slot).insert(piece);
  slot = std::move(s);
  info_slot = std::move(info);
}

template <class T>
bool fills_slots(const Subject<T>& s) {
  for (const auto& slot : subject_slots())
    if (s.provides(slot.name)) return true;
  return false;
}

template <class T>
bool fills_anything(const Subject<T>& s) {
  if constexpr (!is_exact_v<T>)
    if (!s.integrators.empty()) return true;
  return fills_slots(s);
}

std::string first_identifier(const std::string& registration) {
  std::string name;
  for (char c : registration) {
    if (c == ',' || c == ' ' || c == '<') break;
    name += c;
  }
  const auto colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

}  // namespace

void register_part(std::shared_ptr<const Subject<double>> s, PartInfo info) {
  store(mutable_registered().d, mutable_registered().d_info, std::move(s), std::move(info));
}
void register_part(std::shared_ptr<const Subject<Real50>> s, PartInfo info) {
  store(mutable_registered().mp, mutable_registered().mp_info, std::move(s), std::move(info));
}
void register_part(std::shared_ptr<const Subject<Rational>> s, PartInfo info) {
  store(mutable_registered().q, mutable_registered().q_info, std::move(s), std::move(info));
}

const Registered& registered() { return mutable_registered(); }

void apply_build_notes(harness::SubjectInfo& info, const nlohmann::json& notes) {
  if (!notes.is_object()) return;
  if (notes.contains("scalar_unavailable"))
    for (const auto& [scalar, why] : notes["scalar_unavailable"].items())
      info.scalar_unavailable[scalar] = why.get<std::string>();
  if (notes.contains("slot_notes"))
    for (const auto& [scalar, slots] : notes["slot_notes"].items())
      for (const auto& [slot, why] : slots.items()) info.slot_notes[scalar][slot] = why.get<std::string>();
  if (notes.contains("warnings"))
    for (const auto& w : notes["warnings"]) info.warnings.push_back(w.get<std::string>());
}

SubjectSet assemble(const std::string& name_in, harness::SubjectInfo& info, const nlohmann::json& notes) {
  const Registered& r = registered();
  SubjectSet s;
  const PartInfo* any = r.d_info ? &*r.d_info : r.mp_info ? &*r.mp_info : r.q_info ? &*r.q_info : nullptr;
  s.name = !name_in.empty() ? name_in : any ? first_identifier(any->registration) : "student";
  s.description = any && !any->description.empty() ? any->description
                  : any                            ? "GEOMECH_STUDENT(" + any->registration + ")"
                                                   : "no GEOMECH_STUDENT registration was found";
  if (!any)
    info.warnings.push_back(
        "the program registered no implementation: the source needs GEOMECH_STUDENT(YourStruct, ...) at namespace "
        "scope (see student/geomech/student.hpp)");
  if (any) s.claims = any->claims;

  apply_build_notes(info, notes);

  std::set<std::string> seen_warnings(info.warnings.begin(), info.warnings.end());
  auto take = [&](const auto& subject, const std::optional<PartInfo>& part, const char* scalar, auto& out) {
    if (!subject) {
      if (!info.scalar_unavailable.count(scalar))
        info.scalar_unavailable[scalar] = std::string("the implementation was not compiled for ") + scalar;
      return;
    }
    for (const auto& [slot, why] : part->slot_notes)
      if (!info.slot_notes[scalar].count(slot)) info.slot_notes[scalar][slot] = why;
    for (const auto& w : part->warnings)
      if (seen_warnings.insert(w).second) info.warnings.push_back(w);
    for (const auto& u : part->unchecked)
      if (seen_warnings.insert(u).second) info.unchecked.push_back(u);
    if (!fills_anything(*subject)) return;  // nothing here: the runner reports each check NOT PROVIDED, with the reason
    out = subject;
  };
  take(r.d, r.d_info, "double", s.d);
  take(r.mp, r.mp_info, "mp50", s.mp);
  take(r.q, r.q_info, "exact", s.q);
  // A double-only implementation: say once, at the top, what that costs.
  if (s.d && fills_slots(*s.d)) {
    const bool mp_missing = !s.mp && !info.scalar_unavailable.count("mp50");
    const bool q_missing = !s.q && !info.scalar_unavailable.count("exact");
    if (mp_missing || q_missing)
      info.warnings.push_back(
          std::string("nothing is written as a template on the scalar, so nothing is checked in ") +
          (mp_missing && q_missing ? "50 digits (mp50) or exact rationals (exact)"
           : mp_missing            ? "50 digits (mp50)"
                                   : "exact rationals (exact)") +
          ": write `template <class T> static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi)` and so on");
  }
  for (const auto& [slot, why] : info.slot_notes["double"])
    if (why.rfind("a function named", 0) == 0) info.unchecked.push_back("slot '" + slot + "': " + why);
  return s;
}

}  // namespace gm::student
