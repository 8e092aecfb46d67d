#include "loopback_hokuyo.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <thread>

#include "test_support.h"

namespace pedtrack::test {
namespace {

// SCIP 2.0 framing. Every line after the echo ends with a sum character: the low 6 bits of the
// byte sum of the line, plus 0x30. Numbers are sent 6 bits per character, each plus 0x30.
char scipSum(const std::string& s) {
  unsigned v = 0;
  for (unsigned char c : s) v += c;
  return static_cast<char>((v & 0x3f) + 0x30);
}
std::string line(const std::string& s) {
  return s + scipSum(s) + "\n";
}
std::string status(const std::string& code) {
  return line(code);
}
// Parameter lines of VV, PP and II: "TAG:value;" and the sum, which the SCIP 2.0 specification
// takes over the line without the ';' (urg_library accepts either).
std::string info(const std::string& tag, const std::string& value) {
  const std::string s = tag + ":" + value;
  return s + ";" + scipSum(s) + "\n";
}
std::string encode(long v, int chars) {
  std::string out(chars, '0');
  for (int i = chars - 1; i >= 0; --i, v >>= 6) out[i] = static_cast<char>((v & 0x3f) + 0x30);
  return out;
}
bool number(const std::string& s, int& out) {
  if (s.empty() || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  out = std::stoi(s);
  return true;
}
// What the device sends for a step without a valid echo: an error code under DMIN, which
// CHokuyoURG marks invalid (it keeps returns of 20 mm and more).
constexpr long kNoEcho = 1;

}  // namespace

LoopbackHokuyo::LoopbackHokuyo(Config config, std::vector<std::vector<float>> scans)
    : cfg_(std::move(config)),
      scans_(std::move(scans)),
      period_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(60.0 / cfg_.scan_rpm / cfg_.speedup))),
      slow_left_(cfg_.slow_replies) {
  const std::size_t steps = static_cast<std::size_t>(cfg_.amax - cfg_.amin + 1);
  for (const auto& s : scans_)
    if (s.size() != steps)
      throw std::invalid_argument("LoopbackHokuyo: a scan has " + std::to_string(s.size()) +
                                  " ranges, PP reports " + std::to_string(steps) + " steps");
  if (cfg_.serial) {
    openPty();
  } else if (!openListener()) {
    const std::string why = std::strerror(errno);
    throw std::runtime_error("LoopbackHokuyo: cannot listen on 127.0.0.1: " + why);
  }
  thread_ = std::thread([this] { serve(); });
}

LoopbackHokuyo::~LoopbackHokuyo() {
  stop_ = true;
  thread_.join();
  if (listen_fd_ >= 0) ::close(listen_fd_);
  if (cfg_.serial && client_fd_ >= 0) ::close(client_fd_);
  if (pty_slave_fd_ >= 0) ::close(pty_slave_fd_);
}

// The device's end of a pseudo-terminal; the driver opens the other end by name. The line is
// put in raw mode here (the driver's own setup does the same), so nothing is echoed or edited
// before the driver has configured it.
void LoopbackHokuyo::openPty() {
  const auto fail = [](const std::string& what) {
    throw std::runtime_error("LoopbackHokuyo: " + what + ": " + std::strerror(errno));
  };
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (master < 0) fail("posix_openpt");
  char name[128];
  if (::grantpt(master) != 0 || ::unlockpt(master) != 0 || ::ptsname_r(master, name, sizeof name))
    fail("pseudo-terminal setup");
  device_path_ = name;
  pty_slave_fd_ = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (pty_slave_fd_ < 0) fail("open " + device_path_);
  termios t{};
  ::tcgetattr(pty_slave_fd_, &t);
  ::cfmakeraw(&t);
  ::tcsetattr(pty_slave_fd_, TCSANOW, &t);
  client_fd_ = master;
  accepted_ = 1;  // the line is connected from the start
  mute_until_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(cfg_.mute_first));
}

// Port 0 the first time: the system picks a free one (tests run in parallel); the same port when
// the device comes back after a Drop. SO_REUSEADDR: the device closed first, so its old
// connections wait in TIME_WAIT on that port.
bool LoopbackHokuyo::openListener() {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return false;
  const int one = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(static_cast<uint16_t>(port_));
  socklen_t len = sizeof a;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(fd, 4) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) != 0) {
    const int e = errno;
    ::close(fd);
    errno = e;
    return false;
  }
  if (port_ == 0) port_ = ntohs(a.sin_port);
  listen_fd_ = fd;
  return true;
}

