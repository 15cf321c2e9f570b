// asv_ros/frames.h against a tf2 buffer filled by hand (no master). The frame `utm_local` is the map
// frame turned 90 deg counter-clockwise about z and shifted by (100, 200) m: a point (10, 0) of it is
// map (100 - 0, 200 + 10) = (100, 210), and a heading along its x axis (yaw 0) is map yaw 90 deg.
#include <gtest/gtest.h>

#include <cmath>

#include <asv_ros/frames.h>
#include <geometry_msgs/TransformStamped.h>
#include <tf2/utils.h>

namespace {

void addUtm(tf2::BufferCore& b, bool is_static) {
  geometry_msgs::TransformStamped t;
  t.header.frame_id = "map";
  t.header.stamp = ros::Time(100.0);
  t.child_frame_id = "utm_local";
  t.transform.translation.x = 100.0;
  t.transform.translation.y = 200.0;
  t.transform.rotation.z = std::sin(M_PI / 4.0);
  t.transform.rotation.w = std::cos(M_PI / 4.0);
  b.setTransform(t, "test", is_static);
}

}  // namespace

TEST(Frames, PoseInAnotherFrameIsMovedIntoMap) {
  tf2::BufferCore b;
  addUtm(b, true);
  tf2::Transform t;
  ASSERT_TRUE(asv_ros::lookupInto(b, "map", "utm_local", ros::Time(5.0), t));
  geometry_msgs::Pose p;
  p.position.x = 10.0;
  p.orientation.w = 1.0;
  const geometry_msgs::Pose m = asv_ros::transformPose(t, p);
  EXPECT_NEAR(m.position.x, 100.0, 1e-9);
  EXPECT_NEAR(m.position.y, 210.0, 1e-9);
  EXPECT_NEAR(tf2::getYaw(m.orientation), M_PI / 2.0, 1e-9);
}

TEST(Frames, WorkingFrameIsIdentityAndUnknownFramesFail) {
  tf2::BufferCore b;
  addUtm(b, false);
  tf2::Transform t;
  ASSERT_TRUE(asv_ros::lookupInto(b, "map", "/map", ros::Time(1.0), t));  // a leading '/' as ROS 1 wrote it
  EXPECT_NEAR(t.getOrigin().length(), 0.0, 1e-12);
  EXPECT_FALSE(asv_ros::lookupInto(b, "map", "", ros::Time(1.0), t));
  EXPECT_FALSE(asv_ros::lookupInto(b, "map", "odom", ros::Time(1.0), t));  // nothing connects it
  // A dynamic transform asked at a time it does not cover: refused, unless the latest is asked for.
  EXPECT_FALSE(asv_ros::lookupInto(b, "map", "utm_local", ros::Time(500.0), t));
  ASSERT_TRUE(asv_ros::lookupInto(b, "map", "utm_local", ros::Time(500.0), t, true));
  EXPECT_NEAR(t.getOrigin().x(), 100.0, 1e-9);
}
