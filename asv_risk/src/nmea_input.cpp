#include "asv_risk/nmea_input.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include <asv_ros/nmea_output.h>
#include <asv_ros/params.h>

namespace asv_risk {

namespace {

constexpr std::size_t kReceiveBuffer = 65536;  // one UDP datagram at most; one read otherwise
constexpr int kPollMs = 200;                   // how often the reader looks at the stop flag

const std::set<std::string> kTypes = {"udp", "tcp", "serial", "file", "topic"};
const std::set<std::string> kTimings = {"tags", "rate", "fast"};

// Closes a file descriptor when it goes out of scope.
struct Fd {
  int fd = -1;
  explicit Fd(int f = -1) : fd(f) {}
  ~Fd() {
    if (fd >= 0)
      ::close(fd);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
};

// Waits for input on `fd` for at most kPollMs. 1 readable, 0 timeout, -1 error or hang-up.
int waitReadable(int fd) {
  pollfd p{fd, POLLIN, 0};
  const int r = ::poll(&p, 1, kPollMs);
  if (r < 0)
    return errno == EINTR ? 0 : -1;
  if (r == 0)
    return 0;
  if (p.revents & POLLIN)
    return 1;
  return (p.revents & (POLLERR | POLLHUP | POLLNVAL)) ? -1 : 0;
}

}  // namespace

void NmeaInputParams::validate() const {
  if (!kTypes.count(type))
    throw std::invalid_argument("input/type must be one of udp, tcp, serial, file, topic (got '" + type +
                                "')");
  if (type == "udp") {
    in_addr a{};
    if (inet_pton(AF_INET, udp_bind_address.c_str(), &a) != 1)
      throw std::invalid_argument("input/udp/bind_address must be an IPv4 address (got '" + udp_bind_address +
                                  "')");
    if (udp_port < 1 || udp_port > 65535)
      throw std::invalid_argument("input/udp/port must be in 1..65535");
  }
  if (type == "tcp") {
    if (tcp_host.empty())
      throw std::invalid_argument("input/tcp/host must not be empty");
    if (tcp_port < 1 || tcp_port > 65535)
      throw std::invalid_argument("input/tcp/port must be in 1..65535");
    if (!(tcp_reconnect_min > 0.0 && tcp_reconnect_max >= tcp_reconnect_min))
      throw std::invalid_argument("input/tcp: 0 < reconnect_min <= reconnect_max");
  }
  if (type == "serial") {
    if (serial_device.empty())
      throw std::invalid_argument("input/serial/device must not be empty");
    if (asv_ros::baudConstant(serial_baud) == B0)
      throw std::invalid_argument(
          "input/serial/baud must be one of 4800, 9600, 19200, 38400, 57600, 115200, 230400");
  }
  if (type == "file") {
    if (file_path.empty())
      throw std::invalid_argument("input/file/path must be set for input/type file");
    if (!kTimings.count(file_timing))
      throw std::invalid_argument("input/file/timing must be tags, rate or fast (got '" + file_timing + "')");
    if (!(file_rate > 0.0) || !(file_speed > 0.0) || !(file_max_gap >= 0.0))
      throw std::invalid_argument("input/file: rate > 0, speed > 0 and max_gap >= 0");
  }
  if (max_line_length < asv::nmea::kStandardMaxLength || max_line_length > kReceiveBuffer)
    throw std::invalid_argument("input/max_line_length must be in 82..65536");
  if (queue_size < 1 || queue_size > 1000000)
    throw std::invalid_argument("input/queue_size must be in 1..1000000");
}

NmeaInputParams inputFromParams(const asv::ParamMap& in, NmeaInputParams p) {
  p.type = in.getString("type", p.type);
  p.udp_bind_address = in.getString("udp/bind_address", p.udp_bind_address);
  p.udp_port = in.getInt("udp/port", p.udp_port);
  p.tcp_host = in.getString("tcp/host", p.tcp_host);
  p.tcp_port = in.getInt("tcp/port", p.tcp_port);
  p.tcp_reconnect_min = in.getDouble("tcp/reconnect_min", p.tcp_reconnect_min);
  p.tcp_reconnect_max = in.getDouble("tcp/reconnect_max", p.tcp_reconnect_max);
  p.serial_device = in.getString("serial/device", p.serial_device);
  p.serial_baud = in.getInt("serial/baud", p.serial_baud);
  p.file_path = in.getString("file/path", p.file_path);
  p.file_timing = in.getString("file/timing", p.file_timing);
  p.file_rate = in.getDouble("file/rate", p.file_rate);
  p.file_speed = in.getDouble("file/speed", p.file_speed);
  p.file_max_gap = in.getDouble("file/max_gap", p.file_max_gap);
  p.file_loop = in.getBool("file/loop", p.file_loop);
  p.frame_id = in.getString("frame_id", p.frame_id);
  p.max_line_length = in.getSize("max_line_length", p.max_line_length, 1);
  p.queue_size = in.getSize("queue_size", p.queue_size, 1);
  p.republish = in.getBool("republish", p.republish);
  p.validate();
  return p;
}

void addFramerStats(const asv::nmea::LineFramer& framer, diagnostic_updater::DiagnosticStatusWrapper& stat) {
  for (const auto& [label, count] : framer.counters())
    stat.add(label, count);
}

// ---- NmeaInput ----

NmeaInput::NmeaInput(ros::NodeHandle nh, const NmeaInputParams& params, LineHandler handler,
                     asv_ros::Lockstep* lockstep)
    : nh_(nh), params_(params), handler_(std::move(handler)) {
  params_.validate();
  const std::string& t = params_.type;
  if (t == "topic") {
    topic_sub_ = lockstep ? lockstep->subscribe("nmea_in", 1000, &NmeaInput::topicCallback, this)
                          : nh_.subscribe("nmea_in", 1000, &NmeaInput::topicCallback, this);
    source_ = "topic:" + topic_sub_.getTopic();
    return;
  }
  if (t == "udp")
    source_ = "udp://" + params_.udp_bind_address + ":" + std::to_string(params_.udp_port);
  else if (t == "tcp")
    source_ = "tcp://" + params_.tcp_host + ":" + std::to_string(params_.tcp_port);
  else if (t == "serial")
    source_ = "serial://" + params_.serial_device + "@" + std::to_string(params_.serial_baud);
  else
    source_ = "file://" + params_.file_path;
  if (params_.republish)
    raw_pub_ = nh_.advertise<asv_msgs::NmeaSentence>("nmea", 1000);
  partial_.reserve(params_.max_line_length);
  drain_timer_ = nh_.createTimer(ros::Duration(0.02), [this](const ros::TimerEvent&) { drain(); });
  thread_ = std::thread(&NmeaInput::run, this);
}

NmeaInput::~NmeaInput() {
  stop_ = true;
  space_.notify_all();
  wake_.notify_all();
  if (thread_.joinable())
    thread_.join();
}

NmeaInputStats NmeaInput::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

void NmeaInput::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) const {
  std::size_t queued = 0;
  const NmeaInputStats s = [&] {
    std::lock_guard<std::mutex> lock(mutex_);
    queued = queue_.size();
    return stats_;
  }();
  stat.add("input", source_);
  stat.add("lines", s.lines);
  if (params_.type != "topic") {
    stat.add("connected", s.connected);
    stat.add("bytes", s.bytes);
    stat.add("connects", s.connects);
    stat.add("connection failures", s.failures);
    stat.add("queued lines", queued);
    stat.add("lines dropped: queue full", s.queue_drops);
    if (params_.type == "udp")
      stat.add("datagrams dropped: socket buffer full", s.kernel_drops);
  }
  stat.add("lines dropped: oversize", s.oversize);
  if (params_.type == "file")
    stat.add("replay finished", s.finished);
}

void NmeaInput::setConnected(bool c, bool failed) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (c && !stats_.connected)
    ++stats_.connects;
  if (failed)
    ++stats_.failures;
  stats_.connected = c;
}

