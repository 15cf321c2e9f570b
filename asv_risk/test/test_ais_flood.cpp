// rostest (ais_flood.test): ais_node under an input flood, the figures of docs/reliability.md.
//  1. Normal rate: 1,000 valid AIVDM position reports (100 ships x 10) at 1,000 datagrams/s over UDP:
//     every one is decoded (messages decoded +1000), none dropped, every ship becomes a target.
//  2. Flood: 100,000 datagrams/s for 10 s (1,000,000), one valid report in every 100, the rest garbage,
//     bad checksums and truncated sentences. ais_node stays up (diagnostics keep coming), its resident
//     memory stays bounded (its queue holds at most queue_size lines), and every datagram is accounted
//     for: read (lines) or counted as dropped (queue full, or socket buffer full via SO_RXQ_OVFL).
//  3. Normal rate again: 1,000 valid reports, all decoded: the flood leaves nothing behind.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <asv_core/codec/ais.h>
#include <asv_core/codec/nmea_encode.h>
#include <asv_msgs/TargetArray.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <xmlrpcpp/XmlRpcClient.h>

namespace {

constexpr int kPort = 29111;

std::string positionReport(std::uint32_t mmsi, int k) {
  namespace ais = asv::ais;
  ais::PositionReportA a;
  a.speed = 100;  // 10 kn
  a.lat = ais::rawLat(54.60 + 0.001 * (mmsi % 100));
  a.lon = ais::rawLon(18.80 + 0.001 * (k % 50));
  a.course = 900;
  a.heading = 90;
  a.second = k % 60;
  return ais::toSentences(ais::encodePositionA(1, mmsi, a), 'A', 0).front();
}

class Flood : public ::testing::Test {
protected:
  void SetUp() override {
    sock_ = ::socket(AF_INET, SOCK_DGRAM, 0);
    ASSERT_GE(sock_, 0);
    addr_.sin_family = AF_INET;
    addr_.sin_port = htons(kPort);
    inet_pton(AF_INET, "127.0.0.1", &addr_.sin_addr);
    targets_sub_ = nh_.subscribe("ais/targets", 1000, &Flood::onTargets, this);
    diag_sub_ = nh_.subscribe("/diagnostics", 100, &Flood::onDiag, this);
    spinner_.start();
    pid_ = nodePid("/ais_node");
  }
  void TearDown() override {
    spinner_.stop();
    ::close(sock_);
  }

  void send(const std::string& d) {
    if (::sendto(sock_, d.data(), d.size(), 0, reinterpret_cast<sockaddr*>(&addr_), sizeof(addr_)) > 0)
      ++sent_;
  }

  void onTargets(const asv_msgs::TargetArray::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& t : m->targets)
      mmsis_.insert(t.mmsi);
  }
  void onDiag(const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
    for (const auto& st : m->status) {
      if (st.name.find("ais input") == std::string::npos)
        continue;
      std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& kv : st.values) {
        char* end = nullptr;
        const double v = std::strtod(kv.value.c_str(), &end);
        if (end != kv.value.c_str() && *end == '\0')
          diag_[kv.key] = v;  // numbers only ("input" is a URL, booleans are True/False)
      }
      ++diag_count_;
    }
  }
  double diag(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = diag_.find(key);
    return it == diag_.end() ? -1.0 : it->second;
  }
  int diagCount() {
    std::lock_guard<std::mutex> lock(mutex_);
    return diag_count_;
  }
  // Waits until the node's diagnostics show `lines` lines read (or dropped) and a fresh report after it.
  void waitForAccounting(double timeout) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
    while (std::chrono::steady_clock::now() < end) {
      const double got =
          diag("lines") + diag("lines dropped: queue full") + diag("datagrams dropped: socket buffer full");
      if (got >= static_cast<double>(sent_))
        break;
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    const int n = diagCount();  // one more report, so every counter is of after the drain
    while (diagCount() < n + 2 && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }

  // The PID of a node, from its XML-RPC API (getPid).
  static int nodePid(const std::string& node) {
    XmlRpc::XmlRpcValue args, result, payload;
    args[0] = ros::this_node::getName();
    args[1] = node;
    for (int i = 0; i < 100; ++i) {
      if (ros::master::execute("lookupNode", args, result, payload, false) &&
          result[0].getType() == XmlRpc::XmlRpcValue::TypeInt && static_cast<int>(result[0]) == 1)
        break;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (result.getType() != XmlRpc::XmlRpcValue::TypeArray || static_cast<int>(result[0]) != 1)
      return -1;
    const std::string uri = result[2];
    std::string host;
    uint32_t port = 0;
    if (!ros::network::splitURI(uri, host, port))
      return -1;
    XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
    XmlRpc::XmlRpcValue a, r;
    a[0] = ros::this_node::getName();
    if (!client.execute("getPid", a, r) || r.getType() != XmlRpc::XmlRpcValue::TypeArray)
      return -1;
    return static_cast<int>(r[2]);
  }
  double rssMiB() const {
    std::ifstream f("/proc/" + std::to_string(pid_) + "/status");
    std::string line;
    while (std::getline(f, line))
      if (line.compare(0, 6, "VmRSS:") == 0)
        return std::stod(line.substr(6)) / 1024.0;
    return -1.0;
  }

  // 1,000 valid reports at 1,000 per second; checks every one is decoded and every ship a target.
  void normalRate(std::uint32_t first_mmsi) {
    const double decoded0 = diag("messages decoded");
    const double drops0 = diag("lines dropped: queue full") + diag("datagrams dropped: socket buffer full");
    {
      std::lock_guard<std::mutex> lock(mutex_);
      mmsis_.clear();
    }
    auto next = std::chrono::steady_clock::now();
    for (int k = 0; k < 1000; ++k) {
      send(positionReport(first_mmsi + static_cast<std::uint32_t>(k % 100), k));
      next += std::chrono::milliseconds(1);
      std::this_thread::sleep_until(next);
    }
    waitForAccounting(20.0);
    EXPECT_EQ(diag("messages decoded") - decoded0, 1000.0) << "a valid sentence was lost at 1,000/s";
    EXPECT_EQ(diag("lines dropped: queue full") + diag("datagrams dropped: socket buffer full"), drops0);
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::uint32_t m = first_mmsi; m < first_mmsi + 100; ++m)
      EXPECT_TRUE(mmsis_.count(m)) << "no target for MMSI " << m;
  }

  ros::NodeHandle nh_;
  ros::AsyncSpinner spinner_{1};
  ros::Subscriber targets_sub_, diag_sub_;
  int sock_ = -1;
  sockaddr_in addr_{};
  int pid_ = -1;
  std::uint64_t sent_ = 0;
  std::mutex mutex_;
  std::set<std::uint32_t> mmsis_;
  std::map<std::string, double> diag_;
  int diag_count_ = 0;
};

