// InputWatch (input_watch.h): when a stage's input counts as stale, with expected ages worked by hand.
#include <gtest/gtest.h>

#include <stdexcept>

#include "asv_core/common/input_watch.h"

namespace {

asv::InputWatch watch(double wall_floor = 0.5, double grace = 10.0) {
  asv::InputWatchConfig c;
  c.wall_floor = wall_floor;
  c.startup_grace = grace;
  asv::InputWatch w(c);
  w.add("targets", 1.5);
  w.add("odom", 1.0);
  return w;
}

}  // namespace

TEST(InputWatch, AnInputIsStaleAfterItsTimeoutInBothClocks) {
  asv::InputWatch w = watch();
  w.start(100.0, 0.0);
  w.received("targets", 100.0, 0.0);
  w.received("odom", 100.0, 0.0);
  EXPECT_TRUE(w.stale(101.0, 1.0).empty());
  // 1.2 s on: odom (1.0 s timeout) is stale, targets (1.5 s) not yet.
  auto s = w.stale(101.2, 1.2);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].name, "odom");
  EXPECT_EQ(s[0].text, "odom: none for 1.2 s (timeout 1.0 s)");
  // 1.6 s: both, in the order added.
  s = w.stale(101.6, 1.6);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].name, "targets");
  EXPECT_NEAR(w.age("targets", 101.6), 1.6, 1e-9);
  // A new message clears it.
  w.received("odom", 101.7, 1.7);
  s = w.stale(101.8, 1.8);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].name, "targets");
}

TEST(InputWatch, FasterThanRealTimeTheWallFloorAlsoMustPass) {
  // At 10x: 2 s of node time are 0.2 s of wall time, under the 0.5 s floor: not stale yet.
  asv::InputWatch w = watch(0.5);
  w.start(0.0, 0.0);
  w.received("targets", 0.0, 0.0);
  w.received("odom", 0.0, 0.0);
  EXPECT_TRUE(w.stale(2.0, 0.2).empty());
  EXPECT_EQ(w.stale(6.0, 0.6).size(), 2u);
  // No floor: node time alone decides.
  asv::InputWatch v = watch(0.0);
  v.start(0.0, 0.0);
  v.received("targets", 0.0, 0.0);
  v.received("odom", 0.0, 0.0);
  EXPECT_EQ(v.stale(2.0, 0.2).size(), 2u);
}

TEST(InputWatch, NeverReceivedIsStaleOnlyAfterTheStartupGrace) {
  asv::InputWatch w = watch(0.5, 10.0);
  w.start(50.0, 0.0);
  EXPECT_TRUE(w.stale(61.0, 11.0).empty());  // 11 s < 1.5 + 10 for targets, 11 = 1.0 + 10 for odom
  auto s = w.stale(61.6, 11.6);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].text, "odom: nothing received in 11.6 s since start");
  EXPECT_FALSE(w.everReceived("odom"));
}

TEST(InputWatch, ABusyNodeReadsItsQueueBeforeCallingAnInputStale) {
  asv::InputWatch w = watch(0.0);
  w.start(0.0, 0.0);
  w.received("targets", 0.0, 0.0);
  w.received("odom", 0.0, 0.0);
  w.busy(5.0, 5.0);  // a 5 s plan: what arrived meanwhile is still queued
  EXPECT_TRUE(w.stale(5.0, 5.0).empty());
  EXPECT_EQ(w.stale(6.6, 6.6).size(), 2u);  // still nothing 1.6 s after the node was free again
}

TEST(InputWatch, BusyDoesNotExtendTheStartupGrace) {
  asv::InputWatch w = watch(0.0, 10.0);
  w.start(0.0, 0.0);
  // A node busy every 2 s: an input that never came is still stale once the grace and its timeout
  // are over (odom: 10 + 1.0 s), and 1.0 s past the last busy spell.
  for (double t = 2.0; t <= 10.0; t += 2.0)
    w.busy(t, t);
  EXPECT_TRUE(w.stale(10.5, 10.5).empty());
  const auto s = w.stale(11.1, 11.1);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].name, "odom");
}

TEST(InputWatch, RefusesBadSettingsAndUnknownInputs) {
  asv::InputWatch w;
  EXPECT_THROW(w.add("x", 0.0), std::invalid_argument);
  w.add("x", 1.0);
  EXPECT_THROW(w.add("x", 2.0), std::invalid_argument);
  EXPECT_THROW(w.received("y", 0.0, 0.0), std::invalid_argument);
  asv::InputWatchConfig c;
  c.wall_floor = -1.0;
  EXPECT_THROW(asv::InputWatch{c}, std::invalid_argument);
}

TEST(InputWatch, ResetForgetsEveryReception) {
  asv::InputWatch w = watch(0.0, 0.0);
  w.received("targets", 10.0, 10.0);
  w.reset();
  EXPECT_FALSE(w.everReceived("targets"));
  w.start(2.0, 2.0);  // the clock went back to 2 s
  EXPECT_DOUBLE_EQ(w.age("targets", 3.0), 1.0);
}

TEST(InputWatch, ReadsItsKeysAndNamesABadOne) {
  asv::ParamMap p;
  p.set("watch/input_timeout", 2.0);
  p.set("watch/wall_floor", 0.0);
  const asv::InputWatchConfig c = asv::InputWatchConfig::fromParams(p);
  EXPECT_DOUBLE_EQ(c.input_timeout, 2.0);
  EXPECT_DOUBLE_EQ(c.wall_floor, 0.0);
  EXPECT_DOUBLE_EQ(c.startup_grace, 10.0);  // the default
  asv::InputWatch w(c);
  w.add("risk");
  w.start(0.0, 0.0);
  w.received("risk", 0.0, 0.0);
  EXPECT_TRUE(w.stale(2.0, 2.0).empty());
  EXPECT_EQ(w.stale(2.1, 2.1).size(), 1u);
  p.set("watch/input_timeout", 0.0);
  try {
    asv::InputWatchConfig::fromParams(p);
    FAIL() << "a zero timeout was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("watch/input_timeout"), std::string::npos) << e.what();
  }
}
