// NMEA sentences out to a device: UDP datagrams (one sentence each, "\r\n"-terminated, as OpenCPN, kplex
// and most autopilot gateways expect) or a serial line (raw 8N1). The counterpart of the ingestion
// nodes' inputs; a write that fails is counted, never thrown.
#pragma once

#include <cstdint>
#include <string>

#include <asv_core/common/param_map.h>
#include <termios.h>

namespace asv_ros {

// Keys output/type (udp | serial | none), output/udp/host, output/udp/port, output/serial/device,
// output/serial/baud; the caller's YAML documents them.
struct NmeaOutputConfig {
  std::string type = "udp";
  std::string udp_host = "127.0.0.1";
  int udp_port = 10110;
  std::string serial_device = "/dev/ttyUSB0";
  int serial_baud = 4800;                                           // NMEA 0183's own rate
  void validate() const;                                            // std::invalid_argument naming the key
  static NmeaOutputConfig fromParams(const asv::ParamMap& params);  // validated
};

// The termios constant of a baud rate; B0 for a rate the stack does not offer.
speed_t baudConstant(int baud);

class NmeaOutput {
public:
  // Opens the socket or the serial device; std::invalid_argument for a bad setting, std::runtime_error
  // naming the device when it cannot be opened.
  explicit NmeaOutput(const NmeaOutputConfig& config);
  ~NmeaOutput();
  NmeaOutput(const NmeaOutput&) = delete;
  NmeaOutput& operator=(const NmeaOutput&) = delete;

  bool send(const std::string& sentence);  // false (and counted) when the write failed
  // Bytes per second the line carries (8N1: baud / 10); unlimited for UDP and none.
  double capacity() const { return cfg_.type == "serial" ? cfg_.serial_baud / 10.0 : 1e12; }
  uint64_t sent() const { return sent_; }
  uint64_t failed() const { return failed_; }
  std::string describe() const;  // "udp 127.0.0.1:10110", "serial /dev/ttyUSB0 at 4800 Bd", "none"

private:
  NmeaOutputConfig cfg_;
  int fd_ = -1;
  uint64_t sent_ = 0, failed_ = 0;
};

}  // namespace asv_ros
