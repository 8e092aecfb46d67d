#pragma once
// A UDP socket read in batches: recvmmsg() takes up to `batch` datagrams per system call, a large
// receive buffer (SO_RCVBUFFORCE when permitted, else SO_RCVBUF up to net.core.rmem_max) rides
// out a busy host, each datagram carries its kernel receive time (SO_TIMESTAMPNS) and the socket
// reports how many datagrams the kernel dropped for want of buffer (SO_RXQ_OVFL).
#include <sys/socket.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pedtrack::velodyne_udp {

class UdpBatchReader {
 public:
  /// Binds `address`:`port` (throws ConfigError naming them when it cannot).
  UdpBatchReader(const std::string& address, int port, int rcvbuf_bytes, int batch);
  ~UdpBatchReader();
  UdpBatchReader(const UdpBatchReader&) = delete;
  UdpBatchReader& operator=(const UdpBatchReader&) = delete;

  /// Waits up to `timeout_ms` for data, then hands every datagram queued (in batches) to `each`
  /// (bytes, size, kernel receive time in UNIX s). Returns the datagrams read. Throws DataError
  /// when the socket fails.
  using Each = std::function<void(const std::uint8_t*, std::size_t, double)>;
  std::size_t read(int timeout_ms, const Each& each);

  int receiveBuffer() const { return rcvbuf_; }                ///< bytes the kernel granted
  std::uint32_t kernelDrops() const { return kernel_drops_; }  ///< datagrams it dropped
  int port() const { return port_; }                           ///< the bound port

 private:
  int fd_ = -1, rcvbuf_ = 0, port_ = 0;
  std::uint32_t kernel_drops_ = 0;
  std::size_t batch_;
  // One slot per datagram of a batch, set up once: read() runs thousands of times a second.
  std::vector<std::uint8_t> data_, control_;
  std::vector<mmsghdr> msgs_;
  std::vector<iovec> iov_;
};

}  // namespace pedtrack::velodyne_udp
