#include "bounded_tcp_socket.h"

#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <chrono>

namespace pedtrack::mrpt_sensor {

std::size_t BoundedTcpSocket::Write(const void* buffer, std::size_t count) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(kWriteTimeoutMs);
  const auto* bytes = static_cast<const char*>(buffer);
  std::size_t sent = 0;
  while (sent < count && isConnected()) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    pollfd p{m_hSock, POLLOUT, 0};
    const int ready = left > 0 ? ::poll(&p, 1, static_cast<int>(left)) : 0;
    if (ready < 0 && errno == EINTR) continue;
    ssize_t n = -1;
    // MSG_NOSIGNAL: a reset connection is an error here, not a SIGPIPE that ends the process.
    // MSG_DONTWAIT: MRPT's socket blocks, and a blocking send() waits for room for all of it.
    if (ready > 0) n = ::send(m_hSock, bytes + sent, count - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && ready > 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) continue;
    ++failed_writes_;  // an error, or no room before the deadline: the link is lost
    close();
    break;
  }
  return count;
}

}  // namespace pedtrack::mrpt_sensor
