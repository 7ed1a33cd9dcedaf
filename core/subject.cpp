#include "core/subject.hpp"

namespace gm {

const std::vector<SlotInfo>& subject_slots() {
  static const std::vector<SlotInfo> table = {
#define GM_SLOT_INFO(name, sig, place, meaning) SlotInfo{#name, #sig, place, meaning},
      GM_SUBJECT_SLOTS(GM_SLOT_INFO)
#undef GM_SLOT_INFO
  };
  return table;
}

bool is_slot_name(std::string_view name) {
  for (const auto& s : subject_slots())
    if (name == s.name) return true;
  return false;
}

}  // namespace gm
