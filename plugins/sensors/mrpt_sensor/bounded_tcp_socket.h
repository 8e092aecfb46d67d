// The TCP link mrpt_sensor gives CHokuyoURG for an Ethernet Hokuyo (IP_DIR / PORT_DIR) in place
// of the plain mrpt::comms::CClientTCPSocket the driver would make itself.
//
// Why: MRPT 2.5's CClientTCPSocket::Write (writeAsync with no timeout) retries a failed send()
// for ever. When a device closes the connection while CHokuyoURG is (re)configuring it (the
// driver reconnects and sends QT at once), every send() fails with EPIPE and the driver spins
// inside doProcess() without returning: the pipeline hangs, whatever its own timeouts say.
// This link bounds each write instead: a send() that fails, or that cannot go out within
// kWriteTimeoutMs, closes the connection, so the driver's next isConnected() check sees it lost
// and reconnects as it does for a connection the device closed while reading.
#pragma once

#include <mrpt/comms/CClientTCPSocket.h>

#include <cstddef>

namespace pedtrack::mrpt_sensor {

class BoundedTcpSocket : public mrpt::comms::CClientTCPSocket {
 public:
  // How long one write may wait for room in the socket's send buffer.
  static constexpr int kWriteTimeoutMs = 1000;

  // Writes that failed and closed the connection (for tests and diagnostics).
  std::size_t failedWrites() const { return failed_writes_; }

 protected:
  // Returns `count` even when the write failed, after closing the connection: CHokuyoURG asserts
  // that every command went out whole, and its destructor sends QT, so a short count would throw
  // from a destructor and end the process. A failed write is then what a command lost on the wire
  // is to the driver: no answer, and a lost connection on its next check.
  std::size_t Write(const void* buffer, std::size_t count) override;

 private:
  std::size_t failed_writes_ = 0;
};

}  // namespace pedtrack::mrpt_sensor
