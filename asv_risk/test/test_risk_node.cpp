// rostest: risk_node fed a scripted own ship and targets. Expected values by hand:
//  - own ship at (0, 6 t) heading north at 6 m/s;
//  - ts1 from the port side at (-6000 + 6 t, 6000) heading east at 6 m/s: both reach (0, 6000) at
//    t = 1000 s, so TCPA = 1000 - t, DCPA = 0. It is the give-way vessel (Rule 15) but does not act:
//    risk 1 while TCPA > t_safe (600 s), then 2, which flags it non-compliant (Hu et al. Algorithm 1);
//  - ts2 head-on 15 km ahead heading south at 6 m/s at t = 0: TCPA = 15000 / 12 = 1250 s > t_max
//    (1200 s), so risk 0, encounter head-on;
//  - three bad targets every time (NaN position, a duplicated id, a stamp 60 s in the future) are
//    rejected and counted, and the valid ones still come through;
//  - the targets stop coming (the tracker down) while the odometry goes on: after watch/input_timeout
//    (1.5 s) plus one check (0.25 s), an ERROR alarm names /targets and `risk` goes on with data_ok false
//    and the last picture, never an empty, clear sea; the targets back, the alarm clears.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <asv_msgs/Alarm.h>
#include <asv_msgs/RiskAssessment.h>
#include <asv_msgs/TargetArray.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

namespace {

class RiskNodeTest : public ::testing::Test {
protected:
  void SetUp() override {
    odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", 10);
    targets_pub_ = nh_.advertise<asv_msgs::TargetArray>("targets", 10);
    risk_sub_ = nh_.subscribe("risk", 10, &RiskNodeTest::riskCb, this);
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
    while ((odom_pub_.getNumSubscribers() == 0 || targets_pub_.getNumSubscribers() == 0 ||
            risk_sub_.getNumPublishers() == 0) &&
           ros::WallTime::now() < deadline)
      ros::WallDuration(0.05).sleep();
    ASSERT_GT(targets_pub_.getNumSubscribers(), 0u) << "risk_node did not subscribe";
  }

  void riskCb(const asv_msgs::RiskAssessment::ConstPtr& m) { last_ = m; }

  asv_msgs::Target target(const std::string& id, double x, double y, double course_deg, double speed) {
    asv_msgs::Target t;
    t.id = id;
    t.source = asv_msgs::Target::SOURCE_AIS;
    t.position.x = x;
    t.position.y = y;
    t.course_over_ground = course_deg * M_PI / 180.0;
    t.speed_over_ground = speed;
    t.stamp = ros::Time::now();
    return t;
  }

  void publishOdom(double t) {
    nav_msgs::Odometry o;
    o.header.stamp = ros::Time::now();
    o.header.frame_id = "map";
    o.child_frame_id = "own/base_link";
    o.pose.pose.position.y = 6.0 * t;
    o.pose.pose.orientation.z = std::sin(M_PI / 4);  // ENU yaw 90 deg = heading north
    o.pose.pose.orientation.w = std::cos(M_PI / 4);
    o.twist.twist.linear.x = 6.0;
    odom_pub_.publish(o);
  }

  // Publishes the situation at scripted time t and waits for the assessment of exactly this update.
  asv_msgs::RiskAssessment::ConstPtr step(double t) {
    publishOdom(t);
    ros::WallDuration(0.1).sleep();

    asv_msgs::TargetArray arr;
    arr.header.frame_id = "map";
    arr.header.stamp = ros::Time::now();
    arr.targets.push_back(target("ts1", -6000.0 + 6.0 * t, 6000.0, 90.0, 6.0));
    if (t == 0.0)
      arr.targets.push_back(target("ts2", 0.0, 15000.0, 180.0, 6.0));
    arr.targets.push_back(target("nan", std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 1.0));
    arr.targets.push_back(target("ts1", 0.0, 0.0, 0.0, 1.0));  // duplicate id
    asv_msgs::Target fut = target("future", 100.0, 100.0, 0.0, 1.0);
    fut.stamp = ros::Time::now() + ros::Duration(60.0);
    arr.targets.push_back(fut);
    last_.reset();
    targets_pub_.publish(arr);
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      ros::spinOnce();
      if (last_ && last_->header.stamp == arr.header.stamp)
        return last_;
      ros::WallDuration(0.01).sleep();
    }
    return nullptr;
  }

  static const asv_msgs::TargetRisk* find(const asv_msgs::RiskAssessment& ra, const std::string& id) {
    for (const auto& t : ra.targets)
      if (t.target_id == id)
        return &t;
    return nullptr;
  }

  ros::NodeHandle nh_;
  ros::Publisher odom_pub_, targets_pub_;
  ros::Subscriber risk_sub_;
  asv_msgs::RiskAssessment::ConstPtr last_;
};

