#pragma once
// A fake Hokuyo (URG/UTM) for tests: it listens on 127.0.0.1 on a port the system chooses (an
// Ethernet model), or sits on the master side of a pseudo-terminal (a USB/RS-232 model, which
// the driver opens as a serial port), and speaks enough SCIP 2.0 for MRPT's CHokuyoURG (SCIP2.0,
// QT, BM, RS, HS, CR, VV, PP, II, MD/ME streams and GD/GE single scans), serving given scans in
// order. It can fail the way a real device does: go silent, drop the connection, send a malformed
// scan.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace pedtrack::test {

class LoopbackHokuyo {
 public:
  using Clock = std::chrono::steady_clock;

  /// What the device reports in PP (and so what CHokuyoURG configures itself from). The defaults
  /// are the 768-beam leg-height Hokuyo of the simulator's leg scenarios: steps 128..895 of 1024.
  struct Config {
    std::string model = "UTM-30LX-EW";
    int ares = 1024;                    ///< steps per revolution (ARES)
    int amin = 128, amax = 895;         ///< first and last measured step (AMIN, AMAX)
    int afrt = 512;                     ///< step facing forward (AFRT)
    int dmin_mm = 20, dmax_mm = 11000;  ///< DMIN, DMAX
    int scan_rpm = 600;                 ///< SCAN: one scan per 60/rpm s of device time
    /// Scans are sent this many times faster than the motor turns (tests replay a 10 Hz scenario
    /// in less time); their timestamps keep the motor's period.
    double speedup = 1;
    /// Seconds from the first connection during which nothing is answered (a device still
    /// booting when the driver comes).
    double mute_first = 0;
    /// A serial device: a pseudo-terminal (devicePath()) instead of a TCP port. Drop does not
    /// apply (there is no connection to refuse).
    bool serial = false;
    /// The first `slow_replies` replies to commands starting with `slow_command` come
    /// `slow_reply_seconds` late (a device or a host busy for a moment).
    std::string slow_command;
    int slow_replies = 0;
    double slow_reply_seconds = 0;
  };

  enum class Fault {
    Silence,      ///< stop answering for `seconds`: commands are read and ignored; the stream
                  ///< on the connection of the moment never resumes (a hung device)
    Drop,         ///< close the connection and refuse connections for `seconds` (switched off)
    Truncate,     ///< send the scan without its last data line (a short frame)
    Garbage,      ///< send noise lines instead of the scan's data, after a valid header
    BadChecksum,  ///< send the scan with every line's sum character wrong, data intact
  };

  /// `scans`: ranges in metres, one per step amin..amax; a value that is not finite or lies
  /// outside [DMIN, DMAX] is sent as an error code (no echo). Starts listening at once.
  LoopbackHokuyo(Config config, std::vector<std::vector<float>> scans);
  ~LoopbackHokuyo();
  LoopbackHokuyo(const LoopbackHokuyo&) = delete;
  LoopbackHokuyo& operator=(const LoopbackHokuyo&) = delete;

  int port() const { return port_; }
  /// The serial device to open (COM_port_LIN), for a `serial` device; empty otherwise.
  const std::string& devicePath() const { return device_path_; }
  /// Fires once, when scan `at_scan` (index into the served scans) is next due. Silence and
  /// Drop keep that scan for later; the malformed ones use it up.
  void addFault(Fault kind, std::size_t at_scan, double seconds = 0);

  std::size_t scansSent() const { return sent_; }          ///< well-formed scans sent
  std::size_t connections() const { return accepted_; }    ///< connections accepted
  std::size_t streamsStarted() const { return streams_; }  ///< MD/ME commands accepted
  std::size_t faultsFired() const { return fired_; }

 private:
  struct Pending {
    Fault kind;
    std::size_t at;
    double seconds;
    bool fired = false;
  };
  struct Stream {  // an MD/ME request in progress
    bool on = false, intensity = false;
    int start = 0, end = 0, cluster = 1, skip = 0, remaining = 0;
    int skipped = 0;
    std::string head;  // "MD" or "ME" and the parameters up to the scan count
    Clock::time_point due;
  };

  bool openListener();
  void openPty();
  void serve();
  void acceptClient();
  void readClient();
  void closeClient();
  void answer(const std::string& cmd);
  void streamTick();
  std::string scanBody(std::size_t k, int start, int end, int cluster, bool intensity) const;
  bool sendAll(const std::string& bytes);
  bool silent() const;
  long clockMs() const;
  std::optional<Pending> takeFault(std::size_t k);

  const Config cfg_;
  const std::vector<std::vector<float>> scans_;
  const Clock::duration period_;  // between streamed scans
  int listen_fd_ = -1, client_fd_ = -1, port_ = 0;
  int pty_slave_fd_ = -1;  // held open so the line stays up while the driver reconnects
  std::string device_path_;
  std::string rx_;
  bool hung_ = false;  // the current connection was silenced: it never streams again
  Stream md_;
  Clock::time_point silent_until_{}, drop_until_{}, mute_until_{};
  std::atomic<std::size_t> next_{0}, sent_{0}, accepted_{0}, streams_{0}, fired_{0};
  std::mutex faults_m_;
  std::vector<Pending> faults_;
  int slow_left_ = 0;  // slow replies still to come
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace pedtrack::test
