#include "entry_stream.h"

#include <mrpt/rtti/CObject.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "stated_sizes.h"

namespace pedtrack::rawlog {

EntryStream::EntryStream(const std::string& path) {
  if (!in_.open(path)) throw std::runtime_error(path + ": cannot open rawlog");
}

void EntryStream::beginEntry() {
  entry_.clear();
  refusal_.clear();
  entry_offset_ = position_;
}

size_t EntryStream::Read(void* buffer, size_t count) {
  auto* out = static_cast<std::uint8_t*>(buffer);
  size_t n = 0;
  while (n < count && !pending_.empty()) {
    out[n++] = pending_.front();
    pending_.pop_front();
  }
  if (n < count) {
    // MRPT passes gzread's -1 (corrupt compressed data) on as a huge size_t (fuzz_rawlog found
    // it): that is a read error, never bytes.
    const size_t got = in_.Read(out + n, count - n);
    if (got > count - n)
      throw std::runtime_error("corrupt compressed data at byte " + std::to_string(position_ + n));
    n += got;
  }
  entry_.insert(entry_.end(), out, out + n);
  position_ += n;
  if (!peeking_) checkStatedSizes(n);
  return n;
}

void EntryStream::checkStatedSizes(std::size_t n) {
  // MRPT reads an object header as one byte (0x80 | name length), then the name in one read.
  if (n == 0 || n > 127 || entry_.size() < n + 1) return;
  const auto name_at = entry_.end() - std::ptrdiff_t(n);
  if (*(name_at - 1) != (0x80 | n)) return;
  refusal_ = refuseStatedSizes(std::string(name_at, entry_.end()),
                               [this](std::size_t count) { return peek(count); });
  if (!refusal_.empty()) throw std::runtime_error(refusal_);
}

bool EntryStream::readByte(std::uint8_t& b) {
  return Read(&b, 1) == 1;
}

bool EntryStream::resync() {
  // Give back everything after the bad entry's first byte, then search it byte by byte.
  if (!entry_.empty()) {
    pending_.insert(pending_.begin(), entry_.begin() + 1, entry_.end());
    position_ = entry_offset_ + 1;
  }
  entry_.clear();
  std::uint8_t b = 0;
  while (readByte(b)) {
    const std::uint64_t candidate = position_ - 1;
    const unsigned len = b & 0x7F;
    if (!(b & 0x80) || len == 0 || len > 64) continue;
    std::string name(len, '\0');
    std::size_t got = 0;
    while (got < len && readByte(reinterpret_cast<std::uint8_t&>(name[got]))) ++got;
    const bool printable = std::all_of(name.begin(), name.begin() + got, [](char c) {
      return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
             c == '_' || c == ':';
    });
    // Give the name bytes back: either the header is real and will be read again, or the next
    // header may start inside them.
    pending_.insert(pending_.begin(), name.begin(), name.begin() + got);
    position_ -= got;
    if (got == len && printable && mrpt::rtti::findRegisteredClass(name) != nullptr) {
      pending_.push_front(b);
      position_ = candidate;
      entry_.clear();
      return true;
    }
  }
  return false;
}

bool EntryStream::atEnd() {
  if (!pending_.empty()) return false;
  std::uint8_t b = 0;
  if (in_.Read(&b, 1) != 1) return true;
  pending_.push_front(b);  // peeked, not consumed
  return false;
}

std::vector<std::uint8_t> EntryStream::peek(std::size_t count) {
  std::vector<std::uint8_t> out(count);
  peeking_ = true;
  try {
    out.resize(Read(out.data(), count));
  } catch (...) {
    peeking_ = false;
    throw;
  }
  peeking_ = false;
  // Given back as if never read: served again first, not part of the entry yet.
  pending_.insert(pending_.begin(), out.begin(), out.end());
  position_ -= out.size();
  entry_.resize(entry_.size() - out.size());
  return out;
}

size_t EntryStream::Write(const void*, size_t) {
  throw std::logic_error("EntryStream is read-only");
}

uint64_t EntryStream::Seek(int64_t, TSeekOrigin) {
  throw std::logic_error("EntryStream cannot seek");
}

uint64_t EntryStream::getTotalBytesCount() const {
  return in_.getTotalBytesCount();
}

}  // namespace pedtrack::rawlog
