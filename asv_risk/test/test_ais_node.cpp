// rostest: ais_node fed AIVDM sentences over UDP (~mode udp, ais_udp.test) or as raw NmeaSentence
// messages on nmea_in, as a replayed bag delivers them (~mode topic, ais_topic.test). Both give the
// same targets. The sentences are made with asv_core's encoder; expectations by hand:
//  - MMSI 244123456, class A, lat 54.61 lon 18.82 around the origin 54.60 18.80: the ENU position is
//    LocalFrame(54.60, 18.80).toLocal(54.61, 18.82), about 1290 m east (0.02 deg * 111.3 km *
//    cos 54.6) and 1113 m north (0.01 deg * 111.3 km); SOG 12.3 kn = 12.3 * 1852 / 3600 = 6.3277 m/s,
//    COG 45.0 deg, heading 44 deg; name, call sign, dimensions (100 + 20 m by 8 + 12 m), type 70 and
//    destination merged from the type 5 sent before;
//  - MMSI 338000001, class B (type 18) with SOG and COG "not available": a target with quality 40
//    (velocity unknown) and speed/course 0, never NaN;
//  - MMSI 244000999 with latitude 91 (not available): no target;
//  - garbage, a truncated sentence, a bad checksum, fill bits 7, an oversize line and binary bytes:
//    ignored, and the valid sentences still come through;
//  - the messages that are not ship targets reach their own topics: an aid to navigation (type 21)
//    on ais/aids_to_navigation, a SAR aircraft (type 9, never on ais/targets) on ais/sar_aircraft, a
//    broadcast safety text (14) on ais/safety_messages and an IMO289 weather report (8, DAC 1 FID
//    31) on ais/weather, with values converted by hand from ITU-R M.1371 and IMO SN.1/Circ.289.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <asv_core/codec/ais.h>
#include <asv_core/codec/nmea_encode.h>
#include <asv_core/common/geodesy.h>
#include <asv_msgs/AidToNavigationArray.h>
#include <asv_msgs/AisSafetyMessage.h>
#include <asv_msgs/AisWeather.h>
#include <asv_msgs/NmeaSentence.h>
#include <asv_msgs/TargetArray.h>
#include <ros/ros.h>

