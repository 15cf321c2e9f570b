// rostest: sim_node publishes /clock, odometry and tf; a set-point changes the own ship's course.
#include <gtest/gtest.h>

#include <cmath>

#include <asv_msgs/CourseSpeedSetpoint.h>
#include <asv_msgs/NmeaSentence.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

namespace {

double courseOfOdom(const nav_msgs::Odometry& o) {
  const double yaw = 2.0 * std::atan2(o.pose.pose.orientation.z, o.pose.pose.orientation.w);
  double c = M_PI / 2 - yaw;  // nautical course from ENU yaw
  while (c < 0)
    c += 2 * M_PI;
  while (c >= 2 * M_PI)
    c -= 2 * M_PI;
  return c;
}

template <typename Pred>
bool waitFor(Pred p, double wall_seconds) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(wall_seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    ros::spinOnce();
    if (p())
      return true;
    ros::WallDuration(0.01).sleep();
  }
  return false;
}

}  // namespace

TEST(SimNode, ClockOdometryTfNmeaAndSetpoint) {
  ros::NodeHandle nh;
  rosgraph_msgs::Clock::ConstPtr clock;
  nav_msgs::Odometry::ConstPtr own, ts1;
  int ais = 0, ttm = 0;
  auto c_sub = nh.subscribe<rosgraph_msgs::Clock>(
      "/clock", 10, [&](const rosgraph_msgs::Clock::ConstPtr& m) { clock = m; });
  auto o_sub = nh.subscribe<nav_msgs::Odometry>("own/odom", 10,
                                                [&](const nav_msgs::Odometry::ConstPtr& m) { own = m; });
  auto t_sub = nh.subscribe<nav_msgs::Odometry>("ts1/odom", 10,
                                                [&](const nav_msgs::Odometry::ConstPtr& m) { ts1 = m; });
  auto n_sub =
      nh.subscribe<asv_msgs::NmeaSentence>("sim/nmea", 1000, [&](const asv_msgs::NmeaSentence::ConstPtr& m) {
        if (m->sentence.rfind("!AIVDM", 0) == 0)
          ++ais;
        if (m->sentence.rfind("$RATTM", 0) == 0)
          ++ttm;
      });
  ros::Publisher cmd = nh.advertise<asv_msgs::CourseSpeedSetpoint>("own/cmd", 1, true);
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);

  ASSERT_TRUE(waitFor([&] { return clock && own && ts1; }, 20.0)) << "no clock or odometry";
  EXPECT_EQ(own->header.frame_id, "map");
  EXPECT_EQ(own->child_frame_id, "own/base_link");
  const ros::Time t0 = clock->clock;
  // Heading north at 5 m/s: ENU yaw +90 deg, body-frame forward speed 5.
  EXPECT_NEAR(courseOfOdom(*own), 0.0, 1e-6);
  EXPECT_NEAR(own->twist.twist.linear.x, 5.0, 1e-6);
  // Time advances (rate 20: 20 s of sim time in about a second of wall time).
  ASSERT_TRUE(waitFor([&] { return (clock->clock - t0).toSec() > 20.0; }, 10.0));
  // tf map -> own/base_link matches the odometry.
  ASSERT_TRUE(waitFor([&] { return buffer.canTransform("map", "own/base_link", ros::Time(0)); }, 10.0));
  const auto tf = buffer.lookupTransform("map", "own/base_link", ros::Time(0));
  EXPECT_NEAR(tf.transform.translation.x, 0.0, 1e-6);
  EXPECT_GT(tf.transform.translation.y, 50.0);
  // ts1 steams west at 5 m/s: x = 3000 - 5 t.
  const double t_sim = (ts1->header.stamp - ros::Time(1.0e9)).toSec();
  EXPECT_NEAR(ts1->pose.pose.position.x, 3000.0 - 5.0 * t_sim, 1e-6);

  // A set-point to 090: the kinematic own ship turns at 1 deg/s after a 10 s delay.
  asv_msgs::CourseSpeedSetpoint sp;
  sp.course = M_PI / 2;
  sp.speed = 5.0;
  cmd.publish(sp);
  ASSERT_TRUE(waitFor([&] { return std::fabs(courseOfOdom(*own) - M_PI / 2) < 1e-3; }, 20.0))
      << "own course " << courseOfOdom(*own);
  EXPECT_GT(ais, 0);  // ts1 is reported by AIS ...
  EXPECT_GT(ttm, 0);  // ... and tracked by the radar
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_sim_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
