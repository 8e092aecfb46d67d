#include "pedtrack/bag_recover.h"

#include <fstream>
#include <map>
#include <vector>

#include "bag_records.h"
#include "pedtrack/errors.h"

namespace pedtrack {
namespace {

using namespace bag;

using Fields = std::vector<std::pair<std::string, std::string>>;

template <typename T>
std::string bytes(T v) {
  return std::string(reinterpret_cast<const char*>(&v), sizeof(T));
}

// A bag time (sec, nsec as two uint32) as one ordered number.
std::uint64_t timeKey(const std::string& t) {
  std::uint32_t sec, nsec;
  std::memcpy(&sec, t.data(), 4);
  std::memcpy(&nsec, t.data() + 4, 4);
  return std::uint64_t(sec) * 1000000000ull + nsec;
}

struct Connection {
  std::string topic;
  std::string header;  // the connection record's data: type, md5sum, message_definition, …
};

struct ChunkInfo {
  std::uint64_t pos = 0;
  std::string start, end;                         // bag times of its first and last message
  std::map<std::uint32_t, std::uint32_t> counts;  // messages per connection
};

// A message record of a chunk, as its index entry needs it.
struct MessageEntry {
  std::uint32_t conn = 0;
  std::string time;          // the record's 8-byte time field
  std::uint32_t offset = 0;  // of the record in the chunk
};

// Writes the re-indexed bag as rosbag_storage reads it: the bag header (pointing at the index),
// each chunk uncompressed and followed by its per-connection index records, then the connection
// records and chunk infos.
class BagWriter {
 public:
  explicit BagWriter(const std::string& path) : out_(path, std::ios::binary | std::ios::trunc) {
    if (!out_) throw DataError("cannot write the re-indexed copy '" + path + "'");
    out_.write(kMagic, std::streamsize(kMagicSize));
    writeHeader(0, 0, 0);
  }

  // One chunk's complete records (the bytes of an uncompressed chunk) and its messages.
  void chunk(const std::uint8_t* c, std::uint64_t size, const std::vector<MessageEntry>& messages,
             const std::map<std::uint32_t, Connection>& known) {
    ChunkInfo info;
    info.pos = std::uint64_t(out_.tellp());
    std::map<std::uint32_t, std::string> index;  // per connection: (time, offset) entries
    for (const MessageEntry& m : messages) {
      if (!known.count(m.conn)) throw Fault{"a message on an unknown connection", m.offset};
      index[m.conn] += m.time + bytes(m.offset);
      ++info.counts[m.conn];
      if (info.start.empty() || timeKey(m.time) < timeKey(info.start)) info.start = m.time;
      if (info.end.empty() || timeKey(m.time) > timeKey(info.end)) info.end = m.time;
      ++messages_;
    }
    if (info.counts.empty()) return;  // only connection records: nothing to index
    write({{"op", std::string(1, char(kChunk))},
           {"compression", "none"},
           {"size", bytes(std::uint32_t(size))}},
          std::string(reinterpret_cast<const char*>(c), size));
    for (const auto& [conn, entries] : index)
      write({{"op", std::string(1, char(kIndex))},
             {"ver", bytes(std::uint32_t(1))},
             {"conn", bytes(conn)},
             {"count", bytes(std::uint32_t(entries.size() / 12))}},
            entries);
    chunks_.push_back(std::move(info));
  }

  // The index: every connection, then every chunk's info; the header rewritten to point at it.
  void close(const std::map<std::uint32_t, Connection>& connections) {
    const auto index_pos = std::uint64_t(out_.tellp());
    for (const auto& [conn, c] : connections)
      write({{"op", std::string(1, char(kConnection))}, {"conn", bytes(conn)}, {"topic", c.topic}},
            c.header);
    for (const auto& info : chunks_) {
      std::string data;
      for (const auto& [conn, n] : info.counts) data += bytes(conn) + bytes(n);
      write({{"op", std::string(1, char(kChunkInfo))},
             {"ver", bytes(std::uint32_t(1))},
             {"chunk_pos", bytes(info.pos)},
             {"start_time", info.start},
             {"end_time", info.end},
             {"count", bytes(std::uint32_t(info.counts.size()))}},
            data);
    }
    out_.seekp(std::streamoff(kMagicSize));
    writeHeader(index_pos, std::uint32_t(connections.size()), std::uint32_t(chunks_.size()));
    out_.close();
    if (!out_) throw DataError("cannot write the re-indexed copy");
  }

