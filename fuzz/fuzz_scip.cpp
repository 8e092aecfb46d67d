// SCIP 2.0 from a Hokuyo, as MRPT's CHokuyoURG (the driver mrpt_sensor runs) parses it: the
// input is everything the "device" answers, from the start-up commands (QT, SCIP2.0, BM, HS,
// PP, VV, MD) to the streamed scans. Commands the driver sends are discarded.
#include <mrpt/hwdrivers/CHokuyoURG.h>
#include <mrpt/io/CStream.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>

namespace {

class DeviceReplies : public mrpt::io::CStream {
 public:
  DeviceReplies(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::size_t Read(void* buffer, std::size_t count) override {
    count = std::min(count, size_ - pos_);
    std::memcpy(buffer, data_ + pos_, count);
    pos_ += count;
    return count;
  }
  std::size_t Write(const void*, std::size_t count) override { return count; }
  std::uint64_t Seek(std::int64_t, mrpt::io::CStream::TSeekOrigin) override { return pos_; }
  std::uint64_t getTotalBytesCount() const override { return size_; }
  std::uint64_t getPosition() const override { return pos_; }
  bool exhausted() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_, pos_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  auto stream = std::make_shared<DeviceReplies>(data, size);
  mrpt::hwdrivers::CHokuyoURG hokuyo;
  hokuyo.logging_enable_console_output = false;
  hokuyo.bindIO(stream);
  try {
    if (hokuyo.turnOn()) {
      mrpt::obs::CObservation2DRangeScan scan;
      for (int i = 0; i < 200 && !stream->exhausted(); ++i) {
        bool there_is = false, error = false;
        hokuyo.doProcessSimple(there_is, scan, error);
      }
    }
  } catch (const std::exception&) {
  }
  hokuyo.bindIO(nullptr);  // its destructor would send QT and wait for an answer
  return 0;
}
