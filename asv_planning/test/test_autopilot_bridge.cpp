// rostest: autopilot_bridge heard by a UDP listener that decodes what it receives. Expected values by
// hand (map origin 54.6 N 18.8 E, as test/autopilot_bridge.test sets it):
//  - disarmed at start: nothing is sent, whatever comes in;
//  - armed, set-point 090 with the ship at (0, 0): the leg runs east from there. The ship then at
//    (1000, 100), 100 m left of it: cross-track 100 m = 0.054 nm, steer right; destination 1852 m ahead
//    of her foot point, (2852, 0), bearing atan2(1852, -100) = 93.1 deg. Its position: 2852 m east of
//    the origin on the WGS84 ellipsoid, N = a / sqrt(1 - e^2 sin^2(54.6 deg)) = 6392373 m, so
//    2852 / (N cos 54.6 deg) = 0.044129 deg = 2.6477' east: 54 36.0000' N, 018 50.6477' E (the map
//    plane's east is a great circle, 0.9 m = 0.0005' south of the parallel at 2852 m: within tolerance);
//  - five ticks a second (rate 5) although set-points come at 20 Hz;
//  - set-points stop (input_timeout 1 s, safe_action invalidate): APB, RMB and XTE with status V and mode
//    N, no HSC, and an ERROR alarm naming the set-point;
//  - disarmed again: nothing.
//  - a route on active_route (latched, map): from (0, 0), where the ship is when it comes, to WP001
//    3000 m east. The ship at (1000, 100) on set-point 108.4, the follower's line of sight to 300 m
//    ahead of her abeam point (atan2(300, -100) = 108.4): the route's leg, WP000 -> WP001, bearing
//    090.0, cross-track 0.054 nm steer right, WP001 bearing atan2(2000, -100) = 92.9 at 2002 m = 1.08
//    nm, heading to steer the set-point 108.4; RMB's destination 3000 m east: 3000 / (N cos 54.6 deg) =
//    0.046419 deg = 2.7851' east, 018 50.7851' E.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <asv_core/codec/nmea.h>
#include <asv_msgs/Alarm.h>
#include <asv_msgs/CourseSpeedSetpoint.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>