  std::size_t messages() const { return messages_; }
  std::size_t chunks() const { return chunks_.size(); }

 private:
  void write(const Fields& fields, const std::string& data) {
    std::string h;
    for (const auto& [k, v] : fields)
      h += bytes(std::uint32_t(k.size() + 1 + v.size())) + k + "=" + v;
    out_ << bytes(std::uint32_t(h.size())) << h << bytes(std::uint32_t(data.size())) << data;
  }
  // rosbag pads its header record to 4096 bytes so that it can be rewritten in place.
  void writeHeader(std::uint64_t index_pos, std::uint32_t conns, std::uint32_t chunks) {
    const Fields f = {{"op", std::string(1, char(kBagHeader))},
                      {"index_pos", bytes(index_pos)},
                      {"conn_count", bytes(conns)},
                      {"chunk_count", bytes(chunks)}};
    std::size_t h = 0;
    for (const auto& [k, v] : f) h += 4 + k.size() + 1 + v.size();
    write(f, std::string(4096 - 8 - h, ' '));
  }

  std::ofstream out_;
  std::vector<ChunkInfo> chunks_;
  std::size_t messages_ = 0;
};

// A connection record (its data is the connection header: type, md5sum, definition, …). The
// first record of a connection id is kept: rosbag writes the same one in the chunk and the index.
void connection(const Record& r, const std::uint8_t* data, std::uint64_t at, std::uint64_t data_at,
                std::map<std::uint32_t, Connection>& connections) {
  fields(data, r.data_size, data_at, true);
  const auto conn = field<std::uint32_t>(r, "conn", at);
  const auto topic = r.fields.find("topic");
  if (topic == r.fields.end()) throw Fault{"a connection record without topic", at};
  connections.emplace(
      conn,
      Connection{topic->second, std::string(reinterpret_cast<const char*>(data), r.data_size)});
}

// A chunk's complete records: their connections into `connections`, their messages, and the
// length of the complete prefix (the whole chunk unless `cut`, the file ended inside it, where a
// record cut off ends it).
struct ChunkScan {
  std::uint64_t size = 0;
  std::vector<MessageEntry> messages;
};
ChunkScan scanChunk(const std::uint8_t* c, std::uint64_t size, std::uint64_t at, bool cut,
                    std::map<std::uint32_t, Connection>& connections) {
  ChunkScan out;
  std::uint64_t& p = out.size;
  while (p < size) {
    if (cut) {  // a record the end of the file cuts off ends the chunk
      if (size - p < 8) break;
      const std::uint32_t hl = u32(c + p);
      if (size - p - 8 < hl) break;
      if (size - p - 8 - hl < u32(c + p + 4 + hl)) break;
    }
    const Record r = record(c, size, p, at, true);  // copied as they are: they must read back
    if (r.op == kConnection) {
      connection(r, c + r.data_at, at + p, at + r.data_at, connections);
    } else if (r.op == kMessage) {
      const auto t = r.fields.find("time");
      if (t == r.fields.end() || t->second.size() != 8)
        throw Fault{"a message without a valid 'time' field", at + p};
      out.messages.push_back(
          {field<std::uint32_t>(r, "conn", at + p), t->second, std::uint32_t(p)});
    } else {
      throw Fault{"a record other than a message or connection inside a chunk", at + p};
    }
    p = r.end;
  }
  return out;
}

}  // namespace

BagRecovery reindexBag(const std::string& path, const std::string& out_path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw DataError("cannot read the file");
  BagRecovery rec;
  rec.file_size = std::uint64_t(in.tellg());
  const std::uint64_t file_size = rec.file_size;
  char head[kMagicSize];
  in.seekg(0);
  in.read(head, std::streamsize(kMagicSize));
  if (!in || std::memcmp(head, kMagic, kMagicSize) != 0)
    throw DataError("not a ROS bag of format 2.0 (no '#ROSBAG V2.0' line)");
  BagWriter out(out_path);
  std::map<std::uint32_t, Connection> connections;
  std::vector<std::uint8_t> buf, chunk;
  std::uint64_t index_pos = 0;
  rec.data_end = file_size;
  try {
    // Reads [at, at + n) into buf; false when the file ends first.
    const auto load = [&](std::uint64_t at, std::uint64_t n) {
      if (file_size - at < n) return false;
      buf.resize(n);
      in.seekg(std::streamoff(at));
      in.read(reinterpret_cast<char*>(buf.data()), std::streamsize(n));
      if (!in) throw Fault{"a read that failed", at};
      return true;
    };
    for (std::uint64_t at = kMagicSize; at < file_size;) {
      // The record's header (a cut one ends the data at its start), then as much of its data as
      // the file holds.
      if (!load(at, 4)) {
        rec.data_end = at;
        break;
      }
      const std::uint32_t hl = u32(buf.data());
      if (!load(at, 8 + std::uint64_t(hl))) {
        rec.data_end = at;
        break;
      }
      const std::uint32_t dl = u32(buf.data() + 4 + hl);
      Record r;
      r.fields = fields(buf.data() + 4, hl, at + 4);
      const auto op = r.fields.find("op");
      if (op == r.fields.end() || op->second.size() != 1) throw Fault{"a record without op", at};
      r.op = std::uint8_t(op->second[0]);
      r.data_size = dl;
      const std::uint64_t data_at = 8 + std::uint64_t(hl);
      const bool whole = file_size - at - data_at >= dl;
      bool open = false;  // a chunk left open by a recorder killed while writing it
      if (r.op == kChunk) {
        const auto c = r.fields.find("compression");
        // Its header still has sizes 0; its records follow it to the end of the file.
        open = c != r.fields.end() && c->second == "none" && dl == 0 &&
               field<std::uint32_t>(r, "size", at) == 0;
      }
      load(at, whole && !open ? data_at + dl : file_size - at);
      const std::uint8_t* data = buf.data() + data_at;
      if (at == kMagicSize) {
        if (r.op != kBagHeader) throw Fault{"no bag header record first", at};
        if (!whole) {
          rec.data_end = at;
          break;
        }
        index_pos = field<std::uint64_t>(r, "index_pos", at);
      } else if (r.op == kChunk) {
        const auto c = r.fields.find("compression");
        const bool plain = c != r.fields.end() && c->second == "none";
        if (whole && !open) {
          const bool packed = decompress(r, data, at, chunk);
          const std::uint8_t* content = packed ? chunk.data() : data;
          const std::uint64_t size = packed ? chunk.size() : dl;
          const ChunkScan scan = scanChunk(content, size, at + data_at, false, connections);
          out.chunk(content, size, scan.messages, connections);
        } else if (plain) {
          // The complete records of the chunk the file ends in.
          const std::uint64_t avail = buf.size() - data_at;
          const ChunkScan scan = scanChunk(data, avail, at + data_at, true, connections);
          out.chunk(data, scan.size, scan.messages, connections);
          rec.data_end = at + data_at + scan.size;
          break;
        } else {
          rec.data_end = at;  // a compressed chunk cut short does not decompress
          break;
        }
      } else if (!whole) {
        rec.data_end = at;
        break;
      } else if (r.op == kConnection) {
        connection(r, data, at, at + data_at, connections);
      } else if (r.op != kIndex && r.op != kChunkInfo) {
        throw Fault{"a record that is no chunk, index or connection at the top level", at};
      }
      at += data_at + dl;
    }
  } catch (const Fault& f) {
    throw DataError("not a readable ROS bag: " + f.what + " at byte " + std::to_string(f.at));
  }
  out.close(connections);
  rec.messages = out.messages();
  rec.chunks = out.chunks();
  if (rec.data_end < file_size || index_pos >= file_size) {  // records or the index cut off
    rec.cause = BagRecovery::Cause::CutShort;
    rec.reason = "cut short: its data ends at byte " + std::to_string(rec.data_end) + " of " +
                 std::to_string(file_size);
  } else if (index_pos == 0) {
    rec.cause = BagRecovery::Cause::NoIndex;
    rec.reason = "no index (the recording was not closed)";
  } else {
    rec.cause = BagRecovery::Cause::DamagedIndex;
    rec.reason = "a damaged index";
  }
  return rec;
}

std::string recoveryWarning(const std::string& path, const BagRecovery& r) {
  const std::string n = std::to_string(r.messages);
  return path + ": " + r.reason + "; " +
         (r.cause == BagRecovery::Cause::CutShort ? "the " + n + " complete messages before it"
                                                  : "its " + n + " messages") +
         " are read (as 'rosbag reindex' would recover them)";
}

}  // namespace pedtrack