bool NmeaInput::sleepFor(double seconds) {
  std::unique_lock<std::mutex> lock(mutex_);
  return !wake_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return stop_.load(); });
}

void NmeaInput::run() {
  try {
    if (params_.type == "udp")
      runUdp();
    else if (params_.type == "tcp")
      runTcp();
    else if (params_.type == "serial")
      runSerial();
    else
      runFile();
  } catch (const std::exception& e) {
    ROS_ERROR("nmea input %s: %s; input stopped", source_.c_str(), e.what());
    setConnected(false, true);
  }
}

void NmeaInput::runUdp() {
  Fd s(::socket(AF_INET, SOCK_DGRAM, 0));
  if (s.fd < 0)
    throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(s.fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
  ::setsockopt(s.fd, SOL_SOCKET, SO_RXQ_OVFL, &one, sizeof(one));  // count the kernel's drops
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(params_.udp_port));
  inet_pton(AF_INET, params_.udp_bind_address.c_str(), &a.sin_addr);
  if (::bind(s.fd, reinterpret_cast<sockaddr*>(&a), sizeof(a)) != 0)
    throw std::runtime_error("cannot bind " + source_ + ": " + std::strerror(errno));
  ROS_INFO("nmea input: listening on %s", source_.c_str());
  setConnected(true, false);
  std::vector<char> buf(kReceiveBuffer);
  while (!stop_) {
    const int w = waitReadable(s.fd);
    if (w <= 0) {
      if (w < 0)
        throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
      continue;
    }
    // A datagram larger than the buffer is truncated by the kernel; its tail never reaches us. The
    // ancillary SO_RXQ_OVFL value is the kernel's count of datagrams dropped on this socket so far.
    iovec iov{buf.data(), buf.size()};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(std::uint32_t))];
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
    const ssize_t n = ::recvmsg(s.fd, &msg, 0);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN)
        continue;
      throw std::runtime_error(std::string("recv: ") + std::strerror(errno));
    }
    for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c != nullptr; c = CMSG_NXTHDR(&msg, c))
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_RXQ_OVFL) {
        std::uint32_t dropped = 0;
        std::memcpy(&dropped, CMSG_DATA(c), sizeof dropped);
        std::lock_guard<std::mutex> lock(mutex_);
        stats_.kernel_drops = dropped;
      }
    addBytes(buf.data(), static_cast<std::size_t>(n), true, false);
  }
}