namespace {

class BridgeTest : public ::testing::Test {
protected:
  void SetUp() override {
    fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
    ASSERT_GE(fd_, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(10191);
    ::inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
    ASSERT_EQ(::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
    timeval tv{0, 20000};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    cmd_ = nh_.advertise<asv_msgs::CourseSpeedSetpoint>("cmd", 10);
    odom_ = nh_.advertise<nav_msgs::Odometry>("odom", 10);
    alarms_ = nh_.subscribe<asv_msgs::Alarm>("alarms", 20,
                                             [this](const asv_msgs::Alarm::ConstPtr& m) { alarm_ = m; });
    ASSERT_TRUE(ros::service::waitForService("/autopilot_bridge/arm", ros::Duration(20.0)));
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
    while ((cmd_.getNumSubscribers() == 0 || odom_.getNumSubscribers() == 0) &&
           ros::WallTime::now() < deadline)
      ros::WallDuration(0.05).sleep();
  }
  void TearDown() override { ::close(fd_); }

  // Feeds odometry at (x, y) heading east at 5 m/s (and the set-point 090 when `cmd`) at 20 Hz for
  // `seconds`, returning the sentences received meanwhile.
  std::vector<std::string> run(double x, double y, bool cmd, double seconds, double course_deg = 90.0) {
    std::vector<std::string> got;
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::WallTime::now() < end) {
      nav_msgs::Odometry o;
      o.header.stamp = ros::Time::now();
      o.header.frame_id = "map";
      o.pose.pose.position.x = x;
      o.pose.pose.position.y = y;
      o.pose.pose.orientation.w = 1.0;  // ENU yaw 0: heading east
      o.twist.twist.linear.x = 5.0;
      odom_.publish(o);
      if (cmd) {
        asv_msgs::CourseSpeedSetpoint c;
        c.header.stamp = ros::Time::now();
        c.course = course_deg * M_PI / 180.0;
        c.speed = 5.0;
        cmd_.publish(c);
      }
      char buf[1024];
      for (ssize_t n; (n = ::recv(fd_, buf, sizeof buf, 0)) > 0;) {
        std::string d(buf, static_cast<size_t>(n));
        EXPECT_EQ(d.substr(d.size() - 2), "\r\n");
        got.push_back(d.substr(0, d.size() - 2));
      }
      ros::spinOnce();
    }
    return got;
  }

  static std::vector<std::string> fields(const std::string& sentence) {
    asv::nmea::Sentence s;
    EXPECT_EQ(asv::nmea::parseSentence(sentence, s), asv::nmea::Reject::kNone) << sentence;
    return std::vector<std::string>(s.fields.begin(), s.fields.begin() + s.field_count);
  }
  // APB's fields by number (0 is the address): 1 status, 3 cross-track [nm], 4 steer L/R, 8 bearing
  // origin to destination, 10 destination, 11 bearing to it, 13 heading to steer, 15 mode.
  static void expectFields(const std::vector<std::string>& got, const std::map<size_t, std::string>& want) {
    for (const auto& [i, v] : want) {
      ASSERT_LT(i, got.size());
      EXPECT_EQ(got[i], v) << "field " << i;
    }
  }
  static std::vector<std::string> ofType(const std::vector<std::string>& got, const std::string& type) {
    std::vector<std::string> out;
    for (const auto& g : got)
      if (g.size() > 6 && g.substr(3, 3) == type)
        out.push_back(g);
    return out;
  }
  static bool arm(bool on) {
    std_srvs::SetBool s;
    s.request.data = on;
    return ros::service::call("/autopilot_bridge/arm", s) && s.response.success;
  }

  ros::NodeHandle nh_;
  ros::Publisher cmd_, odom_;
  ros::Subscriber alarms_;
  asv_msgs::Alarm::ConstPtr alarm_;
  int fd_ = -1;
};

TEST_F(BridgeTest, ArmedSetpointsBecomeTheSentencesAnAutopilotSteersBy) {
  EXPECT_TRUE(run(0.0, 0.0, true, 1.0).empty()) << "sentences sent while disarmed";
  ASSERT_TRUE(arm(true));
  run(0.0, 0.0, true, 0.6);  // the leg starts here
  const std::vector<std::string> got = run(1000.0, 100.0, true, 2.0);
  const auto apb = ofType(got, "APB"), hsc = ofType(got, "HSC");
  ASSERT_GE(apb.size(), 5u);
  EXPECT_GE(apb.size(), 8u);  // rate 5 Hz over 2 s, set-points at 20 Hz
  EXPECT_LE(apb.size(), 11u);
  expectFields(fields(apb.back()),
               {{1, "A"}, {3, "0.054"}, {4, "R"}, {8, "90.0"}, {11, "93.1"}, {13, "93.1"}, {15, "A"}});
  EXPECT_EQ(ofType(got, "XTE").back(), "$ECXTE,A,A,0.054,R,N,A*3D");
  EXPECT_EQ(hsc.back(), "$ECHSC,93.1,T,,M*52");
  const auto r = fields(ofType(got, "RMB").back());
  ASSERT_GE(r.size(), 15u);
  EXPECT_EQ(r[6].substr(0, 2), "54");
  EXPECT_NEAR(std::stod(std::string(r[6].substr(2))), 36.0, 0.001);  // 0.0005' south: the map plane's east
  EXPECT_EQ(r[7], "N");
  EXPECT_EQ(r[8].substr(0, 5), "01850");
  EXPECT_NEAR(std::stod(std::string(r[8].substr(3))), 50.6477, 0.002);
  EXPECT_EQ(r[9], "E");

  // The set-points stop: invalid within the 1 s timeout and a tick, with an alarm.
  const std::vector<std::string> lost = run(1000.0, 100.0, false, 2.0);
  const auto apb_lost = ofType(lost, "APB");
  ASSERT_FALSE(apb_lost.empty());
  const auto v = fields(apb_lost.back());
  EXPECT_EQ(v[1], "V");
  EXPECT_EQ(v[15], "N");
  EXPECT_TRUE(ofType(std::vector<std::string>(lost.end() - 3, lost.end()), "HSC").empty());
  ASSERT_TRUE(alarm_);
  EXPECT_EQ(alarm_->level, asv_msgs::Alarm::ERROR);
  ASSERT_EQ(alarm_->inputs.size(), 1u);
  EXPECT_EQ(alarm_->inputs[0], "set-point");
  EXPECT_NE(alarm_->action.find("invalid"), std::string::npos) << alarm_->action;

  ASSERT_TRUE(arm(false));
  run(1000.0, 100.0, true, 0.3);  // a tick in flight
  EXPECT_TRUE(run(1000.0, 100.0, true, 1.0).empty()) << "sentences sent after disarming";
}

TEST_F(BridgeTest, ARouteInForceIsSentAsItsOwnLeg) {
  ros::Publisher route = nh_.advertise<nav_msgs::Path>("active_route", 1, true);
  run(0.0, 0.0, true, 0.5);  // the ship at (0, 0) when the route comes
  nav_msgs::Path path;
  path.header.frame_id = "map";
  path.header.stamp = ros::Time::now();
  geometry_msgs::PoseStamped wp;
  wp.pose.position.x = 3000.0;
  wp.pose.orientation.w = 1.0;
  path.poses.push_back(wp);
  route.publish(path);
  run(0.0, 0.0, true, 1.0);
  ASSERT_TRUE(arm(true));
  const std::vector<std::string> got = run(1000.0, 100.0, true, 1.5, 108.435);
  const auto apb = ofType(got, "APB");
  ASSERT_FALSE(apb.empty());
  expectFields(fields(apb.back()),
               {{3, "0.054"}, {4, "R"}, {8, "90.0"}, {10, "WP001"}, {11, "92.9"}, {13, "108.4"}});
  const auto r = fields(ofType(got, "RMB").back());
  ASSERT_GE(r.size(), 15u);
  EXPECT_EQ(r[4], "WP000");
  EXPECT_EQ(r[5], "WP001");
  EXPECT_NEAR(std::stod(std::string(r[8].substr(3))), 50.7851, 0.002);
  EXPECT_EQ(r[10], "1.1");
  ASSERT_TRUE(arm(false));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_autopilot_bridge");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
