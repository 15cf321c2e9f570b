// NMEA 0183 line input shared by ais_node and arpa_node: UDP, TCP client, serial device, file replay,
// or the raw-sentence topic `nmea_in` (asv_msgs/NmeaSentence, as rosbag records and replays it).
//
// Device inputs run in one reader thread that splits the byte stream into lines and queues them;
// a ROS timer drains the queue in the spinner thread, so the node's handler never runs concurrently
// with its other callbacks. Memory is bounded everywhere: one fixed receive buffer, lines longer
// than max_line_length are dropped (counted), and the queue holds at most queue_size lines (network
// and serial input beyond it is dropped and counted; file replay waits instead).
// Every line read from a device is republished on `nmea` (asv_msgs/NmeaSentence with receive stamp
// and source) when `republish` is set, so a bag of `nmea` replays into `nmea_in` unchanged.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <string_view>
#include <thread>

#include <asv_ros/lockstep.h>

#include <asv_core/codec/line_framer.h>
#include <asv_core/codec/nmea.h>
#include <asv_msgs/NmeaSentence.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include <asv_core/common/param_map.h>

namespace asv_risk {

struct NmeaInputParams {
  std::string type = "udp";  // udp | tcp | serial | file | topic
  // udp: datagrams on this local address and port. 127.0.0.1 (the default) hears only this
  // machine; bind 0.0.0.0 (or the LAN interface's address) to hear a receiver on the LAN.
  std::string udp_bind_address = "127.0.0.1";
  int udp_port = 10110;
  // tcp: client of a receiver/multiplexer server; reconnects with exponential backoff.
  std::string tcp_host = "127.0.0.1";
  int tcp_port = 10110;
  double tcp_reconnect_min = 1.0;   // [s] first retry delay, doubled per failure
  double tcp_reconnect_max = 30.0;  // [s] longest retry delay
  // serial: raw 8N1 at this baud rate (AIS receivers 38400, radars 4800).
  std::string serial_device = "/dev/ttyUSB0";
  int serial_baud = 38400;
  // file: replay of a log, one sentence per line.
  std::string file_path;
  std::string file_timing = "tags";  // tags: original timing from tag-block c: times | rate | fast
  double file_rate = 10.0;           // [lines/s] for timing rate
  double file_speed = 1.0;           // playback speed factor for timing tags
  double file_max_gap = 10.0;        // [s] longest pause taken from the tag times (log gaps)
  bool file_loop = false;            // start again at the end
  // all inputs
  std::string frame_id = "ais";        // NmeaSentence header.frame_id of republished sentences
  std::size_t max_line_length = 1024;  // [bytes] longer lines are dropped and counted
  std::size_t queue_size = 10000;      // lines waiting for the node
  bool republish = true;               // publish every line read from a device on `nmea`

  void validate() const;  // throws std::invalid_argument
};

// Reads the input parameters (the node's input/ subtree, as ParamMap::sub("input")); `defaults` gives
// the node's own defaults. std::invalid_argument naming a bad value.
NmeaInputParams inputFromParams(const asv::ParamMap& params, NmeaInputParams defaults);

// Adds a framer's counters (asv::nmea::LineFramer::counters) to a node's diagnostics.
void addFramerStats(const asv::nmea::LineFramer& framer, diagnostic_updater::DiagnosticStatusWrapper& stat);

struct NmeaInputStats {
  std::uint64_t lines = 0;         // lines handed to the node
  std::uint64_t bytes = 0;         // bytes read from the device
  std::uint64_t oversize = 0;      // lines longer than max_line_length, dropped
  std::uint64_t queue_drops = 0;   // lines dropped because the queue was full
  std::uint64_t kernel_drops = 0;  // udp: datagrams the kernel dropped (socket buffer full), SO_RXQ_OVFL
  std::uint64_t connects = 0;      // successful opens/connections
  std::uint64_t failures = 0;      // failed opens/connections and read errors
  bool connected = false;
  bool finished = false;  // file replay reached its end
  // Every line or datagram lost before the node saw it.
  std::uint64_t drops() const { return oversize + queue_drops + kernel_drops; }
};

class NmeaInput {
public:
  // Called in the spinner thread for every line (terminator stripped) with its receive stamp.
  using LineHandler = std::function<void(const std::string& line, const ros::Time& stamp)>;

  // Opens the input (device inputs start their reader thread). Topics are resolved in `nh`.
  // lockstep: for type topic, the sentences reach the handler at the node's lockstep steps (the node's
  // own Lockstep, which must outlive this input); nullptr: at receipt.
  NmeaInput(ros::NodeHandle nh, const NmeaInputParams& params, LineHandler handler,
            asv_ros::Lockstep* lockstep = nullptr);
  ~NmeaInput();
  NmeaInput(const NmeaInput&) = delete;
  NmeaInput& operator=(const NmeaInput&) = delete;

  const std::string& source() const { return source_; }  // e.g. udp://127.0.0.1:10110
  NmeaInputStats stats() const;
  // The source is there: a topic input always (its publisher is the ROS graph's business), a device while
  // open or connected (a file until its end). The ingestion nodes send their heartbeat only then.
  bool linkUp() const { return params_.type == "topic" || stats().connected; }
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) const;

private:
  struct Line {
    std::string text;
    ros::Time stamp;
  };

  void run();
  void runUdp();
  void runTcp();
  void runSerial();
  void runFile();
  // Line assembly from raw bytes; `end_of_record` ends the current line (end of a UDP datagram).
  void addBytes(const char* data, std::size_t n, bool end_of_record, bool block);
  void endLine(bool block);
  bool push(std::string&& text, bool block);
  void drain();
  void topicCallback(const asv_msgs::NmeaSentence::ConstPtr& msg);
  bool sleepFor(double seconds);  // false when stopping
  void setConnected(bool c, bool failed);

  ros::NodeHandle nh_;
  NmeaInputParams params_;
  LineHandler handler_;
  std::string source_;
  ros::Publisher raw_pub_;
  ros::Subscriber topic_sub_;
  ros::Timer drain_timer_;

  std::atomic<bool> stop_{false};
  std::thread thread_;
  mutable std::mutex mutex_;
  std::condition_variable space_, wake_;
  std::deque<Line> queue_;
  NmeaInputStats stats_;  // guarded by mutex_

  // Reader-thread state.
  std::string partial_;
  bool discarding_ = false;  // inside an oversize line: drop until its end
};

}  // namespace asv_risk
