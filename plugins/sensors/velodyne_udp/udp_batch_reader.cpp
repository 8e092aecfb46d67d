#include "velodyne_udp/udp_batch_reader.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "pedtrack/errors.h"

namespace pedtrack::velodyne_udp {
namespace {

// A datagram buffer larger than any data packet (1,206 bytes): a longer datagram is seen whole
// (MSG_TRUNC) and refused by size rather than cut to look like one.
constexpr std::size_t kSlot = 2048;
// Room for the two control messages each datagram carries.
constexpr std::size_t kControl = CMSG_SPACE(sizeof(timespec)) + CMSG_SPACE(sizeof(std::uint32_t));

}  // namespace

UdpBatchReader::UdpBatchReader(const std::string& address, int port, int rcvbuf_bytes, int batch)
    : batch_(static_cast<std::size_t>(batch)) {
  const std::string where = address + ":" + std::to_string(port);
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw ConfigError("port: cannot open a UDP socket: " + std::string(strerror(errno)));
  const int on = 1;
  ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  // As root (CAP_NET_ADMIN) past net.core.rmem_max; otherwise up to it.
  if (::setsockopt(fd_, SOL_SOCKET, SO_RCVBUFFORCE, &rcvbuf_bytes, sizeof rcvbuf_bytes) != 0)
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &rcvbuf_bytes, sizeof rcvbuf_bytes);
  socklen_t len = sizeof rcvbuf_;
  ::getsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &rcvbuf_, &len);
  ::setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof on);
  ::setsockopt(fd_, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::inet_pton(AF_INET, address.c_str(), &a.sin_addr) != 1) {
    ::close(fd_);
    throw ConfigError("address: '" + address + "' is not an IPv4 address");
  }
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    const std::string why = strerror(errno);
    ::close(fd_);
    throw ConfigError("port: cannot listen on " + where + ": " + why);
  }
  len = sizeof a;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len);
  port_ = ntohs(a.sin_port);
  data_.resize(batch_ * kSlot);
  control_.resize(batch_ * kControl);
  msgs_.resize(batch_);
  iov_.resize(batch_);
}

UdpBatchReader::~UdpBatchReader() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t UdpBatchReader::read(int timeout_ms, const Each& each) {
  pollfd p{fd_, POLLIN, 0};
  const int ready = ::poll(&p, 1, timeout_ms);
  if (ready < 0 && errno != EINTR)
    throw DataError("UDP poll failed: " + std::string(strerror(errno)));
  if (ready <= 0) return 0;
  std::size_t total = 0;
  for (;;) {  // until the socket is drained
    for (std::size_t i = 0; i < batch_; ++i) {
      // recvmmsg writes the lengths back: every slot is set again before each call.
      iov_[i] = {data_.data() + i * kSlot, kSlot};
      msgs_[i] = {};
      msgs_[i].msg_hdr.msg_iov = &iov_[i];
      msgs_[i].msg_hdr.msg_iovlen = 1;
      msgs_[i].msg_hdr.msg_control = control_.data() + i * kControl;
      msgs_[i].msg_hdr.msg_controllen = kControl;
    }
    const int n =
        ::recvmmsg(fd_, msgs_.data(), static_cast<unsigned>(batch_), MSG_DONTWAIT, nullptr);
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return total;
      throw DataError("UDP receive failed: " + std::string(strerror(errno)));
    }
    for (int i = 0; i < n; ++i) {
      double t = 0;
      msghdr& h = msgs_[i].msg_hdr;
      for (cmsghdr* c = CMSG_FIRSTHDR(&h); c; c = CMSG_NXTHDR(&h, c)) {
        if (c->cmsg_level != SOL_SOCKET) continue;
        if (c->cmsg_type == SCM_TIMESTAMPNS) {
          timespec ts;
          std::memcpy(&ts, CMSG_DATA(c), sizeof ts);
          t = double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
        } else if (c->cmsg_type == SO_RXQ_OVFL) {
          std::memcpy(&kernel_drops_, CMSG_DATA(c), sizeof kernel_drops_);  // a running total
        }
      }
      if (t == 0) {  // no kernel stamp: now
        timespec now;
        clock_gettime(CLOCK_REALTIME, &now);
        t = double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
      }
      // A datagram longer than the slot reports its whole length (MSG_TRUNC): refused by size.
      const std::size_t size = (h.msg_flags & MSG_TRUNC) ? kSlot + 1 : msgs_[i].msg_len;
      each(data_.data() + std::size_t(i) * kSlot, size, t);
    }
    total += std::size_t(n);
    if (std::size_t(n) < batch_) return total;
  }
}

}  // namespace pedtrack::velodyne_udp