void LoopbackHokuyo::addFault(Fault kind, std::size_t at_scan, double seconds) {
  if (cfg_.serial && kind == Fault::Drop)
    throw std::invalid_argument("LoopbackHokuyo: a serial device has no connection to drop");
  std::lock_guard<std::mutex> lock(faults_m_);
  faults_.push_back({kind, at_scan, seconds});
}

// The fault due at scan k, marked as fired.
std::optional<LoopbackHokuyo::Pending> LoopbackHokuyo::takeFault(std::size_t k) {
  std::lock_guard<std::mutex> lock(faults_m_);
  for (auto& f : faults_)
    if (!f.fired && f.at == k) {
      f.fired = true;
      ++fired_;
      return f;
    }
  return std::nullopt;
}

// The device clock counts scans, one motor period each: frames keep the scenario's timing
// whatever the pace of sending and the host's load (the 24-bit ms counter wraps, as the device's).
long LoopbackHokuyo::clockMs() const {
  return std::lround(static_cast<double>(next_) * 60000.0 / cfg_.scan_rpm) & 0xffffff;
}

bool LoopbackHokuyo::silent() const {
  const auto now = Clock::now();
  return hung_ || now < silent_until_ || now < mute_until_;
}

// One thread does everything, polling in 2 ms slices so the stream keeps its pace and the
// destructor's stop request is seen at once; no call below blocks for longer than that, except
// a send to a client that stopped reading, which gives up after 0.5 s.
void LoopbackHokuyo::serve() {
  pinToDeviceCpu();
  while (!stop_) {
    if (!cfg_.serial && listen_fd_ < 0 && Clock::now() >= drop_until_)
      openListener();  // back up after a Drop
    pollfd fds[2] = {{listen_fd_, POLLIN, 0}, {client_fd_, POLLIN, 0}};
    const nfds_t n = client_fd_ >= 0 ? 2 : 1;
    if (::poll(fds, n, 2) < 0 && errno != EINTR) break;
    if (fds[0].revents & POLLIN) acceptClient();
    if (n == 2 && fds[1].fd == client_fd_ && (fds[1].revents & (POLLIN | POLLHUP | POLLERR)))
      readClient();
    if (client_fd_ >= 0) streamTick();
  }
  closeClient();
}

void LoopbackHokuyo::acceptClient() {
  const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK);
  if (fd < 0) return;
  if (accepted_++ == 0)
    mute_until_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(cfg_.mute_first));
  closeClient();  // one client at a time, like the device; the newest wins
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  client_fd_ = fd;
}

void LoopbackHokuyo::closeClient() {
  // A serial line stays: only the session's state is forgotten.
  if (!cfg_.serial) {
    if (client_fd_ >= 0) ::close(client_fd_);
    client_fd_ = -1;
  }
  rx_.clear();
  hung_ = false;
  md_ = Stream{};
}

void LoopbackHokuyo::readClient() {
  char buf[4096];
  for (int i = 0; i < 64; ++i) {  // bounded: the rest is read on the next poll
    const ssize_t n = ::read(client_fd_, buf, sizeof buf);
    if (n > 0) {
      rx_.append(buf, static_cast<std::size_t>(n));
      continue;
    }
    // A pty's master reads EIO while no one has the line open: nothing to read, not a hang-up.
    if (cfg_.serial) break;
    if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
      closeClient();  // the driver hung up
      return;
    }
    break;
  }
  if (rx_.size() > 65536) rx_.clear();  // no command is that long: noise
  // SCIP commands end with LF (or CR); a silent device reads them and does nothing.
  for (std::size_t p; client_fd_ >= 0 && (p = rx_.find_first_of("\n\r")) != std::string::npos;) {
    const std::string cmd = rx_.substr(0, p);
    rx_.erase(0, p + 1);
    // A serial line is not reconnected: a hung device is woken by the QT with which a driver
    // that opened the line anew starts, once its silence is over.
    if (cfg_.serial && hung_ && Clock::now() >= silent_until_ && cmd.rfind("QT", 0) == 0) {
      hung_ = false;
      md_ = Stream{};
    }
    if (!cmd.empty() && !silent()) answer(cmd);
  }
}

