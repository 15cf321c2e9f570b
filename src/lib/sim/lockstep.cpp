#include "asv_core/sim/lockstep.h"

#include <algorithm>

namespace asv {

bool LockstepCoordinator::hello(const std::string& node, int phase,
                                const std::vector<LockstepInput>& inputs) {
  if (node.empty() || phase < 1)
    return false;
  auto it = parts_.find(node);
  if (it != parts_.end()) {
    if (!it->second.admitted)
      return true;  // repeated hello while waiting for admission
    for (const auto& [topic, n] : it->second.outputs)
      retired_[topic] += n;
  }
  Participant p;
  p.phase = phase;
  p.inputs = inputs;
  parts_[node] = std::move(p);
  return true;
}

std::vector<std::string> LockstepCoordinator::pendingAdmissions() const {
  std::vector<std::string> out;
  for (const auto& [name, p] : parts_)
    if (!p.admitted)
      out.push_back(name);
  return out;
}

void LockstepCoordinator::admit(const std::string& node) {
  auto it = parts_.find(node);
  if (it == parts_.end())
    return;
  it->second.admitted = true;
  for (const auto& in : it->second.inputs)
    it->second.seen[in.topic] = total(in.topic);
}

bool LockstepCoordinator::admitted(const std::string& node) const {
  auto it = parts_.find(node);
  return it != parts_.end() && it->second.admitted;
}

int LockstepCoordinator::phaseOf(const std::string& node) const {
  auto it = parts_.find(node);
  return it == parts_.end() ? -1 : it->second.phase;
}

uint64_t LockstepCoordinator::total(const std::string& topic) const {
  uint64_t n = 0;
  if (auto it = own_.find(topic); it != own_.end())
    n += it->second;
  if (auto it = retired_.find(topic); it != retired_.end())
    n += it->second;
  for (const auto& [name, p] : parts_)
    if (auto it = p.outputs.find(topic); it != p.outputs.end())
      n += it->second;
  return n;
}

std::map<std::string, uint64_t> LockstepCoordinator::totals() const {
  std::set<std::string> topics;
  for (const auto& [t, n] : own_)
    topics.insert(t);
  for (const auto& [t, n] : retired_)
    topics.insert(t);
  for (const auto& [name, p] : parts_)
    for (const auto& [t, n] : p.outputs)
      topics.insert(t);
  std::map<std::string, uint64_t> out;
  for (const auto& t : topics)
    out[t] = total(t);
  return out;
}

std::vector<int> LockstepCoordinator::phases() const {
  std::set<int> s;
  for (const auto& [name, p] : parts_)
    if (p.admitted)
      s.insert(p.phase);
  return {s.begin(), s.end()};
}

std::vector<std::string> LockstepCoordinator::runners(int phase, int64_t t_ns) const {
  std::vector<std::string> out;
  for (const auto& [name, p] : parts_) {
    if (!p.admitted || p.phase != phase)
      continue;
    bool due = p.next_due_ns > 0 && p.next_due_ns <= t_ns;
    for (const auto& in : p.inputs) {
      if (due)
        break;
      auto seen = p.seen.find(in.topic);
      due = in.trigger && total(in.topic) > (seen == p.seen.end() ? 0 : seen->second);
    }
    if (due)
      out.push_back(name);
  }
  return out;
}

bool LockstepCoordinator::anyRunner(int64_t t_ns) const {
  for (int phase : phases())
    if (!runners(phase, t_ns).empty())
      return true;
  return false;
}

void LockstepCoordinator::started(const std::vector<std::string>& runners) {
  for (const auto& name : runners) {
    auto it = parts_.find(name);
    if (it == parts_.end())
      continue;
    for (const auto& in : it->second.inputs)
      it->second.seen[in.topic] = total(in.topic);
  }
}

void LockstepCoordinator::acked(const std::string& node, const std::map<std::string, uint64_t>& outputs,
                                int64_t next_due_ns) {
  auto it = parts_.find(node);
  if (it == parts_.end() || !it->second.admitted)
    return;
  for (const auto& [topic, n] : outputs)
    it->second.outputs[topic] = std::max(it->second.outputs[topic], n);
  it->second.next_due_ns = next_due_ns;
}

}  // namespace asv