void NmeaInput::runTcp() {
  double backoff = params_.tcp_reconnect_min;
  std::vector<char> buf(kReceiveBuffer);
  while (!stop_) {
    std::string error;
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* res = nullptr;
    const int g =
        ::getaddrinfo(params_.tcp_host.c_str(), std::to_string(params_.tcp_port).c_str(), &hints, &res);
    Fd s;
    if (g != 0) {
      error = gai_strerror(g);
    } else {
      for (addrinfo* ai = res; ai && s.fd < 0; ai = ai->ai_next) {
        Fd c(::socket(ai->ai_family, ai->ai_socktype | SOCK_NONBLOCK, ai->ai_protocol));
        if (c.fd < 0)
          continue;
        int r = ::connect(c.fd, ai->ai_addr, ai->ai_addrlen);
        if (r != 0 && errno == EINPROGRESS) {
          pollfd p{c.fd, POLLOUT, 0};
          r = ::poll(&p, 1, 3000) == 1 ? 0 : -1;
          int err = r == 0 ? 0 : ETIMEDOUT;
          socklen_t len = sizeof(err);
          if (r == 0)
            ::getsockopt(c.fd, SOL_SOCKET, SO_ERROR, &err, &len);
          errno = err;
          r = err == 0 ? 0 : -1;
        }
        if (r == 0)
          std::swap(s.fd, c.fd);
        else
          error = std::strerror(errno);
      }
      ::freeaddrinfo(res);
    }
    if (s.fd < 0) {
      setConnected(false, true);
      ROS_WARN_THROTTLE(30.0, "nmea input: cannot connect to %s (%s); retrying in %.1f s", source_.c_str(),
                        error.c_str(), backoff);
      if (!sleepFor(backoff))
        return;
      backoff = std::min(2.0 * backoff, params_.tcp_reconnect_max);
      continue;
    }
    ROS_INFO("nmea input: connected to %s", source_.c_str());
    setConnected(true, false);
    backoff = params_.tcp_reconnect_min;
    partial_.clear();
    discarding_ = false;
    while (!stop_) {
      const int w = waitReadable(s.fd);
      if (w == 0)
        continue;
      const ssize_t n = w < 0 ? -1 : ::recv(s.fd, buf.data(), buf.size(), 0);
      if (n < 0 && (errno == EINTR || errno == EAGAIN))
        continue;
      if (n <= 0) {
        ROS_WARN("nmea input: %s %s; reconnecting", source_.c_str(),
                 n == 0 ? "closed the connection" : std::strerror(errno));
        setConnected(false, n < 0);
        break;
      }
      addBytes(buf.data(), static_cast<std::size_t>(n), false, false);
    }
  }
}

