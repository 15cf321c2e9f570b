#include <gtest/gtest.h>

#include "asv_core/sim/lockstep.h"

using asv::LockstepCoordinator;
using Names = std::vector<std::string>;

namespace {
constexpr int64_t kSec = 1000000000;

// The scenario pipeline's shape: ingestion (phase 1) triggered by NMEA, reading odometry; a tracker
// (phase 2) publishing every 0.5 s; risk (phase 3) triggered by the tracks.
LockstepCoordinator pipeline() {
  LockstepCoordinator c;
  c.hello("/ais_node", 1, {{"/sim/nmea", true}});
  c.hello("/arpa_node", 1, {{"/sim/nmea", true}, {"/own/odom", false}});
  c.hello("/tracker", 2, {{"/ais/targets", true}, {"/arpa/targets", true}});
  c.hello("/risk_node", 3, {{"/own/odom", false}, {"/targets", true}});
  for (const auto& n : c.pendingAdmissions())
    c.admit(n);
  return c;
}

// Every participant acts at t0 (its first step); then only the tracker has a job, due at t0 + 0.5 s.
void firstStep(LockstepCoordinator& c, int64_t t0) {
  for (int phase : {1, 2, 3}) {
    const Names r = c.runners(phase, t0);
    c.started(r);
    for (const auto& n : r)
      c.acked(n, {}, n == "/tracker" ? t0 + kSec / 2 : 0);
  }
}
}  // namespace

TEST(Lockstep, AdmissionWaitsForTheNextStepAndEveryNewcomerRunsFirst) {
  LockstepCoordinator c;
  c.hello("/b", 2, {});
  c.hello("/a", 1, {});
  c.hello("/a", 1, {});  // repeated while waiting: one entry
  EXPECT_EQ(c.pendingAdmissions(), (Names{"/a", "/b"}));
  EXPECT_TRUE(c.phases().empty());  // nobody acts before admission
  c.admit("/a");
  EXPECT_TRUE(c.admitted("/a"));
  EXPECT_FALSE(c.admitted("/b"));
  EXPECT_EQ(c.phases(), (std::vector<int>{1}));
  // A newcomer has not told its due time yet: it acts at its first step.
  EXPECT_EQ(c.runners(1, 5 * kSec), (Names{"/a"}));
}

TEST(Lockstep, AJoinWithoutANameOrAWorkPhaseIsRefused) {
  LockstepCoordinator c;
  // Phase 0 is the admission round: a participant there would be admitted again at every step.
  EXPECT_FALSE(c.hello("/zero", 0, {}));
  EXPECT_FALSE(c.hello("/negative", -1, {}));
  EXPECT_FALSE(c.hello("", 1, {}));
  EXPECT_EQ(c.participants(), 0u);
  EXPECT_TRUE(c.pendingAdmissions().empty());
  EXPECT_TRUE(c.hello("/a", 1, {}));
  EXPECT_TRUE(c.hello("/late_phase", 9, {}));  // a phase the stack does not name yet is still a phase
  EXPECT_EQ(c.pendingAdmissions(), (Names{"/a", "/late_phase"}));
}

TEST(Lockstep, RunnersAreThoseWithADueJobOrNewTriggerInput) {
  LockstepCoordinator c = pipeline();
  const int64_t t0 = 100 * kSec;
  firstStep(c, t0);
  const int64_t t1 = t0 + kSec / 10;
  // Odometry alone wakes nobody: it is read, not a trigger.
  c.published("/own/odom");
  EXPECT_TRUE(c.runners(1, t1).empty());
  // One NMEA sentence wakes both ingestion nodes (and only them).
  c.published("/sim/nmea");
  EXPECT_EQ(c.runners(1, t1), (Names{"/ais_node", "/arpa_node"}));
  EXPECT_TRUE(c.runners(2, t1).empty());  // the tracker's next job is at t0 + 0.5 s
  c.started({"/ais_node", "/arpa_node"});
  c.acked("/ais_node", {{"/ais/targets", 1}}, 0);
  c.acked("/arpa_node", {}, 0);
  EXPECT_TRUE(c.runners(1, t1).empty());  // what they were started with is seen
  // The AIS array triggers the tracker before its periodic job is due.
  EXPECT_EQ(c.runners(2, t1), (Names{"/tracker"}));
  EXPECT_TRUE(c.runners(3, t1).empty());
  // Due exactly at t0 + 0.5 s (integer nanoseconds: no rounding), not a nanosecond before.
  c.started({"/tracker"});
  c.acked("/tracker", {{"/targets", 1}}, t0 + kSec / 2);
  EXPECT_TRUE(c.runners(2, t0 + kSec / 2 - 1).empty());
  EXPECT_EQ(c.runners(2, t0 + kSec / 2), (Names{"/tracker"}));
  EXPECT_EQ(c.runners(3, t1), (Names{"/risk_node"}));
}

TEST(Lockstep, TotalsAddTheSimulatorsAndEveryParticipantsCounts) {
  LockstepCoordinator c = pipeline();
  c.published("/sim/nmea", 7);
  c.published("/own/odom", 3);
  c.acked("/tracker", {{"/targets", 4}}, 0);
  // Counts are cumulative: a late, smaller report never lowers a total.
  c.acked("/tracker", {{"/targets", 2}}, 0);
  EXPECT_EQ(c.total("/sim/nmea"), 7u);
  EXPECT_EQ(c.total("/targets"), 4u);
  EXPECT_EQ(c.total("/nothing"), 0u);
  const auto t = c.totals();
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(t.at("/own/odom"), 3u);
}

TEST(Lockstep, ARestartedParticipantKeepsItsEarlierMessagesInTheTotals) {
  LockstepCoordinator c = pipeline();
  c.acked("/tracker", {{"/targets", 10}}, 0);
  // The tracker restarts (respawn): its new incarnation counts from zero again.
  c.hello("/tracker", 2, {{"/ais/targets", true}, {"/arpa/targets", true}});
  EXPECT_FALSE(c.admitted("/tracker"));
  EXPECT_EQ(c.pendingAdmissions(), (Names{"/tracker"}));
  EXPECT_TRUE(c.runners(2, kSec).empty());  // not acting until admitted again
  c.admit("/tracker");
  c.acked("/tracker", {{"/targets", 3}}, 0);
  EXPECT_EQ(c.total("/targets"), 13u);  // 10 received before the restart + 3 after
}

TEST(Lockstep, AcknowledgementsOfUnknownNodesAreIgnored) {
  LockstepCoordinator c = pipeline();
  c.acked("/stranger", {{"/targets", 99}}, 1);
  EXPECT_EQ(c.total("/targets"), 0u);
  EXPECT_EQ(c.participants(), 4u);
}

TEST(Lockstep, AnyRunnerLooksAtEveryPhase) {
  LockstepCoordinator c = pipeline();
  const int64_t t0 = 100 * kSec;
  firstStep(c, t0);
  EXPECT_FALSE(c.anyRunner(t0 + kSec / 10));  // nothing due, no new trigger input
  EXPECT_TRUE(c.anyRunner(t0 + kSec / 2));    // the tracker's job (phase 2)
  c.published("/targets");                    // a trigger of the risk node (phase 3)
  EXPECT_TRUE(c.anyRunner(t0 + kSec / 10));
}
