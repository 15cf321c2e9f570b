// rostest: one ship seen by the radar (a TTM on nmea_in, placed by arpa_node from the own odometry)
// and by AIS (a report on ais/targets) becomes one FUSED track on targets. Expectations by hand:
//  - own ship at (100, -50 - v t) heading east (ENU yaw 0 = nautical heading 90 deg), where
//    v = 10 kn and t is the time since the start: it keeps station with the target, so the radar
//    geometry stays constant while every report stays consistent with the velocities;
//  - TTM target 3: 1.00 nm at relative bearing 315 deg = true bearing 45 deg, 10 kn on true course
//    180 deg: at (100 + 1852 sin 45, -50 - v t + 1852 cos 45) = (1409.563, 1259.563 - v t), velocity
//    (0, -5.1444);
//  - AIS MMSI 244000123 "FUSE ME" 11.2 m away at (1419.563, 1254.563 - v t), same velocity: inside the
//    200 m gate and the 2.5 m/s velocity gate, so one track with both identities, named from AIS,
//    positioned between the two and much nearer the AIS fix (10 m against the radar's 30 m+).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include <asv_core/codec/nmea_encode.h>
#include <asv_msgs/NmeaSentence.h>
#include <asv_msgs/TargetArray.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

namespace {

constexpr double kKn = 1852.0 / 3600.0;
const double kR = 1852.0 * std::sqrt(0.5);  // 1 nm along 45 deg, per axis

class TrackerFusionTest : public ::testing::Test {
protected:
  void SetUp() override {
    odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", 10);
    nmea_pub_ = nh_.advertise<asv_msgs::NmeaSentence>("nmea_in", 10);
    ais_pub_ = nh_.advertise<asv_msgs::TargetArray>("ais/targets", 10);
    arpa_sub_ = nh_.subscribe("arpa/targets", 10, &TrackerFusionTest::arpaCb, this);
    tracks_sub_ = nh_.subscribe("targets", 10, &TrackerFusionTest::tracksCb, this);
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
    while (ros::ok() && ros::WallTime::now() < deadline &&
           (odom_pub_.getNumSubscribers() == 0 || nmea_pub_.getNumSubscribers() == 0 ||
            ais_pub_.getNumSubscribers() == 0 || tracks_sub_.getNumPublishers() == 0))
      ros::WallDuration(0.05).sleep();
    ASSERT_GT(ais_pub_.getNumSubscribers(), 0u) << "tracker is not up";
    ASSERT_GT(nmea_pub_.getNumSubscribers(), 0u) << "arpa_node is not up";
  }

  void arpaCb(const asv_msgs::TargetArray::ConstPtr& m) {
    for (const auto& t : m->targets)
      if (t.arpa_number == 3)
        arpa_ = t;
  }
  void tracksCb(const asv_msgs::TargetArray::ConstPtr& m) {
    for (const auto& t : m->targets)
      if (t.source == asv_msgs::Target::SOURCE_FUSED)
        fused_ = m;
  }

  double drift(const ros::Time& t) const { return -10.0 * kKn * (t - t0_).toSec(); }

  void sendAll() {
    const ros::Time now = ros::Time::now();
    if (t0_.isZero())
      t0_ = now;
    nav_msgs::Odometry o;
    o.header.stamp = now;
    o.header.frame_id = "map";
    o.child_frame_id = "own/base_link";
    o.pose.pose.position.x = 100.0;
    o.pose.pose.position.y = -50.0 + drift(now);
    o.pose.pose.orientation.w = 1.0;  // yaw 0: heading east
    o.twist.twist.linear.x = 3.0;
    odom_pub_.publish(o);
    ros::WallDuration(0.05).sleep();

    asv_msgs::NmeaSentence s;
    s.header.stamp = now;
    s.header.frame_id = "radar";
    s.sentence = asv::nmea::withChecksum('$', "RATTM,03,1.00,315.0,R,10.0,180.0,T,,,N,TGT3,T,,,A");
    s.source = "test";
    nmea_pub_.publish(s);

    asv_msgs::TargetArray a;
    a.header.stamp = now;
    a.header.frame_id = "map";
    asv_msgs::Target t;
    t.id = "ais:244000123";
    t.source = asv_msgs::Target::SOURCE_AIS;
    t.ais_class = asv_msgs::Target::AIS_CLASS_A;
    t.mmsi = 244000123;
    t.name = "FUSE ME";
    t.position.x = 100.0 + kR + 10.0;
    t.position.y = -50.0 + kR - 5.0 + drift(now);
    t.course_over_ground = M_PI;
    t.speed_over_ground = 10.0 * kKn;
    t.velocity.y = -10.0 * kKn;
    t.position_covariance = {100.0, 0.0, 0.0, 100.0};
    t.quality = 100;
    t.stamp = now;
    a.targets.push_back(t);
    ais_pub_.publish(a);
  }