void NmeaInput::runSerial() {
  double backoff = 1.0;
  std::vector<char> buf(4096);
  while (!stop_) {
    Fd s(::open(params_.serial_device.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK));
    termios tio{};
    bool ok = s.fd >= 0 && ::tcgetattr(s.fd, &tio) == 0;
    if (ok) {
      ::cfmakeraw(&tio);
      tio.c_cflag |= CLOCAL | CREAD;
      tio.c_cflag &= ~(CSTOPB | PARENB | CRTSCTS);
      tio.c_cc[VMIN] = 0;
      tio.c_cc[VTIME] = 0;
      ok = ::cfsetispeed(&tio, asv_ros::baudConstant(params_.serial_baud)) == 0 &&
           ::cfsetospeed(&tio, asv_ros::baudConstant(params_.serial_baud)) == 0 &&
           ::tcsetattr(s.fd, TCSANOW, &tio) == 0;
    }
    if (!ok) {
      setConnected(false, true);
      ROS_WARN_THROTTLE(30.0, "nmea input: cannot open %s (%s); retrying in %.0f s", source_.c_str(),
                        std::strerror(errno), backoff);
      if (!sleepFor(backoff))
        return;
      backoff = std::min(2.0 * backoff, 30.0);
      continue;
    }
    ROS_INFO("nmea input: reading %s", source_.c_str());
    setConnected(true, false);
    backoff = 1.0;
    partial_.clear();
    discarding_ = false;
    while (!stop_) {
      const int w = waitReadable(s.fd);
      if (w == 0)
        continue;
      const ssize_t n = w < 0 ? -1 : ::read(s.fd, buf.data(), buf.size());
      if (n < 0 && (errno == EINTR || errno == EAGAIN))
        continue;
      if (n <= 0) {
        ROS_WARN("nmea input: %s: %s; reopening", source_.c_str(),
                 n == 0 ? "end of input" : std::strerror(errno));
        setConnected(false, true);
        sleepFor(1.0);
        break;
      }
      addBytes(buf.data(), static_cast<std::size_t>(n), false, false);
    }
  }
}