// A reply is the command's echo, a status line ("00": fine) and, for commands that return data,
// data lines; an empty line ends it.
void LoopbackHokuyo::answer(const std::string& cmd) {
  if (slow_left_ > 0 && !cfg_.slow_command.empty() && cmd.rfind(cfg_.slow_command, 0) == 0) {
    --slow_left_;
    std::this_thread::sleep_for(std::chrono::duration<double>(cfg_.slow_reply_seconds));
  }
  const std::string echo = cmd + "\n", c2 = cmd.substr(0, 2);
  const auto reply = [&](const std::string& code, const std::string& data = "") {
    sendAll(echo + status(code) + data + "\n");
  };
  if (cmd == "SCIP2.0" || c2 == "BM" || c2 == "HS" || c2 == "CR" || c2 == "SS" || c2 == "TM") {
    reply("00");
  } else if (c2 == "QT" || c2 == "RS") {  // laser off / reset: a running stream ends
    md_.on = false;
    reply("00");
  } else if (cmd == "VV") {
    reply("00", info("VEND", "Hokuyo Automatic Co.,Ltd.") + info("PROD", cfg_.model) +
                    info("FIRM", "pedtrack loopback") + info("PROT", "SCIP 2.0") +
                    info("SERI", "H0000000"));
  } else if (cmd == "PP") {
    reply("00",
          info("MODL", cfg_.model) + info("DMIN", std::to_string(cfg_.dmin_mm)) +
              info("DMAX", std::to_string(cfg_.dmax_mm)) + info("ARES", std::to_string(cfg_.ares)) +
              info("AMIN", std::to_string(cfg_.amin)) + info("AMAX", std::to_string(cfg_.amax)) +
              info("AFRT", std::to_string(cfg_.afrt)) +
              info("SCAN", std::to_string(cfg_.scan_rpm)));
  } else if (cmd == "II") {
    reply("00", info("MODL", cfg_.model) + info("LASR", md_.on ? "ON" : "OFF") +
                    info("SCSP", std::to_string(cfg_.scan_rpm)) + info("MESM", "Measuring") +
                    info("SBPS", "Ethernet 100 [Mbps]") + info("TIME", encode(clockMs(), 4)) +
                    info("STAT", "sensor is working normally"));
  } else if ((c2 == "MD" || c2 == "ME" || c2 == "GD" || c2 == "GE") &&
             cmd.size() == (c2[0] == 'M' ? 15u : 12u)) {
    // MD/ME: start step (4), end step (4), cluster (2), scan interval (1), scans (2, 00: until
    // QT); GD/GE: start, end, cluster, one scan now.
    Stream s;
    int count = 0;
    if (!number(cmd.substr(2, 4), s.start) || !number(cmd.substr(6, 4), s.end) ||
        !number(cmd.substr(10, 2), s.cluster) ||
        (c2[0] == 'M' && (!number(cmd.substr(12, 1), s.skip) || !number(cmd.substr(13), count))))
      return reply("01");  // a parameter is not a number
    if (s.start < cfg_.amin || s.end > cfg_.amax || s.start > s.end)
      return reply("04");  // steps out of the measured range
    s.cluster = std::max(s.cluster, 1);
    s.intensity = c2[1] == 'E';
    if (c2[0] == 'G') {
      if (next_ >= scans_.size()) return reply("10");  // nothing left to measure
      reply("00", scanBody(next_, s.start, s.end, s.cluster, s.intensity));
      ++next_, ++sent_;
      return;
    }
    s.on = true;
    s.remaining = count;
    s.head = cmd.substr(0, 13);
    // The first scan comes 0.2 s after the reply: on a first connection CHokuyoURG runs its whole
    // start-up twice, the second right after the first MD, starting with QT and a purge that
    // would eat a scan sent in between.
    s.due = Clock::now() + std::max<Clock::duration>(period_, std::chrono::milliseconds(200));
    md_ = s;
    ++streams_;
    reply("00");
  } else {
    reply("0E");  // a command this device does not know
  }
}

