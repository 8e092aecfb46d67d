#include "loopback_vlp16.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <thread>

namespace pedtrack::test {

using Velo = mrpt::obs::CObservationVelodyneScan;

int freeUdpPort() {
  const int fd = socket(AF_INET, SOCK_DGRAM, 0);
  if (fd < 0) throw std::runtime_error("freeUdpPort: socket() failed");
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = 0;
  socklen_t len = sizeof a;
  if (bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
      getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) != 0) {
    close(fd);
    throw std::runtime_error("freeUdpPort: bind() failed");
  }
  close(fd);
  return ntohs(a.sin_port);
}

LoopbackVlp16::LoopbackVlp16(int data_port, int position_port)
    : data_port_(data_port), position_port_(position_port) {
  fd_ = socket(AF_INET, SOCK_DGRAM, 0);
  if (fd_ < 0) throw std::runtime_error("LoopbackVlp16: socket() failed");
}

LoopbackVlp16::~LoopbackVlp16() {
  if (fd_ >= 0) close(fd_);
}

void LoopbackVlp16::sendTo(int port, const void* data, std::size_t size) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(static_cast<uint16_t>(port));
  sendto(fd_, data, size, 0, reinterpret_cast<sockaddr*>(&a), sizeof a);
}

std::size_t LoopbackVlp16::sendRevolution(const Velo& scan, double t, double seconds) {
  const std::size_t n = scan.scan_packets.size();
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < n; ++i) {
    sendTo(data_port_, &scan.scan_packets[i], sizeof(Velo::TVelodyneRawPacket));
    // The VLP-16 manual (63-9243 Rev D, 9.3.3): about one position packet per 14 data packets.
    if (++data_sent_ % 14 == 0) sendPosition(t + seconds * i / n);
    // Paced as the device sends them: a burst of a whole revolution could overflow the
    // receiver's socket buffer, which a real sensor never does.
    std::this_thread::sleep_until(start + std::chrono::duration<double>(seconds * (i + 1) / n));
  }
  return n;
}

void LoopbackVlp16::sendPosition(double t) {
  // 512 bytes: 198 unused, the µs since the top of the hour, the PPS status (2: locked), 3
  // unused, then $GPRMC terminated by CR/LF and padded with zeros (manual, table 9-3).
  Velo::TVelodynePositionPacket pos;
  std::memset(&pos, 0, sizeof pos);
  const uint32_t us = static_cast<uint32_t>(std::fmod(t, 3600.0) * 1e6);
  std::memcpy(reinterpret_cast<char*>(&pos) + 198, &us, 4);
  reinterpret_cast<unsigned char*>(&pos)[202] = 2;
  const std::time_t secs = static_cast<std::time_t>(t);
  std::tm utc{};
  gmtime_r(&secs, &utc);
  char body[96];
  std::snprintf(
      body, sizeof body, "GPRMC,%02d%02d%02d,A,4140.0000,N,00200.0000,E,0.0,0.0,%02d%02d%02d,,,A",
      utc.tm_hour, utc.tm_min, utc.tm_sec, utc.tm_mday, utc.tm_mon + 1, utc.tm_year % 100);
  unsigned char sum = 0;
  for (const char* c = body; *c; ++c) sum ^= static_cast<unsigned char>(*c);
  std::snprintf(pos.NMEA_GPRMC, sizeof pos.NMEA_GPRMC, "$%s*%02X\r\n", body, sum);
  sendTo(position_port_, &pos, sizeof pos);
}

void LoopbackVlp16::sendGarbage() {
  const char junk[100] = "not a velodyne packet";
  sendTo(data_port_, junk, sizeof junk);
}

}  // namespace pedtrack::test