  ros::NodeHandle nh_;
  ros::Publisher odom_pub_, nmea_pub_, ais_pub_;
  ros::Subscriber arpa_sub_, tracks_sub_;
  std::optional<asv_msgs::Target> arpa_;
  asv_msgs::TargetArray::ConstPtr fused_;
  ros::Time t0_;
};

TEST_F(TrackerFusionTest, AisAndArpaOfOneShipBecomeOneFusedTrack) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(15.0);
  while (ros::ok() && ros::WallTime::now() < deadline && !(fused_ && arpa_)) {
    sendAll();
    const ros::WallTime next = ros::WallTime::now() + ros::WallDuration(0.25);
    while (ros::WallTime::now() < next) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
  }
  ASSERT_TRUE(arpa_) << "arpa_node published no target 3";
  EXPECT_EQ(arpa_->id, "arpa:3");
  EXPECT_EQ(arpa_->source, asv_msgs::Target::SOURCE_ARPA);
  EXPECT_NEAR(arpa_->position.x, 100.0 + kR, 0.01);
  EXPECT_NEAR(arpa_->position.y, -50.0 + kR + drift(arpa_->stamp), 0.01);
  EXPECT_NEAR(arpa_->speed_over_ground, 10.0 * kKn, 1e-9);
  EXPECT_NEAR(arpa_->course_over_ground, M_PI, 1e-9);
  EXPECT_NEAR(arpa_->velocity.y, -10.0 * kKn, 1e-9);
  EXPECT_EQ(arpa_->name, "TGT3");

  ASSERT_TRUE(fused_) << "no FUSED track on targets";
  EXPECT_EQ(fused_->header.frame_id, "map");
  ASSERT_EQ(fused_->targets.size(), 1u) << "AIS and ARPA of one ship must be one track";
  const asv_msgs::Target& t = fused_->targets[0];
  EXPECT_EQ(t.mmsi, 244000123u);
  EXPECT_EQ(t.arpa_number, 3);
  EXPECT_EQ(t.name, "FUSE ME");
  EXPECT_EQ(t.ais_class, asv_msgs::Target::AIS_CLASS_A);
  EXPECT_EQ(t.quality, 100);
  EXPECT_LT(t.age, 2.0);
  EXPECT_NEAR(t.speed_over_ground, 10.0 * kKn, 0.1);
  EXPECT_NEAR(t.course_over_ground, M_PI, 0.05);
  // Dead-reckoned to the array stamp from the last report: compare at the report time.
  const double dt = (fused_->header.stamp - t.stamp).toSec();
  const double x = t.position.x - t.velocity.x * dt, y = t.position.y - t.velocity.y * dt;
  const double to_ais = std::hypot(x - (100.0 + kR + 10.0), y - (-50.0 + kR - 5.0 + drift(t.stamp)));
  const double to_arpa = std::hypot(x - (100.0 + kR), y - (-50.0 + kR + drift(t.stamp)));
  EXPECT_LT(to_ais, to_arpa);
  EXPECT_LT(to_ais, 5.0);
  EXPECT_GT(t.position_covariance[0], 0.0);
  EXPECT_LE(t.position_covariance[0], 100.0 + 1.0);  // no worse than the AIS fix alone (plus dead reckoning)
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_tracker_fusion");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
