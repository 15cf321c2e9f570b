#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include <asv_core/common/units.h>

#include "asv_ros/conversions.h"

using namespace asv_ros;

TEST(Conversions, OdometryYawAndBodyTwistBecomeCourseOverGround) {
  nav_msgs::Odometry o;
  // ENU yaw 0 (heading east, course 090), moving 3 m/s ahead and 4 m/s to the left (north).
  o.pose.pose.orientation.w = 1.0;
  o.pose.pose.position.x = 10.0;
  o.twist.twist.linear.x = 3.0;
  o.twist.twist.linear.y = 4.0;
  asv::ShipState s;
  ASSERT_EQ(odometryToShipState(o, "own", s), Reject::None);
  EXPECT_NEAR(asv::radToDeg(s.heading), 90.0, 1e-9);
  EXPECT_NEAR(s.speed, 5.0, 1e-12);
  EXPECT_NEAR(asv::radToDeg(s.course), asv::radToDeg(std::atan2(3.0, 4.0)), 1e-9);  // 36.87 deg
  EXPECT_DOUBLE_EQ(s.position.x(), 10.0);
  // Yaw +90 deg (heading north): forward speed 2 m/s means course 000.
  o.pose.pose.orientation.z = std::sin(asv::kPi / 4);
  o.pose.pose.orientation.w = std::cos(asv::kPi / 4);
  o.twist.twist.linear.x = 2.0;
  o.twist.twist.linear.y = 0.0;
  ASSERT_EQ(odometryToShipState(o, "own", s), Reject::None);
  EXPECT_NEAR(asv::wrapPi(s.course), 0.0, 1e-9);
  // Stopped: the course is the heading.
  o.twist.twist.linear.x = 0.0;
  ASSERT_EQ(odometryToShipState(o, "own", s), Reject::None);
  EXPECT_NEAR(asv::wrapPi(s.course), 0.0, 1e-9);
}

TEST(Conversions, BadOdometryIsRejected) {
  nav_msgs::Odometry o;
  o.pose.pose.orientation.w = 1.0;
  o.pose.pose.position.y = std::numeric_limits<double>::quiet_NaN();
  asv::ShipState s;
  EXPECT_EQ(odometryToShipState(o, "own", s), Reject::NonFinite);
  o.pose.pose.position.y = 0.0;
  o.pose.pose.orientation.w = 0.0;  // zero quaternion
  EXPECT_EQ(odometryToShipState(o, "own", s), Reject::Impossible);
}

TEST(Conversions, TargetChecks) {
  asv_msgs::Target t;
  t.id = "ais:1";
  t.position.x = 100;
  t.course_over_ground = asv::degToRad(270.0);
  t.speed_over_ground = 5.0;
  asv::ShipState s;
  ASSERT_EQ(targetToShipState(t, s), Reject::None);
  EXPECT_DOUBLE_EQ(s.heading, s.course);  // no heading: course stands in
  t.has_heading = true;
  t.heading = asv::degToRad(265.0);
  ASSERT_EQ(targetToShipState(t, s), Reject::None);
  EXPECT_NEAR(asv::radToDeg(s.heading), 265.0, 1e-9);
  t.heading = std::numeric_limits<double>::infinity();
  EXPECT_EQ(targetToShipState(t, s), Reject::NonFinite);
  t.has_heading = false;
  t.speed_over_ground = 60.0;  // 117 kn
  EXPECT_EQ(targetToShipState(t, s), Reject::Impossible);
  t.speed_over_ground = -1.0;
  EXPECT_EQ(targetToShipState(t, s), Reject::Impossible);
  t.speed_over_ground = 5.0;
  t.id.clear();
  EXPECT_EQ(targetToShipState(t, s), Reject::EmptyId);
}

