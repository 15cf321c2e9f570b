#include "asv_ros/nmea_output.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace asv_ros {

NmeaOutputConfig NmeaOutputConfig::fromParams(const asv::ParamMap& p) {
  NmeaOutputConfig c;
  c.type = p.getString("output/type", c.type);
  c.udp_host = p.getString("output/udp/host", c.udp_host);
  c.udp_port = p.getInt("output/udp/port", c.udp_port);
  c.serial_device = p.getString("output/serial/device", c.serial_device);
  c.serial_baud = p.getInt("output/serial/baud", c.serial_baud);
  c.validate();
  return c;
}

void NmeaOutputConfig::validate() const {
  const NmeaOutputConfig& c = *this;
  if (c.type != "udp" && c.type != "serial" && c.type != "none")
    throw std::invalid_argument("output/type must be udp, serial or none");
  in_addr a{};
  if (c.type == "udp" && ::inet_pton(AF_INET, c.udp_host.c_str(), &a) != 1)
    throw std::invalid_argument("output/udp/host '" + c.udp_host + "' is not an IPv4 address");
  if (c.udp_port < 1 || c.udp_port > 65535)
    throw std::invalid_argument("output/udp/port must be in 1-65535");
  if (baudConstant(c.serial_baud) == B0)
    throw std::invalid_argument(
        "output/serial/baud must be 4800, 9600, 19200, 38400, 57600, 115200 or 230400");
}

speed_t baudConstant(int baud) {
  switch (baud) {
    case 4800:
      return B4800;
    case 9600:
      return B9600;
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    case 230400:
      return B230400;
    default:
      return B0;
  }
}

NmeaOutput::NmeaOutput(const NmeaOutputConfig& config) : cfg_(config) {
  cfg_.validate();
  if (cfg_.type == "udp") {
    fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
  } else if (cfg_.type == "serial") {
    // Opened without blocking on the modem lines, then written blocking: a sentence goes out whole or
    // not at all (a partial one would run into the next on the wire).
    fd_ = ::open(cfg_.serial_device.c_str(), O_WRONLY | O_NOCTTY | O_NONBLOCK);
    termios tio{};
    bool ok = fd_ >= 0 && ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK) == 0 &&
              ::tcgetattr(fd_, &tio) == 0;
    if (ok) {
      ::cfmakeraw(&tio);
      tio.c_cflag |= CLOCAL;
      tio.c_cflag &= ~(CSTOPB | PARENB | CRTSCTS);
      ok = ::cfsetospeed(&tio, baudConstant(cfg_.serial_baud)) == 0 && ::tcsetattr(fd_, TCSANOW, &tio) == 0;
    }
    if (!ok && fd_ >= 0) {
      ::close(fd_);
      fd_ = -1;
    }
  } else {
    return;  // none
  }
  if (fd_ < 0)
    throw std::runtime_error("cannot open " + describe() + ": " + std::strerror(errno));
}

NmeaOutput::~NmeaOutput() {
  if (fd_ >= 0)
    ::close(fd_);
}

bool NmeaOutput::send(const std::string& sentence) {
  if (cfg_.type == "none")
    return true;
  const std::string line = sentence + "\r\n";
  ssize_t n = -1;
  if (cfg_.type == "udp") {
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<uint16_t>(cfg_.udp_port));
    ::inet_pton(AF_INET, cfg_.udp_host.c_str(), &addr.sin_addr);  // checked in fromParams
    n = ::sendto(fd_, line.data(), line.size(), 0, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
  } else {
    std::size_t done = 0;
    while (done < line.size()) {
      const ssize_t w = ::write(fd_, line.data() + done, line.size() - done);
      if (w < 0 && errno == EINTR)
        continue;
      if (w <= 0)
        break;
      done += static_cast<std::size_t>(w);
    }
    n = static_cast<ssize_t>(done);
  }
  const bool ok = n == static_cast<ssize_t>(line.size());
  ++(ok ? sent_ : failed_);
  return ok;
}

std::string NmeaOutput::describe() const {
  if (cfg_.type == "udp")
    return "udp " + cfg_.udp_host + ":" + std::to_string(cfg_.udp_port);
  if (cfg_.type == "serial")
    return "serial " + cfg_.serial_device + " at " + std::to_string(cfg_.serial_baud) + " Bd";
  return "none";
}

}  // namespace asv_ros
