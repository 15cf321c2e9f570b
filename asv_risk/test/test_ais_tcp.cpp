// rostest (ais_tcp.test): ais_node as the client of a TCP NMEA server (a receiver or multiplexer such as
// AIS-catcher or kplex) that goes away and comes back.
//  1. The node connects; 50 position reports of ship A arrive as targets.
//  2. The server closes the connection and is gone for 3 s (connection refused): the node's diagnostics
//     show it not connected (ERROR) and count the failures.
//  3. The server is back: the node reconnects by itself (backoff from reconnect_min 0.5 s, doubling to
//     reconnect_max 2 s, so within about 2 s), and 50 reports of ship B arrive as targets.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>

#include <asv_core/codec/ais.h>
#include <asv_core/codec/nmea_encode.h>
#include <asv_msgs/TargetArray.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/ros.h>

namespace {

constexpr int kPort = 29112;

std::string positionReport(std::uint32_t mmsi, int k) {
  namespace ais = asv::ais;
  ais::PositionReportA a;
  a.speed = 80;
  a.lat = ais::rawLat(54.61);
  a.lon = ais::rawLon(18.81 + 0.0001 * k);
  a.course = 900;
  a.heading = 90;
  a.second = k % 60;
  return ais::toSentences(ais::encodePositionA(1, mmsi, a), 'A', 0).front() + "\r\n";
}

class Server {
public:
  Server() {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    const int one = 1;
    ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(kPort);
    inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
    ok_ = ::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 && ::listen(fd_, 4) == 0;
  }
  ~Server() {
    if (client_ >= 0)
      ::close(client_);
    if (fd_ >= 0)
      ::close(fd_);
  }
  bool ok() const { return ok_; }
  // Waits up to `timeout` seconds for the node to connect.
  bool accept(double timeout) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout * 1000)) <= 0)
      return false;
    client_ = ::accept(fd_, nullptr, nullptr);
    return client_ >= 0;
  }
  bool send(const std::string& s) {
    return client_ >= 0 &&
           ::send(client_, s.data(), s.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(s.size());
  }
  void dropClient() {
    ::close(client_);
    client_ = -1;
  }
  // Stops accepting: a reconnection attempt is then refused, not queued in the listen backlog.
  void stopListening() {
    ::close(fd_);
    fd_ = -1;
  }

private:
  int fd_ = -1, client_ = -1;
  bool ok_ = false;
};

class Tcp : public ::testing::Test {
protected:
  void SetUp() override {
    sub_ = nh_.subscribe("ais/targets", 100, &Tcp::onTargets, this);
    diag_sub_ = nh_.subscribe("/diagnostics", 100, &Tcp::onDiag, this);
    spinner_.start();
  }
  void onTargets(const asv_msgs::TargetArray::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& t : m->targets)
      ++reports_[t.mmsi];
  }
  void onDiag(const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& st : m->status) {
      if (st.name.find("ais input") == std::string::npos)
        continue;
      level_ = static_cast<unsigned char>(st.level);  // 0 OK .. 3 STALE
      for (const auto& kv : st.values) {
        if (kv.key == "connects")
          connects_ = std::atoi(kv.value.c_str());
        else if (kv.key == "connection failures")
          failures_ = std::atoi(kv.value.c_str());
      }
    }
  }
  bool waitFor(const std::function<bool()>& cond, double timeout) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
    while (std::chrono::steady_clock::now() < end) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (cond())
          return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    std::lock_guard<std::mutex> lock(mutex_);
    return cond();
  }

  ros::NodeHandle nh_;
  ros::AsyncSpinner spinner_{1};
  ros::Subscriber sub_, diag_sub_;
  std::mutex mutex_;
  std::map<std::uint32_t, int> reports_;
  int connects_ = 0, failures_ = 0, level_ = -1;
};

TEST_F(Tcp, ReconnectsAfterTheServerGoesAwayAndComesBack) {
  const std::uint32_t kA = 244100001, kB = 244100002;
  {
    Server s;
    ASSERT_TRUE(s.ok()) << "cannot listen on 127.0.0.1:" << kPort;
    ASSERT_TRUE(s.accept(15.0)) << "ais_node never connected";
    for (int k = 0; k < 50; ++k) {
      ASSERT_TRUE(s.send(positionReport(kA, k)));
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_TRUE(waitFor([&] { return reports_.count(kA) > 0; }, 5.0))
        << "no target from the first connection";
    EXPECT_TRUE(waitFor([&] { return connects_ == 1; }, 3.0)) << "connects " << connects_;
    s.stopListening();  // first, so that the node's immediate retry is refused
    s.dropClient();
  }  // the server is gone: connections are refused
  const auto gone = std::chrono::steady_clock::now();
  EXPECT_TRUE(
      waitFor([&] { return level_ == diagnostic_msgs::DiagnosticStatus::ERROR && failures_ >= 1; }, 5.0))
      << "level " << level_ << ", failures " << failures_;
  std::this_thread::sleep_until(gone + std::chrono::seconds(3));

  Server s;
  ASSERT_TRUE(s.ok());
  const auto back = std::chrono::steady_clock::now();
  ASSERT_TRUE(s.accept(5.0)) << "ais_node did not reconnect";
  const double after = std::chrono::duration<double>(std::chrono::steady_clock::now() - back).count();
  std::printf("ais_tcp: reconnected %.2f s after the server came back\n", after);
  EXPECT_LT(after, 2.5);  // reconnect_max 2 s, plus a diagnostics period of slack
  for (int k = 0; k < 50; ++k) {
    ASSERT_TRUE(s.send(positionReport(kB, k)));
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(waitFor([&] { return reports_.count(kB) > 0; }, 5.0)) << "no target after the reconnection";
  EXPECT_TRUE(
      waitFor([&] { return connects_ == 2 && level_ != diagnostic_msgs::DiagnosticStatus::ERROR; }, 3.0))
      << "connects " << connects_ << ", level " << level_;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_ais_tcp");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
