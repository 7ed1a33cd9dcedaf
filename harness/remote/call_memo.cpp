#include "harness/remote/call_memo.hpp"

namespace gm::protocol {

const nlohmann::json* CallMemo::find(const std::string& key, bool* recheck) {
  const auto it = replies_.find(key);
  if (it == replies_.end()) {
    ++misses_;
    return nullptr;
  }
  ++hits_;
  *recheck = hits_ % kRecheckEvery == 0;
  return &it->second;
}

void CallMemo::remember(const std::string& key, const nlohmann::json& result) {
  if (replies_.size() >= kMaxEntries) replies_.clear();
  replies_.insert_or_assign(key, result);
}

std::string CallMemo::compare(const nlohmann::json& before, const nlohmann::json& now) {
  if (before == now) return "";
  auto cut = [](std::string s) { return s.size() > 400 ? s.substr(0, 397) + "..." : s; };
  return "the first time: " + cut(before.dump()) + "\n  the second time: " + cut(now.dump());
}

}  // namespace gm::protocol
