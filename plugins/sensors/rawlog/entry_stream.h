#pragma once
// A read-only MRPT stream over a rawlog (gz-compressed or plain) that remembers the bytes of the
// entry being read, so that after a corrupt entry it can scan forward for the next object header
// and resume there. Memory stays bounded by the largest entry. It also refuses an entry whose 2D
// scan claims more beams than a scanner gives, a sensor label of gigabytes or a frame of a
// billion observations, before MRPT sizes memory to them (stated_sizes.h).
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CStream.h>

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace pedtrack::rawlog {

class EntryStream : public mrpt::io::CStream {
 public:
  explicit EntryStream(const std::string& path);

  /// Marks the start of a top-level entry.
  void beginEntry();
  /// Bytes consumed since beginEntry().
  std::size_t entryBytes() const { return entry_.size(); }
  /// Uncompressed offset of the current entry's first byte.
  std::uint64_t entryOffset() const { return entry_offset_; }
  /// Rewinds to the byte after the current entry's first byte and scans forward to the next
  /// plausible object header (0x80|len, a registered MRPT class name). Returns false at EOF.
  bool resync();
  /// True when no byte is left (a failed entry that reached it was truncated).
  bool atEnd();
  /// Why this stream refused the current entry ("" when it did not): MRPT reports an exception
  /// thrown from a read as its own parse error, with this text lines further down.
  const std::string& refusal() const { return refusal_; }
  /// Up to `count` next bytes, left unread (fewer at the end of the file).
  std::vector<std::uint8_t> peek(std::size_t count);

  size_t Read(void* buffer, size_t count) override;
  size_t Write(const void*, size_t) override;
  uint64_t Seek(int64_t, TSeekOrigin) override;
  uint64_t getTotalBytesCount() const override;
  uint64_t getPosition() const override { return position_; }

 private:
  bool readByte(std::uint8_t& b);
  /// After a read of n bytes: when they were a class name (its object header's 0x80 | n just
  /// before), throws if the sizes the object states, still unread, are beyond reason
  /// (refuseStatedSizes).
  void checkStatedSizes(std::size_t n);
  mrpt::io::CFileGZInputStream in_;
  std::deque<std::uint8_t> pending_;  // bytes given back by resync(), served before `in_`
  std::vector<std::uint8_t> entry_;
  std::uint64_t position_ = 0, entry_offset_ = 0;
  bool peeking_ = false;  // peek() reads too: no header check inside it
  std::string refusal_;
};

}  // namespace pedtrack::rawlog