TEST_F(Flood, HundredThousandPerSecondForTenSeconds) {
  ASSERT_GT(pid_, 0) << "cannot find ais_node's PID";
  for (int i = 0; i < 100 && diagCount() == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_GT(diagCount(), 0) << "ais_node publishes no diagnostics";

  normalRate(244000000);
  const double rss0 = rssMiB();
  ASSERT_GT(rss0, 0.0);

  // The flood: batches of 100 datagrams every millisecond for 10 s.
  std::vector<std::string> junk = {"garbage \x01\x02 garbage garbage garbage garbage garbage",
                                   "!AIVDM,1,1,,A,15M67FC000G?ufbE`FepT@3n00Sa,0*00",  // bad checksum
                                   "!AIVDM,1,1,,A,15M6", "$GPGGA,,,,,,0,00,,,M,,M,,*66 trailing junk"};
  const double decoded0 = diag("messages decoded");
  const std::uint64_t sent0 = sent_;
  double rss_max = rss0;
  std::atomic<bool> done{false};
  std::thread sampler([&] {
    while (!done) {
      rss_max = std::max(rss_max, rssMiB());
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  const auto t0 = std::chrono::steady_clock::now();
  auto next = t0;
  int valid = 0;
  for (int ms = 0; ms < 10000; ++ms) {
    for (int i = 0; i < 100; ++i) {
      if (i == 0) {
        send(positionReport(245000000u + static_cast<std::uint32_t>(valid % 1000), valid));
        ++valid;
      } else {
        send(junk[static_cast<std::size_t>(i) % junk.size()]);
      }
    }
    next += std::chrono::milliseconds(1);
    std::this_thread::sleep_until(next);
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::uint64_t flood = sent_ - sent0;
  // The kernel's drop count comes with the next datagram read: one more after the socket has drained.
  std::this_thread::sleep_for(std::chrono::seconds(2));
  send("$PROBE,after,the,flood*00");
  waitForAccounting(30.0);
  done = true;
  sampler.join();
  const double lines = diag("lines"), qdrops = diag("lines dropped: queue full"),
               kdrops = diag("datagrams dropped: socket buffer full");
  const double decoded = diag("messages decoded") - decoded0;
  std::printf(
      "ais_flood: %lu datagrams in %.2f s (%.0f/s), %d valid; read %.0f lines in all, dropped %.0f "
      "(queue full) + %.0f (socket buffer); valid decoded %.0f of %d; RSS %.1f MiB before, %.1f MiB "
      "at most\n",
      static_cast<unsigned long>(flood), secs, flood / secs, valid, lines, qdrops, kdrops, decoded, valid,
      rss0, rss_max);
  EXPECT_EQ(flood, 1000000u);
  EXPECT_GT(flood / secs, 80000.0) << "the sender could not keep up: the test did not flood";
  // Every datagram of every phase is accounted for: read, or counted as dropped.
  EXPECT_EQ(lines + qdrops + kdrops, static_cast<double>(sent_));
  EXPECT_LT(rss_max - rss0, 64.0) << "memory grew under the flood";
  EXPECT_GT(decoded, 0.0);
  EXPECT_LE(decoded, valid);
  // Still up: it still reports, and the flood left nothing behind.
  const int n = diagCount();
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  EXPECT_GT(diagCount(), n) << "ais_node stopped reporting";
  normalRate(246000000);
  waitForAccounting(10.0);
  EXPECT_EQ(diag("lines") + diag("lines dropped: queue full") + diag("datagrams dropped: socket buffer full"),
            static_cast<double>(sent_));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_ais_flood");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