TEST_F(RiskNodeTest, NonCompliantGiveWayTargetIsFlaggedWhenRiskBecomesUrgent) {
  using TR = asv_msgs::TargetRisk;
  // t = 0: risk 1 for ts1, head-on ts2 at risk 0.
  auto ra = step(0.0);
  ASSERT_TRUE(ra) << "no /risk for the first update";
  EXPECT_EQ(ra->header.frame_id, "map");
  EXPECT_EQ(ra->rejected_targets, 3u);
  ASSERT_EQ(ra->targets.size(), 2u);
  const TR* ts1 = find(*ra, "ts1");
  const TR* ts2 = find(*ra, "ts2");
  ASSERT_TRUE(ts1 && ts2);
  EXPECT_NEAR(ts1->tcpa, 1000.0, 1e-6);
  EXPECT_NEAR(ts1->dcpa, 0.0, 1e-6);
  EXPECT_NEAR(ts1->range, std::hypot(6000.0, 6000.0), 1e-6);
  EXPECT_EQ(ts1->encounter, TR::ENCOUNTER_CROSSING);
  EXPECT_EQ(ts1->own_role, TR::ROLE_STAND_ON);
  EXPECT_EQ(ts1->risk_level, TR::RISK_COLLISION);
  EXPECT_TRUE(ts1->compliant);
  EXPECT_EQ(ts1->decision, TR::DECISION_RULE_APPLIES);
  EXPECT_EQ(ts1->applicable_rule, 17);
  EXPECT_NEAR(ts2->tcpa, 1250.0, 1e-6);
  EXPECT_EQ(ts2->encounter, TR::ENCOUNTER_HEAD_ON);
  EXPECT_EQ(ts2->own_role, TR::ROLE_GIVE_WAY);
  EXPECT_EQ(ts2->risk_level, TR::RISK_NONE);
  EXPECT_EQ(ra->max_risk_level, TR::RISK_COLLISION);

  // t = 300: TCPA 700 s, still risk 1.
  ra = step(300.0);
  ASSERT_TRUE(ra);
  ts1 = find(*ra, "ts1");
  ASSERT_TRUE(ts1);
  EXPECT_NEAR(ts1->tcpa, 700.0, 1e-6);
  EXPECT_EQ(ts1->risk_level, TR::RISK_COLLISION);
  EXPECT_TRUE(ts1->compliant);

  // t = 450: TCPA 550 s < t_safe: urgent, and the target that should have given way is flagged.
  ra = step(450.0);
  ASSERT_TRUE(ra);
  ts1 = find(*ra, "ts1");
  ASSERT_TRUE(ts1);
  EXPECT_NEAR(ts1->tcpa, 550.0, 1e-6);
  EXPECT_EQ(ts1->risk_level, TR::RISK_URGENT);
  EXPECT_FALSE(ts1->compliant);
  EXPECT_EQ(ts1->decision, TR::DECISION_RULE_2);
  EXPECT_EQ(ts1->applicable_rule, 2);
  EXPECT_GT(ts1->cri, 0.6);

  // t = 600: still urgent, the flag stays.
  ra = step(600.0);
  ASSERT_TRUE(ra);
  ts1 = find(*ra, "ts1");
  ASSERT_TRUE(ts1);
  EXPECT_EQ(ts1->risk_level, TR::RISK_URGENT);
  EXPECT_FALSE(ts1->compliant);
  EXPECT_EQ(ra->rejected_targets, 3u);
  for (const auto& t : ra->targets)
    for (double v : {t.tcpa, t.dcpa, t.cri, t.range, t.bearing, t.safe_distance_d1, t.safe_distance_d2})
      EXPECT_TRUE(std::isfinite(v));
}

TEST_F(RiskNodeTest, AStoppedTrackerIsAnAlarmAndNeverAClearSea) {
  std::vector<asv_msgs::Alarm::ConstPtr> alarms;
  std::vector<asv_msgs::RiskAssessment::ConstPtr> risks;
  ros::Subscriber a = nh_.subscribe<asv_msgs::Alarm>(
      "alarms", 50, [&](const asv_msgs::Alarm::ConstPtr& m) { alarms.push_back(m); });
  ros::Subscriber r = nh_.subscribe<asv_msgs::RiskAssessment>(
      "risk", 50, [&](const asv_msgs::RiskAssessment::ConstPtr& m) { risks.push_back(m); });
  auto ra = step(0.0);
  ASSERT_TRUE(ra);
  EXPECT_TRUE(ra->data_ok) << ra->data_fault;
  EXPECT_GE(ra->targets_age, 0.0);
  EXPECT_LT(ra->targets_age, 0.5);
  EXPECT_GE(ra->odom_age, 0.0);
  EXPECT_LT(ra->odom_age, 1.0);
  // 3 s without targets, the own ship still reporting.
  risks.clear();
  const ros::WallTime stopped = ros::WallTime::now();
  while (ros::WallTime::now() - stopped < ros::WallDuration(3.0)) {
    publishOdom(0.0);
    ros::WallDuration(0.1).sleep();
    ros::spinOnce();
  }
  const asv_msgs::RiskAssessment* flagged = nullptr;
  for (const auto& m : risks)
    if (!m->data_ok && !flagged)
      flagged = m.get();
  ASSERT_TRUE(flagged) << "no risk with data_ok false in 3 s without targets";
  EXPECT_NE(flagged->data_fault.find("/targets: none for"), std::string::npos) << flagged->data_fault;
  EXPECT_GT(flagged->targets_age, 1.5);
  EXPECT_LT(flagged->targets_age, 2.5);
  EXPECT_EQ(flagged->targets.size(), 2u);  // the last picture (ts1, ts2), not an empty sea
  const asv_msgs::Alarm* raised = nullptr;
  for (const auto& m : alarms)
    if (m->level == asv_msgs::Alarm::ERROR && !raised)
      raised = m.get();
  ASSERT_TRUE(raised) << "no alarm";
  EXPECT_EQ(raised->source, "/risk_node");
  ASSERT_EQ(raised->inputs.size(), 1u);
  EXPECT_EQ(raised->inputs[0], "/targets");
  // The targets back: a fresh assessment, and the alarm clears.
  ra = step(1.0);
  ASSERT_TRUE(ra);
  EXPECT_TRUE(ra->data_ok) << ra->data_fault;
  const ros::WallTime back = ros::WallTime::now();
  while (ros::WallTime::now() - back < ros::WallDuration(1.0) &&
         alarms.back()->level != asv_msgs::Alarm::OK) {
    ros::WallDuration(0.05).sleep();
    ros::spinOnce();
  }
  EXPECT_EQ(alarms.back()->level, asv_msgs::Alarm::OK);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_risk_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
