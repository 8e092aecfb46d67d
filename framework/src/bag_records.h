// The records of a ROS1 bag (format 2.0), parsed from memory with every length checked: shared
// by the structure check run before rosbag_storage reads a bag (bag_check.cpp) and the chunk
// scan that re-indexes a bag cut short (bag_recover.cpp). Internal to pedtrack_bag_check.
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace pedtrack::bag {

constexpr char kMagic[] = "#ROSBAG V2.0\n";
constexpr std::size_t kMagicSize = sizeof(kMagic) - 1;
// Record ops (the bag format 2.0 specification).
constexpr std::uint8_t kMessage = 0x02, kBagHeader = 0x03, kIndex = 0x04, kChunk = 0x05,
                       kChunkInfo = 0x06, kConnection = 0x07;
// rosbag_storage decompresses a chunk into one buffer of its stated size; real chunks are well
// under 100 MB (rosbag record writes 768 KB).
constexpr std::uint32_t kMaxChunk = 1u << 30;

/// A structural fault and the byte it lies at.
struct Fault {
  std::string what;
  std::uint64_t at;
};

inline std::uint32_t u32(const std::uint8_t* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

/// A header's fields, each a 4-byte length and "name=value", must tile it exactly (what
/// ros::Header::parse assumes). `at` is the header's position, for the message. `strict`: also
/// what ros::Header::parse refuses with an exception (a field without '=', or over 1 MB), for
/// records written anew that must read back.
std::map<std::string, std::string> fields(const std::uint8_t* h, std::uint32_t size,
                                          std::uint64_t at, bool strict = false);

struct Record {
  std::uint8_t op = 0;
  std::map<std::string, std::string> fields;
  std::uint32_t header_size = 0;
  std::uint64_t data_at = 0;  // position of its data
  std::uint32_t data_size = 0;
  std::uint64_t end = 0;  // position after it
};

/// The record at `at` of the bytes [base, base + size) (positions counted from `origin`).
Record record(const std::uint8_t* base, std::uint64_t size, std::uint64_t at, std::uint64_t origin,
              bool strict = false);

/// A fixed-size field's value (e.g. "conn", a uint32).
template <typename T>
T field(const Record& r, const char* name, std::uint64_t at) {
  const auto f = r.fields.find(name);
  if (f == r.fields.end() || f->second.size() != sizeof(T))
    throw Fault{std::string("a record without a valid '") + name + "' field", at};
  T v;
  std::memcpy(&v, f->second.data(), sizeof(T));
  return v;
}

/// A compressed chunk's content into `out` (true); an uncompressed one is left where it lies
/// (false). `data` is the chunk record's data, `at` its position.
bool decompress(const Record& chunk, const std::uint8_t* data, std::uint64_t at,
                std::vector<std::uint8_t>& out);

}  // namespace pedtrack::bag