void NmeaInput::runFile() {
  using Clock = std::chrono::steady_clock;
  std::vector<char> buf(kReceiveBuffer);
  do {
    Fd f(::open(params_.file_path.c_str(), O_RDONLY));
    if (f.fd < 0)
      throw std::runtime_error("cannot open " + params_.file_path + ": " + std::strerror(errno));
    setConnected(true, false);
    ROS_INFO("nmea input: replaying %s (timing %s)", source_.c_str(), params_.file_timing.c_str());
    // Pacing state: wall-clock target of the next line.
    Clock::time_point next = Clock::now();
    bool have_tag = false;
    double last_tag = 0.0;
    asv::nmea::Sentence sentence;
    partial_.clear();
    discarding_ = false;
    auto pace = [&](const std::string& line) {
      if (params_.file_timing == "rate") {
        next += std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(1.0 / params_.file_rate));
      } else if (params_.file_timing == "tags" && !line.empty() && line[0] == '\\' &&
                 asv::nmea::parseSentence(line, sentence) == asv::nmea::Reject::kNone &&
                 sentence.tag.has_time) {
        const double t = sentence.tag.unix_time;
        if (have_tag) {
          const double gap = std::clamp(t - last_tag, 0.0, params_.file_max_gap) / params_.file_speed;
          next += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(gap));
        }
        have_tag = true;
        last_tag = t;
      } else {
        return;
      }
      const double wait = std::chrono::duration<double>(next - Clock::now()).count();
      if (wait > 0.0)
        sleepFor(wait);
    };
    while (!stop_) {
      const ssize_t n = ::read(f.fd, buf.data(), buf.size());
      if (n < 0 && errno == EINTR)
        continue;
      if (n <= 0)
        break;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        stats_.bytes += static_cast<std::uint64_t>(n);
      }
      // Lines one at a time, so that each can be paced.
      for (ssize_t i = 0; i < n && !stop_; ++i) {
        const char c = buf[i];
        if (c != '\n' && c != '\r') {
          if (discarding_)
            continue;
          if (partial_.size() >= params_.max_line_length) {
            std::lock_guard<std::mutex> lock(mutex_);
            ++stats_.oversize;
            partial_.clear();
            discarding_ = true;
            continue;
          }
          partial_.push_back(c);
          continue;
        }
        if (!discarding_ && !partial_.empty())
          pace(partial_);
        endLine(true);
      }
    }
    if (!stop_) {
      pace(partial_);
      endLine(true);
    }
  } while (params_.file_loop && !stop_);
  std::lock_guard<std::mutex> lock(mutex_);
  stats_.finished = true;
  stats_.connected = false;
  ROS_INFO("nmea input: replay of %s finished", source_.c_str());
}

void NmeaInput::addBytes(const char* data, std::size_t n, bool end_of_record, bool block) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stats_.bytes += n;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const char c = data[i];
    if (c == '\n' || c == '\r') {
      endLine(block);
      continue;
    }
    if (discarding_)
      continue;
    if (partial_.size() >= params_.max_line_length) {
      std::lock_guard<std::mutex> lock(mutex_);
      ++stats_.oversize;
      partial_.clear();
      discarding_ = true;
      continue;
    }
    partial_.push_back(c);
  }
  if (end_of_record)
    endLine(block);
}

void NmeaInput::endLine(bool block) {
  if (discarding_) {
    discarding_ = false;
    partial_.clear();
    return;
  }
  if (partial_.empty())
    return;
  std::string line(partial_);
  partial_.clear();
  push(std::move(line), block);
}

bool NmeaInput::push(std::string&& text, bool block) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (queue_.size() >= params_.queue_size) {
    if (!block) {
      ++stats_.queue_drops;
      return false;
    }
    space_.wait(lock, [this] { return stop_ || queue_.size() < params_.queue_size; });
    if (stop_)
      return false;
  }
  queue_.push_back(Line{std::move(text), ros::Time::now()});
  return true;
}

void NmeaInput::drain() {
  std::deque<Line> lines;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    lines.swap(queue_);
    stats_.lines += lines.size();
  }
  space_.notify_all();
  for (Line& l : lines) {
    if (params_.republish) {
      asv_msgs::NmeaSentence m;
      m.header.stamp = l.stamp;
      m.header.frame_id = params_.frame_id;
      m.sentence = l.text;
      m.source = source_;
      raw_pub_.publish(m);
    }
    handler_(l.text, l.stamp);
  }
}

void NmeaInput::topicCallback(const asv_msgs::NmeaSentence::ConstPtr& msg) {
  std::string_view s = msg->sentence;
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r'))
    s.remove_suffix(1);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (s.size() > params_.max_line_length) {
      ++stats_.oversize;
      return;
    }
    ++stats_.lines;
  }
  handler_(std::string(s), msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp);
}

}  // namespace asv_risk