TEST(Conversions, RiskMessageCarriesTheCoreResult) {
  asv::RiskAssessor a;
  asv::ShipState own, tgt;
  own.speed = 5.0;
  tgt.id = "t";
  tgt.position = {0, 5000};
  tgt.course = tgt.heading = asv::kPi;
  tgt.speed = 5.0;
  const asv_msgs::TargetRisk m = toMsg(a.assess(own, tgt), 123);
  EXPECT_EQ(m.target_id, "t");
  EXPECT_EQ(m.mmsi, 123u);
  EXPECT_NEAR(m.tcpa, 500.0, 1e-9);
  EXPECT_EQ(m.encounter, asv_msgs::TargetRisk::ENCOUNTER_HEAD_ON);
  EXPECT_EQ(m.own_role, asv_msgs::TargetRisk::ROLE_GIVE_WAY);  // head-on: each ship gives way
  EXPECT_EQ(m.applicable_rule, 14);
  EXPECT_EQ(m.risk_level, asv_msgs::TargetRisk::RISK_URGENT);  // 500 s, 0 m: within t_safe, d_safe
  // planner_node reads the same message back as the planners' risk fields.
  asv::PlannerTarget pt;
  EXPECT_TRUE(riskFromMsg(m, pt));
  EXPECT_EQ(pt.risk, asv::RiskLevel::Urgent);
  EXPECT_EQ(pt.encounter, asv::Encounter::HeadOn);
  EXPECT_EQ(pt.role, asv::OwnRole::BothGiveWay);
  EXPECT_TRUE(pt.compliant);
  EXPECT_NEAR(pt.tcpa, 500.0, 1e-9);
  EXPECT_NEAR(pt.dcpa, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(pt.cri, m.cri);
}

// A GNSS driver's messages (own_ship_node's navsat input), by hand.
TEST(Conversions, NavSatFixStatusAndCovarianceBecomeQualityAndSigma) {
  sensor_msgs::NavSatFix m;
  m.latitude = 48.1173;
  m.longitude = 11.5;
  m.status.status = sensor_msgs::NavSatStatus::STATUS_SBAS_FIX;
  m.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN;
  m.position_covariance[0] = 4.0;  // east variance
  m.position_covariance[4] = 9.0;  // north: the larger, 1-sigma 3 m
  asv::gnss::Fix f;
  std::string why;
  ASSERT_TRUE(asv_ros::navSatToFix(m, f, why));
  EXPECT_EQ(f.quality, asv::gnss::Quality::kDifferential);
  ASSERT_TRUE(f.sigma);
  EXPECT_DOUBLE_EQ(*f.sigma, 3.0);
  m.status.status = sensor_msgs::NavSatStatus::STATUS_FIX;
  m.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN;
  ASSERT_TRUE(asv_ros::navSatToFix(m, f, why));
  EXPECT_EQ(f.quality, asv::gnss::Quality::kGnss);
  EXPECT_FALSE(f.sigma);  // the fix type's error then applies
  m.status.status = sensor_msgs::NavSatStatus::STATUS_NO_FIX;
  EXPECT_FALSE(asv_ros::navSatToFix(m, f, why));
  EXPECT_EQ(why, "NavSatFix: no fix (status -1)");
  m.status.status = sensor_msgs::NavSatStatus::STATUS_FIX;
  m.latitude = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(asv_ros::navSatToFix(m, f, why));
  EXPECT_EQ(why, "NavSatFix: no position");
}

TEST(Conversions, EnuVelocityAndOrientationBecomeCourseSpeedAndHeading) {
  geometry_msgs::TwistStamped v;
  v.twist.linear.x = -3.0;  // west
  v.twist.linear.y = -4.0;  // south: course 216.87 (180 + atan(3/4)), speed 5
  asv::gnss::Motion m;
  ASSERT_TRUE(asv_ros::enuTwistToMotion(v, m));
  EXPECT_NEAR(asv::radToDeg(*m.course), 216.8699, 1e-4);
  EXPECT_DOUBLE_EQ(*m.speed, 5.0);
  v.twist.linear.x = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(asv_ros::enuTwistToMotion(v, m));
  geometry_msgs::QuaternionStamped q;  // ENU yaw 30 deg (about z): heading 060
  q.quaternion.z = std::sin(asv::degToRad(15.0));
  q.quaternion.w = std::cos(asv::degToRad(15.0));
  double h = 0.0;
  ASSERT_TRUE(asv_ros::orientationToHeading(q, false, h));
  EXPECT_NEAR(asv::radToDeg(h), 60.0, 1e-9);
  ASSERT_TRUE(asv_ros::orientationToHeading(q, true, h));  // nmea_navsat_driver: the yaw is HDT itself
  EXPECT_NEAR(asv::radToDeg(h), 30.0, 1e-9);
  q.quaternion.w = 0.0;
  q.quaternion.z = 0.0;  // the zero quaternion is no rotation
  EXPECT_FALSE(asv_ros::orientationToHeading(q, false, h));
}

// One vocabulary: the message says crossing and the side as the role, head-on give way; the planners'
// five encounters come back from the pair.
TEST(Conversions, EncounterAndRoleRoundTripThroughTheMessage) {
  using TR = asv_msgs::TargetRisk;
  using asv::Encounter;
  const std::vector<std::tuple<Encounter, uint8_t, uint8_t>> cases{
      {Encounter::None, TR::ENCOUNTER_NONE, TR::ROLE_NONE},
      {Encounter::HeadOn, TR::ENCOUNTER_HEAD_ON, TR::ROLE_GIVE_WAY},
      {Encounter::CrossingGiveWay, TR::ENCOUNTER_CROSSING, TR::ROLE_GIVE_WAY},
      {Encounter::CrossingStandOn, TR::ENCOUNTER_CROSSING, TR::ROLE_STAND_ON},
      {Encounter::Overtaking, TR::ENCOUNTER_OVERTAKING, TR::ROLE_GIVE_WAY},
      {Encounter::BeingOvertaken, TR::ENCOUNTER_BEING_OVERTAKEN, TR::ROLE_STAND_ON}};
  for (const auto& [e, msg_encounter, msg_role] : cases) {
    SCOPED_TRACE(asv::toString(e));
    EXPECT_EQ(encounterToMsg(e), msg_encounter);
    EXPECT_EQ(roleToMsg(asv::ownRole(e)), msg_role);
    EXPECT_EQ(encounterFromMsg(msg_encounter, msg_role), e);
  }
  EXPECT_EQ(encounterFromMsg(99, TR::ROLE_NONE), Encounter::None);  // a value from a newer message: none
  TR unknown;
  unknown.encounter = 99;
  unknown.risk_level = TR::RISK_URGENT;
  asv::PlannerTarget pt;
  EXPECT_FALSE(riskFromMsg(unknown, pt));      // said, not silent
  EXPECT_EQ(pt.risk, asv::RiskLevel::Urgent);  // and the risk still counts
}
