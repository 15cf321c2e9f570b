#include <gtest/gtest.h>

#include "asv_risk/heartbeat.h"

TEST(Heartbeat, HeartbeatOnlyWhenNothingWentOutForAPeriod) {
  ros::Time last(100.0);
  // 0.3 s after the last array: nothing to send; 0.5 s: an empty array, stamped now, in the frame.
  EXPECT_FALSE(asv_risk::heartbeatArray(ros::Time(100.3), last, 0.5, "map"));
  const auto hb = asv_risk::heartbeatArray(ros::Time(100.5), last, 0.5, "map");
  ASSERT_TRUE(hb);
  EXPECT_TRUE(hb->targets.empty());
  EXPECT_EQ(hb->header.stamp, ros::Time(100.5));
  EXPECT_EQ(hb->header.frame_id, "map");
  EXPECT_EQ(last, ros::Time(100.5));
  EXPECT_FALSE(asv_risk::heartbeatArray(ros::Time(100.9), last, 0.5, "map"));
  // The clock went back (a looping bag): at once; no clock yet: never.
  EXPECT_TRUE(asv_risk::heartbeatArray(ros::Time(50.0), last, 0.5, "map"));
  EXPECT_FALSE(asv_risk::heartbeatArray(ros::Time(0.0), last, 0.5, "map"));
}
