// Lockstep simulation: the bookkeeping of the simulator's side, free of ROS.
//
// Rule: in lockstep the simulation advances one step only when every stage of the pipeline has done
// all the work that step gives it. The stages (participants) act in a fixed order of phases
// (ingestion, tracking, risk, planning, evaluation); within a phase, a participant acts once it has
// received every message published so far on each of its inputs. So what a stage sees, and when, no
// longer depends on how fast the machine is or how the operating system schedules the processes:
// the same scenario and seed give the same messages on every run.
//
// The coordinator counts the messages published on each lockstep topic (the simulator's own, and each
// participant's as its acknowledgements report them) and decides who acts in a phase: a participant
// acts when one of its periodic jobs is due or a message arrived on one of its trigger inputs since it
// last acted. Participants that have nothing to do are not woken, so a step with no work costs nothing.
// Times are ROS times in integer nanoseconds (exact: no rounding decides a due time).
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace asv {

struct LockstepInput {
  std::string topic;
  bool trigger = true;  // a message on it gives the participant work; false: it only reads the latest
};

class LockstepCoordinator {
public:
  // A participant asks to join (or, restarted, to join again): admitted at the next step's phase 0.
  // Its earlier output counts stay in the totals (the subscribers received those messages). Refused
  // (false, nothing changes) without a node name or with a phase below 1: phase 0 is the admission
  // round itself, and a participant in it would be admitted again at every step.
  bool hello(const std::string& node, int phase, const std::vector<LockstepInput>& inputs);
  // Participants waiting for admission, sorted by name.
  std::vector<std::string> pendingAdmissions() const;
  // A participant acknowledged its admission: it now counts its inputs from the current totals.
  void admit(const std::string& node);
  bool admitted(const std::string& node) const;
  int phaseOf(const std::string& node) const;  // -1: unknown
  std::size_t participants() const { return parts_.size(); }

  // The simulator published a message on `topic`.
  void published(const std::string& topic, uint64_t n = 1) { own_[topic] += n; }
  // Messages published so far on `topic` by everyone.
  uint64_t total(const std::string& topic) const;
  // Every topic with its total, sorted by topic.
  std::map<std::string, uint64_t> totals() const;

  // The distinct phases of the admitted participants, ascending.
  std::vector<int> phases() const;
  // Admitted participants of `phase` with work at time t_ns, sorted by name.
  std::vector<std::string> runners(int phase, int64_t t_ns) const;
  bool anyRunner(int64_t t_ns) const;  // in any phase
  // The runners were sent their step: they will have seen every trigger message published so far.
  void started(const std::vector<std::string>& runners);
  // A participant finished its step: cumulative counts of its outputs, and its next due time (0: none).
  void acked(const std::string& node, const std::map<std::string, uint64_t>& outputs, int64_t next_due_ns);

private:
  struct Participant {
    int phase = 0;
    bool admitted = false;
    std::vector<LockstepInput> inputs;
    std::map<std::string, uint64_t> outputs;  // cumulative counts reported by this incarnation
    std::map<std::string, uint64_t> seen;     // trigger totals when it last started a step
    int64_t next_due_ns = 1;                  // due at once until its first acknowledgement
  };
  std::map<std::string, Participant> parts_;
  std::map<std::string, uint64_t> own_;      // the simulator's publications
  std::map<std::string, uint64_t> retired_;  // outputs of participants' earlier incarnations
};

}  // namespace asv
