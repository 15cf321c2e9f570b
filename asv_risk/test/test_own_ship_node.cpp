// rostest: own_ship_node fed a GNSS log (test/data/gnss_log.nmea, written by make_gnss_log.py: a ship
// sailing 090 at 10 kn = 5.144 m/s from the map origin, one RMC + GGA + HDT epoch per second) on
// nmea_in, one epoch every 0.2 s. Expected by hand:
//  - after epoch k the odometry is 5.144 k m east of the origin (plus what it dead-reckons since, at
//    most 0.3 s x 5.144 m/s here), 0 north, ENU yaw 0 (heading 090), body twist (5.144, 0);
//  - its position variance (HDOP 0.9 x 4 m)^2 = 12.96 m^2 (the GGA, the epoch's last fix; at epoch 20
//    the RMC's, (1.5 x 4 m)^2 = 36 m^2, as that epoch's GGA is rejected);
//  - epoch 20's GGA, 0.5' (926 m) north, is a jump: rejected, the odometry stays on the track; epoch
//    25's RMC (status V) is rejected, its GGA used;
//  - the log over, the fix goes stale after 2 s: an ERROR alarm naming it, and the odometry stops.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <asv_msgs/Alarm.h>
#include <asv_msgs/NmeaSentence.h>
#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/NavSatFix.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

namespace {

constexpr double kSpeed = 10.0 * 1852.0 / 3600.0;

TEST(OwnShipNode, GnssLogToOdometryJumpsRejectedStaleFixAlarmed) {
  ros::NodeHandle nh;
  std::string path;
  ASSERT_TRUE(nh.getParam("gnss_log", path));
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);)
    lines.push_back(l);
  ASSERT_EQ(lines.size(), 120u) << path;
  nav_msgs::Odometry::ConstPtr odom;
  ros::Time last_odom;
  asv_msgs::Alarm::ConstPtr alarm;
  ros::Publisher pub = nh.advertise<asv_msgs::NmeaSentence>("nmea_in", 100);
  ros::Subscriber os =
      nh.subscribe<nav_msgs::Odometry>("own/odom", 50, [&](const nav_msgs::Odometry::ConstPtr& m) {
        odom = m;
        last_odom = ros::Time::now();
      });
  ros::Subscriber as =
      nh.subscribe<asv_msgs::Alarm>("alarms", 10, [&](const asv_msgs::Alarm::ConstPtr& m) { alarm = m; });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
  while ((pub.getNumSubscribers() == 0 || os.getNumPublishers() == 0) && ros::WallTime::now() < deadline)
    ros::WallDuration(0.05).sleep();
  double max_north = 0.0;
  for (std::size_t k = 0; k < 40; ++k) {
    for (std::size_t i = 0; i < 3; ++i) {
      asv_msgs::NmeaSentence s;
      s.header.stamp = ros::Time::now();
      s.sentence = lines[3 * k + i];
      pub.publish(s);
    }
    const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(0.2);
    while (ros::WallTime::now() < until) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
    if (k < 2)
      continue;  // the first epochs may pass while the connections settle
    ASSERT_TRUE(odom) << "no odometry after epoch " << k;
    max_north = std::max(max_north, std::fabs(odom->pose.pose.position.y));
    {
      EXPECT_NEAR(odom->pose.pose.position.x, kSpeed * static_cast<double>(k), 2.0) << "epoch " << k;
      EXPECT_NEAR(odom->twist.twist.linear.x, kSpeed, 1e-3);
      EXPECT_NEAR(odom->twist.twist.linear.y, 0.0, 1e-3);
      EXPECT_NEAR(odom->pose.pose.orientation.z, 0.0, 1e-6);  // yaw 0: heading 090
      // Epoch 20's GGA was rejected: its RMC is the fix, without HDOP: (1.5 x 4 m)^2.
      EXPECT_NEAR(odom->pose.covariance[0], k == 20 ? 36.0 : 12.96, 1e-9) << "epoch " << k;
    }
  }
  EXPECT_LT(max_north, 3.0) << "the 926 m jump reached the odometry";
  EXPECT_EQ(odom->header.frame_id, "map");
  EXPECT_EQ(odom->child_frame_id, "own/base_link");
  // The log is over: the fix goes stale.
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(4.0);
  while (ros::WallTime::now() < end) {
    ros::spinOnce();
    ros::WallDuration(0.02).sleep();
  }
  ASSERT_TRUE(alarm);
  EXPECT_EQ(alarm->level, asv_msgs::Alarm::ERROR);
  ASSERT_FALSE(alarm->inputs.empty());
  EXPECT_EQ(alarm->inputs[0], "fix");
  EXPECT_LT((ros::Time::now() - last_odom).toSec(), 4.0);
  EXPECT_GT((ros::Time::now() - last_odom).toSec(), 1.0) << "odometry goes on without a fix";
}