namespace {

constexpr double kDeg = M_PI / 180.0;

std::vector<std::string> inputLines() {
  namespace ais = asv::ais;
  std::vector<std::string> lines;
  ais::StaticVoyageData d;
  d.shipname.assign("TEST SHIP");
  d.callsign.assign("PA1234");
  d.shiptype = 70;
  d.to_bow = 100;
  d.to_stern = 20;
  d.to_port = 8;
  d.to_starboard = 12;
  d.destination.assign("ROTTERDAM");
  for (const auto& s : ais::toSentences(ais::encodeStaticVoyage(244123456, d), 'A', 3))
    lines.push_back(s);

  // Noise before the position report.
  lines.push_back("garbage \x01\x02\x03 more garbage");
  lines.push_back("!AIVDM,1,1,,A,15M6");                               // truncated
  lines.push_back("!AIVDM,1,1,,A,15M67FC000G?ufbE`FepT@3n00Sa,0*00");  // bad checksum
  lines.push_back(std::string(5000, 'A'));                             // oversize
  lines.push_back(std::string("\xff\xfe\x00\x10!!$$\x80\x00", 10));    // binary

  ais::PositionReportA a;
  a.status = 0;
  a.speed = 123;  // 12.3 kn
  a.accuracy = true;
  a.lat = ais::rawLat(54.61);
  a.lon = ais::rawLon(18.82);
  a.course = 450;  // 45.0 deg
  a.heading = 44;
  a.second = 10;
  const std::vector<std::string> pos = ais::toSentences(ais::encodePositionA(1, 244123456, a), 'A', 0);
  lines.insert(lines.end(), pos.begin(), pos.end());

  // The same report with fill bits 7: rejected.
  std::string body = pos[0].substr(1, pos[0].find('*') - 1);
  body[body.size() - 1] = '7';
  lines.push_back(asv::nmea::withChecksum('!', body));

  ais::PositionReportB b;
  b.lat = ais::rawLat(54.59);
  b.lon = ais::rawLon(18.79);
  b.speed = ais::kSpeedNotAvailable;
  b.course = ais::kCourseNotAvailable;
  for (const auto& s : ais::toSentences(ais::encodePositionB(338000001, b), 'B', 0))
    lines.push_back(s);

  ais::PositionReportA na = a;
  na.lat = ais::kLatNotAvailable;
  for (const auto& s : ais::toSentences(ais::encodePositionA(1, 244000999, na), 'A', 0))
    lines.push_back(s);
  return lines;
}

// One sentence of an `n`-bit message, zero but for the (start, width, value) fields.
std::string sentenceWith(std::size_t n,
                         const std::vector<std::tuple<std::size_t, int, std::uint32_t>>& fields) {
  std::vector<int> bits(n, 0);
  for (const auto& [start, width, value] : fields)
    for (int k = 0; k < width; ++k)
      bits[start + k] = static_cast<int>((value >> (width - 1 - k)) & 1u);
  asv::ais::BitWriter w;
  for (int b : bits)
    w.put(static_cast<std::uint32_t>(b), 1);
  return asv::ais::toSentences(w, 'A', 0, "AI", 200).front();
}

// Six-bit code of an upper-case letter or a space.
std::uint32_t sixbit(char c) {
  return c == ' ' ? 32u : static_cast<std::uint32_t>(c - '@');
}

std::vector<std::string> auxiliaryLines() {
  namespace ais = asv::ais;
  const auto lat = [](double deg) { return static_cast<std::uint32_t>(ais::rawLat(deg)); };
  const auto lon = [](double deg) { return static_cast<std::uint32_t>(ais::rawLon(deg)); };
  // Type 21: aid 992611234 "BUOY", port hand mark (24), at 54.605 N 18.81 E, real, on position.
  std::vector<std::tuple<std::size_t, int, std::uint32_t>> aid = {
      {0, 6, 21}, {8, 30, 992611234}, {38, 5, 24}, {164, 28, lon(18.81)}, {192, 27, lat(54.605)}};
  const std::string name = "BUOY";
  for (std::size_t k = 0; k < 20; ++k)
    aid.emplace_back(43 + 6 * k, 6, sixbit(k < name.size() ? name[k] : ' '));
  // Type 9: SAR aircraft 111232511 at 54.62 N 18.83 E, 300 m, 100 kn, course 90.0.
  const std::string sar = sentenceWith(168, {{0, 6, 9},
                                             {8, 30, 111232511},
                                             {38, 12, 300},
                                             {50, 10, 100},
                                             {61, 28, lon(18.83)},
                                             {89, 27, lat(54.62)},
                                             {116, 12, 900}});
  // Type 14 from 244123456: "SAFETY".
  std::vector<std::tuple<std::size_t, int, std::uint32_t>> text = {{0, 6, 14}, {8, 30, 244123456}};
  const std::string words = "SAFETY";
  for (std::size_t k = 0; k < words.size(); ++k)
    text.emplace_back(40 + 6 * k, 6, sixbit(words[k]));
  // Type 8 DAC 1 FID 31 from 2300061 at 54.615 N 18.81 E (1/1000 min): wind 17 kn from 132 deg,
  // gust 20 kn, air 1.4 degC (14), 1013 hPa (214 + 799), visibility 3.5 NM (35), water level 5.38 m
  // (1538 / 100 - 10), sea state 4 Beaufort.
  const std::string weather = sentenceWith(360, {{0, 6, 8},
                                                 {8, 30, 2300061},
                                                 {40, 10, 1},
                                                 {50, 6, 31},
                                                 {56, 25, 1128600},
                                                 {81, 24, 3276900},
                                                 {122, 7, 17},
                                                 {129, 7, 20},
                                                 {136, 9, 132},
                                                 {154, 11, 14},
                                                 {182, 9, 214},
                                                 {194, 7, 35},
                                                 {201, 12, 1538},
                                                 {322, 4, 4}});
  return {sentenceWith(272, aid), sar, sentenceWith(40 + 6 * words.size(), text), weather};
}

class AisNodeTest : public ::testing::Test {
protected:
  void SetUp() override {
    ros::NodeHandle("~").param<std::string>("mode", mode_, "udp");
    targets_sub_ = nh_.subscribe("ais/targets", 100, &AisNodeTest::targetsCb, this);
    aids_sub_ = nh_.subscribe<asv_msgs::AidToNavigationArray>(
        "ais/aids_to_navigation", 10,
        [this](const asv_msgs::AidToNavigationArray::ConstPtr& m) { aids_ = *m; });
    sar_sub_ = nh_.subscribe<asv_msgs::TargetArray>("ais/sar_aircraft", 10,
                                                    [this](const asv_msgs::TargetArray::ConstPtr& m) {
                                                      for (const auto& t : m->targets)
                                                        sar_[t.mmsi] = t;
                                                    });
    safety_sub_ = nh_.subscribe<asv_msgs::AisSafetyMessage>(
        "ais/safety_messages", 10, [this](const asv_msgs::AisSafetyMessage::ConstPtr& m) { safety_ = m; });
    weather_sub_ = nh_.subscribe<asv_msgs::AisWeather>(
        "ais/weather", 10, [this](const asv_msgs::AisWeather::ConstPtr& m) { weather_ = m; });
    raw_sub_ = nh_.subscribe("nmea", 1000, &AisNodeTest::rawCb, this);
    if (mode_ == "topic")
      nmea_pub_ = nh_.advertise<asv_msgs::NmeaSentence>("nmea_in", 1000);
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
    while (ros::ok() && ros::WallTime::now() < deadline &&
           (targets_sub_.getNumPublishers() == 0 || (mode_ == "topic" && nmea_pub_.getNumSubscribers() == 0)))
      ros::WallDuration(0.05).sleep();
    ASSERT_GT(targets_sub_.getNumPublishers(), 0u) << "ais_node is not up";
    sock_ = ::socket(AF_INET, SOCK_DGRAM, 0);
    ASSERT_GE(sock_, 0);
  }
  void TearDown() override {
    if (sock_ >= 0)
      ::close(sock_);
  }

