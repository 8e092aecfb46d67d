#include "pedtrack/bag_check.h"

#include <bzlib.h>
#include <roslz4/lz4s.h>

#include <fstream>
#include <set>

#include "bag_records.h"
#include "pedtrack/errors.h"

namespace pedtrack {
namespace bag {

std::map<std::string, std::string> fields(const std::uint8_t* h, std::uint32_t size,
                                          std::uint64_t at, bool strict) {
  std::map<std::string, std::string> out;
  std::uint32_t i = 0;
  while (i < size) {
    if (size - i < 4) throw Fault{"a header field's length cut off", at + i};
    const std::uint32_t len = u32(h + i);
    if (len > size - i - 4) throw Fault{"a header field longer than its header", at + i};
    const char* f = reinterpret_cast<const char*>(h + i + 4);
    const char* eq = static_cast<const char*>(std::memchr(f, '=', len));
    if (strict && (!eq || len > 1000000))
      throw Fault{eq ? "a header field over 1 MB" : "a header field without '='", at + i};
    if (eq) out[std::string(f, eq)] = std::string(eq + 1, f + len);
    i += 4 + len;
  }
  return out;
}

Record record(const std::uint8_t* base, std::uint64_t size, std::uint64_t at, std::uint64_t origin,
              bool strict) {
  if (size - at < 4) throw Fault{"a record cut off", origin + at};
  const std::uint32_t hl = u32(base + at);
  if (size - at - 4 < std::uint64_t(hl) + 4)
    throw Fault{"a record header past the end", origin + at};
  Record r;
  r.fields = fields(base + at + 4, hl, origin + at + 4, strict);
  const auto op = r.fields.find("op");
  if (op == r.fields.end() || op->second.size() != 1)
    throw Fault{"a record without op", origin + at};
  r.op = std::uint8_t(op->second[0]);
  r.header_size = hl;
  r.data_size = u32(base + at + 4 + hl);
  r.data_at = at + 8 + hl;
  if (size - r.data_at < r.data_size) throw Fault{"record data past the end", origin + at};
  r.end = r.data_at + r.data_size;
  return r;
}

bool decompress(const Record& chunk, const std::uint8_t* data, std::uint64_t at,
                std::vector<std::uint8_t>& out) {
  const auto c = chunk.fields.find("compression");
  const std::string how = c == chunk.fields.end() ? "" : c->second;
  const std::uint32_t size = field<std::uint32_t>(chunk, "size", at);
  if (size > kMaxChunk) throw Fault{"a chunk of more than 1 GiB", at};
  if (how == "none") {
    // rosbag_storage asserts that the two agree.
    if (size != chunk.data_size) throw Fault{"a chunk whose size disagrees with its data", at};
    return false;
  }
  out.resize(size);
  auto* in = reinterpret_cast<char*>(const_cast<std::uint8_t*>(data));
  bool ok = false;
  if (how == "bz2") {
    unsigned int n = size;
    ok = BZ2_bzBuffToBuffDecompress(reinterpret_cast<char*>(out.data()), &n, in, chunk.data_size, 0,
                                    0) == BZ_OK &&
         n == size;
  } else if (how == "lz4") {
    unsigned int n = size;
    ok = roslz4_buffToBuffDecompress(in, chunk.data_size, reinterpret_cast<char*>(out.data()),
                                     &n) == ROSLZ4_OK &&
         n == size;
  } else {
    throw Fault{"a chunk compressed as '" + how + "' (none, bz2 and lz4 are read)", at};
  }
  if (!ok) throw Fault{"a " + how + " chunk that does not decompress to its size", at};
  return true;
}

}  // namespace bag

namespace {

using namespace bag;

// Every record in a chunk; the positions of its message records.
std::set<std::uint32_t> checkChunk(const std::uint8_t* c, std::uint64_t size, std::uint64_t at) {
  std::set<std::uint32_t> messages;
  for (std::uint64_t p = 0; p < size;) {
    const Record r = record(c, size, p, at);
    if (r.op == kMessage) messages.insert(std::uint32_t(p));
    if (r.op == kConnection) fields(c + r.data_at, r.data_size, at + r.data_at);
    p = r.end;
  }
  return messages;
}

void walk(std::ifstream& in, std::uint64_t file_size) {
  std::set<std::uint64_t> starts, chunks;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> chunk_refs;  // (chunk_pos, where named)
  std::uint64_t index_pos = 0;
  std::uint32_t conn_count = 0, chunk_count = 0, index_conns = 0, chunk_infos = 0;
  std::set<std::uint32_t> messages;  // of the last chunk
  std::vector<std::uint8_t> buf, chunk;
  for (std::uint64_t at = kMagicSize; at < file_size;) {
    // The header's length, then header, data length and data (a chunk's data is needed whole).
    std::uint8_t len[4];
    if (file_size - at < 4) throw Fault{"a record cut off", at};
    in.seekg(std::streamoff(at));
    in.read(reinterpret_cast<char*>(len), 4);
    const std::uint32_t hl = u32(len);
    if (file_size - at - 4 < std::uint64_t(hl) + 4) throw Fault{"a record header past the end", at};
    buf.resize(std::size_t(hl) + 8);
    std::memcpy(buf.data(), len, 4);
    in.read(reinterpret_cast<char*>(buf.data() + 4), std::streamsize(hl) + 4);
    const std::uint32_t dl = u32(buf.data() + 4 + hl);
    if (file_size - at - 8 - hl < dl) throw Fault{"record data past the end", at};
    buf.resize(buf.size() + dl);
    in.read(reinterpret_cast<char*>(buf.data() + 8 + hl), std::streamsize(dl));
    if (!in) throw Fault{"a read that failed", at};
    const Record r = record(buf.data(), buf.size(), 0, at);
    const std::uint8_t* data = buf.data() + r.data_at;
    starts.insert(at);
    if (at == kMagicSize) {
      if (r.op != kBagHeader) throw Fault{"no bag header record first", at};
      index_pos = field<std::uint64_t>(r, "index_pos", at);
      conn_count = field<std::uint32_t>(r, "conn_count", at);
      chunk_count = field<std::uint32_t>(r, "chunk_count", at);
      const auto e = r.fields.find("encryptor");
      if (e != r.fields.end() && !e->second.empty() && e->second != "rosbag/NoEncryptor")
        throw Fault{"an encrypted bag ('" + e->second + "'; decrypt it first)", at};
    }
    if (r.op == kChunk) {
      chunks.insert(at);
      messages = decompress(r, data, at, chunk) ? checkChunk(chunk.data(), chunk.size(), at)
                                                : checkChunk(data, r.data_size, at);
    } else if (r.op == kIndex) {
      const std::uint32_t count = field<std::uint32_t>(r, "count", at);
      if (field<std::uint32_t>(r, "ver", at) != 1 || std::uint64_t(count) * 12 != r.data_size)
        throw Fault{"an index record whose entries disagree with its count", at};
      for (std::uint32_t k = 0; k < count; ++k)
        if (!messages.count(u32(data + 12 * k + 8)))
          throw Fault{"an index entry that names no message of its chunk", at};
    } else if (r.op == kChunkInfo) {
      chunk_refs.emplace_back(field<std::uint64_t>(r, "chunk_pos", at), at);
      ++chunk_infos;
    } else if (r.op == kConnection) {
      fields(data, r.data_size, at + r.data_at);
      if (index_pos && at >= index_pos) ++index_conns;
    }
    at += r.end;
  }
  if (starts.empty()) throw Fault{"no records", kMagicSize};
  if (index_pos == 0) throw Fault{"an unindexed bag (run 'rosbag reindex' on it)", kMagicSize};
  if (index_pos != file_size && !starts.count(index_pos))
    throw Fault{"an index position that is no record", kMagicSize};
  // rosbag_storage reads as many connection records and chunk infos as the header counts.
  if (index_conns < conn_count || chunk_infos < chunk_count)
    throw Fault{"an index cut short (" + std::to_string(index_conns) + " of " +
                    std::to_string(conn_count) + " connections, " + std::to_string(chunk_infos) +
                    " of " + std::to_string(chunk_count) + " chunk infos)",
                index_pos};
  for (const auto& [pos, where] : chunk_refs)
    if (!chunks.count(pos)) throw Fault{"a chunk info naming no chunk", where};
}

}  // namespace

void checkBagStructure(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw DataError("cannot read the file");
  const auto file_size = std::uint64_t(in.tellg());
  char head[kMagicSize];
  in.seekg(0);
  in.read(head, std::streamsize(kMagicSize));
  if (!in || std::memcmp(head, kMagic, kMagicSize) != 0)
    throw DataError("not a ROS bag of format 2.0 (no '#ROSBAG V2.0' line)");
  try {
    walk(in, file_size);
  } catch (const Fault& f) {
    throw DataError("not a readable ROS bag: " + f.what + " at byte " + std::to_string(f.at));
  }
}

}  // namespace pedtrack