void LoopbackHokuyo::streamTick() {
  const auto now = Clock::now();
  if (!md_.on || hung_ || now < md_.due) return;
  md_.due += period_;
  if (md_.due < now) md_.due = now + period_;  // after a pause, no burst of late scans
  if (now < silent_until_ || next_ >= scans_.size()) return;
  std::optional<Fault> spoil;  // a malformed scan to send instead of this one
  if (const auto f = takeFault(next_)) {
    if (f->kind == Fault::Silence || f->kind == Fault::Drop) {
      const auto until = now + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(f->seconds));
      if (f->kind == Fault::Silence) {
        silent_until_ = until;
        hung_ = true;
      } else {  // down: connections are refused until it is back
        drop_until_ = until;
        closeClient();
        ::close(listen_fd_);
        listen_fd_ = -1;
      }
      return;  // the scan waits for a client that starts over
    }
    spoil = f->kind;
  }
  if (md_.skipped < md_.skip) {  // scan interval: the motor turns, nothing is sent
    ++md_.skipped;
    ++next_;
    return;
  }
  md_.skipped = 0;
  // Each streamed scan repeats the command with the scans still to come, then status 99.
  const int left = md_.remaining > 0 ? md_.remaining - 1 : 0;
  std::string body = scanBody(next_, md_.start, md_.end, md_.cluster, md_.intensity);
  if (spoil == Fault::Truncate) {
    body.erase(body.rfind('\n', body.size() - 2) + 1);
  } else if (spoil == Fault::Garbage) {
    std::string noise = body.substr(0, body.find('\n') + 1);  // the timestamp line stays
    unsigned seed = static_cast<unsigned>(next_) * 2654435761u + 1;
    for (int l = 0; l < 5; ++l) {
      std::string s(17 + 9 * l, '0');
      for (char& c : s) c = static_cast<char>(0x30 + ((seed = seed * 1103515245u + 12345u) >> 26));
      noise += line(s);
    }
    body = noise;
  } else if (spoil == Fault::BadChecksum) {
    for (std::size_t p = body.find('\n'); p != std::string::npos; p = body.find('\n', p + 1))
      body[p - 1] = static_cast<char>(0x30 + ((body[p - 1] - 0x30 + 1) & 0x3f));
  }
  const std::string tail = (left < 10 ? "0" : "") + std::to_string(left);
  if (!sendAll(md_.head + tail + "\n" + status("99") + body + "\n")) return;
  ++next_;
  if (!spoil) ++sent_;
  if (md_.remaining > 0 && --md_.remaining == 0) md_.on = false;
}

// The timestamp line (device clock, 4 characters), then the steps' ranges (mm, 3 characters;
// ME adds a 3-character intensity), cut into lines of 64 characters.
std::string LoopbackHokuyo::scanBody(std::size_t k, int start, int end, int cluster,
                                     bool intensity) const {
  const std::vector<float>& r = scans_[k];
  std::string data;
  for (int s = start; s <= end; s += cluster) {
    long best = -1;  // a cluster reports its nearest valid return
    for (int j = s; j < std::min(s + cluster, end + 1); ++j) {
      const float v = r[static_cast<std::size_t>(j - cfg_.amin)];
      const long mm = std::isfinite(v) ? std::lround(v * 1000.0) : -1;
      if (mm >= cfg_.dmin_mm && mm <= cfg_.dmax_mm) best = best < 0 ? mm : std::min(best, mm);
    }
    data += encode(best < 0 ? kNoEcho : best, 3);
    if (intensity) data += encode(best < 0 ? 0 : 1000, 3);  // the scans carry none: a constant
  }
  std::string out = line(encode(clockMs(), 4));
  for (std::size_t i = 0; i < data.size(); i += 64) out += line(data.substr(i, 64));
  return out;
}

bool LoopbackHokuyo::sendAll(const std::string& bytes) {
  const auto give_up = Clock::now() + std::chrono::milliseconds(500);
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n =
        cfg_.serial ? ::write(client_fd_, bytes.data() + done, bytes.size() - done)
                    : ::send(client_fd_, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) && !stop_ &&
        Clock::now() < give_up) {
      pollfd p{client_fd_, POLLOUT, 0};
      ::poll(&p, 1, 10);
      continue;
    }
    closeClient();  // the driver is gone or stopped reading
    return false;
  }
  return true;
}

}  // namespace pedtrack::test