  void targetsCb(const asv_msgs::TargetArray::ConstPtr& m) {
    EXPECT_EQ(m->header.frame_id, "map");
    for (const auto& t : m->targets)
      latest_[t.mmsi] = t;
  }
  void rawCb(const asv_msgs::NmeaSentence::ConstPtr& m) {
    ++raw_count_;
    raw_source_ = m->source;
  }

  void send(const std::vector<std::string>& lines) {
    for (const std::string& l : lines) {
      if (mode_ == "topic") {
        asv_msgs::NmeaSentence m;
        m.header.stamp = ros::Time::now();
        m.header.frame_id = "ais";
        m.sentence = l;
        m.source = "test";
        nmea_pub_.publish(m);
      } else {
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_port = htons(29110);
        inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
        const std::string datagram = l + "\r\n";
        ::sendto(sock_, datagram.data(), datagram.size(), 0, reinterpret_cast<sockaddr*>(&a), sizeof(a));
      }
    }
  }

  ros::NodeHandle nh_;
  std::string mode_;
  ros::Subscriber targets_sub_, raw_sub_, aids_sub_, sar_sub_, safety_sub_, weather_sub_;
  asv_msgs::AidToNavigationArray aids_;
  std::map<std::uint32_t, asv_msgs::Target> sar_;
  asv_msgs::AisSafetyMessage::ConstPtr safety_;
  asv_msgs::AisWeather::ConstPtr weather_;
  ros::Publisher nmea_pub_;
  int sock_ = -1;
  std::map<std::uint32_t, asv_msgs::Target> latest_;
  int raw_count_ = 0;
  std::string raw_source_;
};

TEST_F(AisNodeTest, SentencesBecomeTargetsInTheMapFrame) {
  const std::vector<std::string> lines = inputLines();
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(15.0);
  // Sent repeatedly until the merged targets arrive (the first datagrams may precede the bind).
  while (ros::ok() && ros::WallTime::now() < deadline &&
         !(latest_.count(244123456) && !latest_[244123456].name.empty() && latest_.count(338000001))) {
    send(lines);
    const ros::WallTime next = ros::WallTime::now() + ros::WallDuration(0.3);
    while (ros::WallTime::now() < next) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
  }
  ASSERT_TRUE(latest_.count(244123456)) << "no target for MMSI 244123456";
  const asv_msgs::Target& t = latest_[244123456];
  const Eigen::Vector2d expected = asv::LocalFrame(54.60, 18.80).toLocal(54.61, 18.82);
  // Independent check of the frame: metres per degree on the WGS84 ellipsoid at 54.6 N.
  EXPECT_NEAR(expected.x(), 0.02 * 111320.0 * std::cos(54.605 * kDeg), 10.0);
  EXPECT_NEAR(expected.y(), 0.01 * 111360.0, 10.0);
  EXPECT_EQ(t.id, "ais:244123456");
  EXPECT_EQ(t.source, asv_msgs::Target::SOURCE_AIS);
  EXPECT_EQ(t.ais_class, asv_msgs::Target::AIS_CLASS_A);
  EXPECT_NEAR(t.position.x, expected.x(), 0.2);  // rawLat/rawLon round to 1/10000 min (0.19 m)
  EXPECT_NEAR(t.position.y, expected.y(), 0.2);
  EXPECT_TRUE(t.has_geodetic);
  EXPECT_NEAR(t.latitude, 54.61, 1e-5);
  EXPECT_NEAR(t.longitude, 18.82, 1e-5);
  EXPECT_NEAR(t.speed_over_ground, 12.3 * 1852.0 / 3600.0, 1e-9);
  EXPECT_NEAR(t.course_over_ground, 45.0 * kDeg, 1e-9);
  EXPECT_NEAR(t.velocity.x, 12.3 * 1852.0 / 3600.0 * std::sin(45.0 * kDeg), 1e-9);
  EXPECT_TRUE(t.has_heading);
  EXPECT_NEAR(t.heading, 44.0 * kDeg, 1e-9);
  EXPECT_FALSE(t.has_rate_of_turn);
  EXPECT_EQ(t.nav_status, 0);
  EXPECT_EQ(t.quality, 100);
  EXPECT_EQ(t.name, "TEST SHIP");
  EXPECT_EQ(t.call_sign, "PA1234");
  EXPECT_EQ(t.destination, "ROTTERDAM");
  EXPECT_EQ(t.ship_type, 70);
  EXPECT_FLOAT_EQ(t.length, 120.0f);
  EXPECT_FLOAT_EQ(t.beam, 20.0f);
  EXPECT_FLOAT_EQ(t.to_bow, 100.0f);
  EXPECT_NEAR(t.position_covariance[0], 100.0, 1e-9);  // accuracy flag set: 10 m

  ASSERT_TRUE(latest_.count(338000001)) << "no target for the class B ship";
  const asv_msgs::Target& b = latest_[338000001];
  EXPECT_EQ(b.ais_class, asv_msgs::Target::AIS_CLASS_B);
  EXPECT_EQ(b.quality, 40);  // velocity not available
  EXPECT_EQ(b.speed_over_ground, 0.0);
  EXPECT_EQ(b.course_over_ground, 0.0);
  EXPECT_FALSE(b.has_heading);

  EXPECT_FALSE(latest_.count(244000999)) << "latitude 91 must not become a position";
  for (const auto& kv : latest_) {
    const asv_msgs::Target& x = kv.second;
    for (double v : {x.position.x, x.position.y, x.course_over_ground, x.speed_over_ground, x.velocity.x,
                     x.velocity.y, x.heading, x.rate_of_turn, x.age})
      EXPECT_TRUE(std::isfinite(v)) << x.id;
  }

  if (mode_ == "udp") {
    EXPECT_GT(raw_count_, 0) << "raw sentences are republished on nmea";
    EXPECT_EQ(raw_source_, "udp://127.0.0.1:29110");
  } else {
    EXPECT_EQ(raw_count_, 0) << "topic input is not republished";
  }
}

TEST_F(AisNodeTest, AidsSarTextsAndWeatherOnTheirOwnTopics) {
  const std::vector<std::string> lines = auxiliaryLines();
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(15.0);
  while (ros::ok() && ros::WallTime::now() < deadline &&
         !(aids_.aids.size() == 1 && sar_.count(111232511) && safety_ && weather_)) {
    send(lines);
    const ros::WallTime next = ros::WallTime::now() + ros::WallDuration(0.5);
    while (ros::WallTime::now() < next) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
  }
  const asv::LocalFrame frame(54.60, 18.80);
  ASSERT_EQ(aids_.aids.size(), 1u) << "no aid on ais/aids_to_navigation";
  EXPECT_EQ(aids_.header.frame_id, "map");
  const asv_msgs::AidToNavigation& a = aids_.aids[0];
  EXPECT_EQ(a.mmsi, 992611234u);
  EXPECT_EQ(a.name, "BUOY");
  EXPECT_EQ(a.aid_type, 24);
  EXPECT_EQ(a.aid_type_text, "Port hand Mark");
  EXPECT_FALSE(a.virtual_aid);
  EXPECT_FALSE(a.off_position);
  const Eigen::Vector2d pa = frame.toLocal(54.605, 18.81);
  EXPECT_NEAR(a.position.x, pa.x(), 0.2);
  EXPECT_NEAR(a.position.y, pa.y(), 0.2);

  ASSERT_TRUE(sar_.count(111232511)) << "no SAR aircraft on ais/sar_aircraft";
  const asv_msgs::Target& s = sar_[111232511];
  EXPECT_EQ(s.id, "sar:111232511");
  EXPECT_DOUBLE_EQ(s.position.z, 300.0);                          // the altitude
  EXPECT_NEAR(s.speed_over_ground, 100 * 1852.0 / 3600.0, 1e-9);  // whole knots
  EXPECT_NEAR(s.course_over_ground, 90.0 * kDeg, 1e-9);
  EXPECT_FALSE(latest_.count(111232511)) << "a SAR aircraft is not a collision target";

  ASSERT_TRUE(safety_) << "no text on ais/safety_messages";
  EXPECT_EQ(safety_->message_type, 14);
  EXPECT_EQ(safety_->mmsi, 244123456u);
  EXPECT_EQ(safety_->text, "SAFETY");

  ASSERT_TRUE(weather_) << "no report on ais/weather";
  const asv_msgs::AisWeather& w = *weather_;
  EXPECT_EQ(w.mmsi, 2300061u);
  ASSERT_TRUE(w.has_position);
  const Eigen::Vector2d pw = frame.toLocal(54.615, 18.81);
  EXPECT_NEAR(w.position.x, pw.x(), 1.0);
  EXPECT_NEAR(w.position.y, pw.y(), 1.0);
  ASSERT_TRUE(w.has_wind && w.has_wind_gust);
  EXPECT_NEAR(w.wind_speed, 17 * 1852.0 / 3600.0, 1e-9);
  EXPECT_NEAR(w.wind_gust, 20 * 1852.0 / 3600.0, 1e-9);
  EXPECT_NEAR(w.wind_direction, 132.0 * kDeg, 1e-9);
  ASSERT_TRUE(w.has_visibility);
  EXPECT_NEAR(w.visibility, 3.5 * 1852.0, 1e-6);
  EXPECT_NEAR(w.air_temperature, 1.4, 1e-9);
  EXPECT_NEAR(w.air_pressure, 101300.0, 1e-6);
  EXPECT_EQ(w.sea_state, 4);
  EXPECT_NEAR(w.water_level, 5.38, 1e-9);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_ais_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