// A GNSS driver's topics (navsat: true, node own_ship_navsat in own_ship_node.test): a fix 0.001 deg north
// of the origin (the meridian arc at 48.1 N: 111.193 m, test_own_ship.cpp) with covariance diag (4, 9),
// velocity due north at 5 m/s, orientation ENU yaw 80 deg (heading 010). Expected by hand: x 0, y 111.193
// plus at most 0.3 s x 5 m/s dead-reckoned, position variance 9 (the larger), body twist
// (5 cos 10, 5 sin 10) = (4.924, 0.868): the ship sails 10 deg to port of her heading.
// REP 105 (odom_frame navsat_odom): the fix stays put while she reports 5 m/s north, so each fix pulls the
// map estimate back; odom -> base_link keeps integrating 5 m/s (about 14 m over the 2.8 s after the first
// fix) and map -> odom carries the difference (y about -14 m); the chain map -> odom -> base_link is
// the odometry's position at its stamp.
TEST(OwnShipNode, NavSatFixVelocityAndHeadingTopicsToOdometry) {
  ros::NodeHandle nh;
  tf2_ros::Buffer tf_buffer;
  tf2_ros::TransformListener tf_listener(tf_buffer);
  ros::Publisher fix = nh.advertise<sensor_msgs::NavSatFix>("navsat/fix", 10);
  ros::Publisher vel = nh.advertise<geometry_msgs::TwistStamped>("navsat/vel", 10);
  ros::Publisher heading = nh.advertise<geometry_msgs::QuaternionStamped>("navsat/heading", 10);
  nav_msgs::Odometry::ConstPtr odom;
  ros::Subscriber os = nh.subscribe<nav_msgs::Odometry>(
      "navsat/odom", 50, [&](const nav_msgs::Odometry::ConstPtr& m) { odom = m; });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
  while ((fix.getNumSubscribers() == 0 || heading.getNumSubscribers() == 0 || os.getNumPublishers() == 0) &&
         ros::WallTime::now() < deadline)
    ros::WallDuration(0.05).sleep();
  sensor_msgs::NavSatFix f;
  f.latitude = 48.1173 + 0.001;
  f.longitude = 11.516666666666667;
  f.status.status = sensor_msgs::NavSatStatus::STATUS_FIX;
  f.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN;
  f.position_covariance[0] = 4.0;
  f.position_covariance[4] = 9.0;
  geometry_msgs::TwistStamped v;
  v.twist.linear.y = 5.0;
  geometry_msgs::QuaternionStamped q;
  q.quaternion.z = std::sin(80.0 * M_PI / 360.0);
  q.quaternion.w = std::cos(80.0 * M_PI / 360.0);
  for (int k = 0; k < 15; ++k) {
    f.header.stamp = v.header.stamp = q.header.stamp = ros::Time::now();
    vel.publish(v);
    heading.publish(q);
    fix.publish(f);
    const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(0.2);
    while (ros::WallTime::now() < until) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
  }
  ASSERT_TRUE(odom) << "no odometry from the NavSatFix topics";
  EXPECT_NEAR(odom->pose.pose.position.x, 0.0, 0.5);
  EXPECT_GT(odom->pose.pose.position.y, 111.193 - 0.5);
  EXPECT_LT(odom->pose.pose.position.y, 111.193 + 5.0 * 0.3 + 0.5);
  EXPECT_DOUBLE_EQ(odom->pose.covariance[0], 9.0);
  EXPECT_NEAR(odom->twist.twist.linear.x, 4.924, 1e-3);
  EXPECT_NEAR(odom->twist.twist.linear.y, 0.868, 1e-3);
  EXPECT_NEAR(2.0 * std::atan2(odom->pose.pose.orientation.z, odom->pose.pose.orientation.w),
              80.0 * M_PI / 180.0, 1e-6);
  EXPECT_EQ(odom->child_frame_id, "navsat_own/base_link");

  const auto chain =
      tf_buffer.lookupTransform("map", "navsat_own/base_link", odom->header.stamp, ros::Duration(1.0));
  EXPECT_NEAR(chain.transform.translation.x, odom->pose.pose.position.x, 1e-6);
  EXPECT_NEAR(chain.transform.translation.y, odom->pose.pose.position.y, 1e-6);
  const auto map_odom = tf_buffer.lookupTransform("map", "navsat_odom", odom->header.stamp);
  EXPECT_NEAR(map_odom.transform.translation.x, 0.0, 0.5);
  EXPECT_LT(map_odom.transform.translation.y, -8.0) << "the fixes' corrections are in map -> odom";
  EXPECT_GT(map_odom.transform.translation.y, -16.0);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_own_ship_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
