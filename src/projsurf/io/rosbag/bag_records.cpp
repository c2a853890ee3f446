#include "projsurf/io/rosbag/bag_records.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <map>

#ifdef PROJSURF_HAVE_BZIP2
#include <bzlib.h>
#endif
#ifdef PROJSURF_HAVE_ROSLZ4
#include <roslz4/lz4s.h>
#endif

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/utf8_text.hpp"

namespace projsurf {
namespace {

// Record ops of the bag format 2.0.
constexpr std::uint8_t kOpMessage = 0x02, kOpBagHeader = 0x03, kOpIndex = 0x04, kOpChunk = 0x05, kOpChunkInfo = 0x06,
                       kOpConnection = 0x07;
constexpr char kMagic[] = "#ROSBAG V2.0\n";
constexpr std::size_t kMagicSize = sizeof kMagic - 1;

std::uint32_t le32(const char *p) {
    const auto *u = reinterpret_cast<const unsigned char *>(p);
    return static_cast<std::uint32_t>(u[0]) | static_cast<std::uint32_t>(u[1]) << 8 |
           static_cast<std::uint32_t>(u[2]) << 16 | static_cast<std::uint32_t>(u[3]) << 24;
}

/// The name=value fields of a record header (or of a connection header), every length
/// checked against the header's size.
std::map<std::string, std::string> parseFields(const std::string &path, const char *p, std::size_t n,
                                               const std::string &where) {
    std::map<std::string, std::string> fields;
    std::size_t pos = 0;
    while (pos < n) {
        if (n - pos < 4) throw InputError(path, "corrupt ROS bag: " + where + " ends inside a field length");
        const std::uint32_t len = le32(p + pos);
        pos += 4;
        if (len > n - pos)
            throw InputError(path, "corrupt ROS bag: a field of " + where + " is longer than the header");
        const char *f = p + pos;
        const void *eq = std::memchr(f, '=', len);
        if (!eq) throw InputError(path, "corrupt ROS bag: a field of " + where + " has no '='");
        const std::size_t name_len = static_cast<const char *>(eq) - f;
        fields[std::string(f, name_len)] = std::string(f + name_len + 1, len - name_len - 1);
        pos += len;
    }
    return fields;
}

/// A record as it lies in a buffer: header fields and where its data is.
struct Record {
    std::map<std::string, std::string> fields;
    std::uint8_t op = 0;
    std::uint64_t data_pos = 0;  // offset of the data in the buffer (or file)
    std::uint32_t data_len = 0;
};

std::uint32_t fieldU32(const std::string &path, const Record &r, const char *name) {
    const auto it = r.fields.find(name);
    if (it == r.fields.end() || it->second.size() != 4)
        throw InputError(path, std::string("corrupt ROS bag: a record has no 4-byte '") + name + "' field");
    return le32(it->second.data());
}

const std::string &fieldString(const std::string &path, const Record &r, const char *name) {
    const auto it = r.fields.find(name);
    if (it == r.fields.end())
        throw InputError(path, std::string("corrupt ROS bag: a record has no '") + name + "' field");
    return it->second;
}

std::uint8_t opOf(const std::string &path, const std::map<std::string, std::string> &fields) {
    const auto it = fields.find("op");
    if (it == fields.end() || it->second.size() != 1)
        throw InputError(path, "corrupt ROS bag: a record has no 'op' field");
    return static_cast<std::uint8_t>(it->second[0]);
}

/// The bag header record's index position, checked: a bag that was not closed or is cut short
/// is refused here, before its records are read.
void checkBagHeader(const std::string &path, const Record &r, std::uint64_t file_size) {
    const auto &ip = fieldString(path, r, "index_pos");
    if (ip.size() != 8) throw InputError(path, "corrupt ROS bag: index_pos is not 8 bytes");
    const std::uint64_t index_pos = le32(ip.data()) | static_cast<std::uint64_t>(le32(ip.data() + 4)) << 32;
    if (index_pos == 0) throw InputError(path, "ROS bag was not closed (no index; run `rosbag reindex`)");
    if (index_pos >= file_size)
        throw InputError(path, "ROS bag is truncated (its index lies beyond the end of the file)");
}

/// The record at `cpos` of a decompressed chunk, checked like the file's.
Record chunkRecordAt(const std::string &path, const std::string &data, std::uint64_t cpos) {
    if (data.size() - cpos < 4) throw InputError(path, "corrupt ROS bag: truncated record in a chunk");
    const std::uint32_t hl = le32(data.data() + cpos);
    if (hl > data.size() - cpos - 4)
        throw InputError(path, "corrupt ROS bag: a record header in a chunk is longer than the chunk");
    Record cr;
    cr.fields = parseFields(path, data.data() + cpos + 4, hl, "a record header");
    cr.op = opOf(path, cr.fields);
    const std::uint64_t after = cpos + 4 + hl;
    if (data.size() - after < 4) throw InputError(path, "corrupt ROS bag: truncated record in a chunk");
    cr.data_len = le32(data.data() + after);
    cr.data_pos = after + 4;
    if (cr.data_len > data.size() - cr.data_pos)
        throw InputError(path, "corrupt ROS bag: a record in a chunk is longer than the chunk");
    return cr;
}

/// What the walk over the records collects: the connections and the messages of one topic.
struct BagIndex {
    const std::string &path;
    const std::string &want_topic;
    std::vector<BagConnection> &connections;
    std::vector<BagMessageRef> &messages;
    std::map<std::uint32_t, std::size_t> by_id;  // connection id -> index in connections
    // Messages per connection in each chunk (by its position), as the chunks hold them: what the
    // index records must agree with.
    std::map<std::uint64_t, std::map<std::uint32_t, std::uint32_t>> chunk_counts;
    std::uint64_t last_chunk = 0;

    void addConnection(const Record &r, const char *data, std::size_t n) {
        BagConnection c;
        c.id = fieldU32(path, r, "conn");
        c.topic = fieldString(path, r, "topic");
        const auto h = parseFields(path, data, n, "a connection header");
        const auto type = h.find("type");
        if (type == h.end()) throw InputError(path, "corrupt ROS bag: a connection has no type");
        c.type = type->second;
        if (const auto md5 = h.find("md5sum"); md5 != h.end()) c.md5sum = md5->second;
        if (by_id.count(c.id)) return;  // connections are repeated at the end of the file
        if (connections.size() >= 100000) throw InputError(path, "ROS bag has more than 100000 connections");
        by_id[c.id] = connections.size();
        connections.push_back(c);
    }

    bool wanted(std::uint32_t conn) const {
        const auto it = by_id.find(conn);
        if (it == by_id.end()) throw InputError(path, "corrupt ROS bag: a message names an unknown connection");
        return connections[it->second].topic == want_topic;
    }

    void addMessage(const Record &r, std::uint64_t chunk_pos) {
        BagMessageRef m;
        m.connection = fieldU32(path, r, "conn");
        const auto &time = fieldString(path, r, "time");
        if (time.size() != 8) throw InputError(path, "corrupt ROS bag: a message time is not 8 bytes");
        m.sec = le32(time.data());
        m.nsec = le32(time.data() + 4);
        m.chunk_pos = chunk_pos;
        m.offset = r.data_pos;
        m.size = r.data_len;
        if (m.size > limits::kMaxBagRecordBytes)
            throw InputError(path, "ROS bag message of " + std::to_string(m.size) + " bytes exceeds the limit of " +
                                       std::to_string(limits::kMaxBagRecordBytes) + " bytes");
        if (chunk_pos != 0) ++chunk_counts[chunk_pos][m.connection];
        if (!wanted(m.connection)) return;
        if (messages.size() >= limits::kMaxBagMessages)
            throw InputError(path, "more than " + std::to_string(limits::kMaxBagMessages) + " messages on '" +
                                       want_topic + "' (the limit of one run; split the bag)");
        messages.push_back(m);
    }

    /// An index record that contradicts the chunks is refused: a bag whose index was rebuilt
    /// wrongly or edited (`rosbag reindex` writes it again).
    [[noreturn]] void contradiction(const std::string &what) const {
        throw InputError(path, "corrupt ROS bag: " + what + " contradicts its chunks (rosbag reindex rebuilds the index)");
    }

    /// An index data record (after its chunk): `count` entries of 12 bytes for one connection.
    void checkIndexData(const Record &r) {
        const std::uint32_t conn = fieldU32(path, r, "conn"), count = fieldU32(path, r, "count");
        if (static_cast<std::uint64_t>(count) * 12 != r.data_len) contradiction("an index record's size");
        const auto chunk = chunk_counts.find(last_chunk);
        const std::uint32_t held =
            chunk == chunk_counts.end() ? 0 : (chunk->second.count(conn) ? chunk->second.at(conn) : 0);
        if (last_chunk == 0 || held != count)
            contradiction("an index record (" + std::to_string(count) + " messages of connection " +
                          std::to_string(conn) + ", the chunk holds " + std::to_string(held) + ")");
    }

    /// A chunk info record: the chunk's position and its messages per connection.
    void checkChunkInfo(const Record &r, const char *data) {
        const auto &pos = fieldString(path, r, "chunk_pos");
        if (pos.size() != 8) throw InputError(path, "corrupt ROS bag: chunk_pos is not 8 bytes");
        const std::uint64_t chunk_pos = le32(pos.data()) | static_cast<std::uint64_t>(le32(pos.data() + 4)) << 32;
        const std::uint32_t count = fieldU32(path, r, "count");
        if (static_cast<std::uint64_t>(count) * 8 != r.data_len) contradiction("a chunk info record's size");
        const auto chunk = chunk_counts.find(chunk_pos);
        std::map<std::uint32_t, std::uint32_t> listed;
        for (std::uint32_t i = 0; i < count; ++i) listed[le32(data + 8 * i)] += le32(data + 8 * i + 4);
        const std::map<std::uint32_t, std::uint32_t> none;
        if ((chunk == chunk_counts.end() ? none : chunk->second) != listed)
            contradiction("the chunk info of the chunk at byte " + std::to_string(chunk_pos));
    }

    /// The connections and messages inside the decompressed chunk that starts at `chunk_pos`.
    void addChunk(const std::string &data, std::uint64_t chunk_pos) {
        last_chunk = chunk_pos;
        std::uint64_t cpos = 0;
        while (cpos < data.size()) {
            const Record cr = chunkRecordAt(path, data, cpos);
            if (cr.op == kOpConnection)
                addConnection(cr, data.data() + cr.data_pos, cr.data_len);
            else if (cr.op == kOpMessage)
                addMessage(cr, chunk_pos);
            else
                throw InputError(path, "corrupt ROS bag: unexpected record type inside a chunk");
            cpos = cr.data_pos + cr.data_len;
        }
    }
};

}  // namespace

struct BagFile::Impl {
    std::string path;
    std::ifstream in;
    std::uint64_t size = 0;
    // What the chunks of this bag have decompressed to so far, and from how many bytes (every
    // decompression counts, a chunk read again too): the work is bounded by the file.
    std::uint64_t decompressed_total = 0, compressed_total = 0;
    // The last chunk decompressed, kept for the messages that follow in it.
    std::uint64_t cached_chunk = 0;
    std::string cached;

    void readAt(std::uint64_t pos, char *dst, std::size_t n) {
        in.clear();
        in.seekg(static_cast<std::streamoff>(pos));
        in.read(dst, static_cast<std::streamsize>(n));
        if (static_cast<std::size_t>(in.gcount()) != n) throw InputError(path, "cannot read the ROS bag");
    }

    /// The record at `pos` of the file (its data not read), checked against the file size.
    Record recordAt(std::uint64_t pos, std::uint64_t &next) {
        char len4[4];
        if (size - pos < 4) throw InputError(path, "corrupt ROS bag: truncated record at byte " + std::to_string(pos));
        readAt(pos, len4, 4);
        const std::uint32_t header_len = le32(len4);
        if (header_len > limits::kMaxBagHeaderBytes || header_len > size - pos - 4)
            throw InputError(path, "corrupt ROS bag: record header at byte " + std::to_string(pos) + " announces " +
                                       std::to_string(header_len) + " bytes");
        std::string header(header_len, '\0');
        readAt(pos + 4, header.data(), header_len);
        Record r;
        r.fields = parseFields(path, header.data(), header.size(), "a record header");
        r.op = opOf(path, r.fields);
        const std::uint64_t after = pos + 4 + header_len;
        if (size - after < 4)
            throw InputError(path, "corrupt ROS bag: truncated record at byte " + std::to_string(pos));
        readAt(after, len4, 4);
        r.data_len = le32(len4);
        r.data_pos = after + 4;
        if (r.data_len > size - r.data_pos)
            throw InputError(path, "corrupt ROS bag: record at byte " + std::to_string(pos) + " announces " +
                                       std::to_string(r.data_len) + " data bytes, " +
                                       std::to_string(size - r.data_pos) + " remain (truncated?)");
        next = r.data_pos + r.data_len;
        return r;
    }

    /// Refuses, before it is decompressed, a chunk of `compressed` bytes that announces `raw`:
    /// beyond limits::kMaxBagChunkRatio times its size (above limits::kMaxBagChunkFreeBytes),
    /// or taking the bag's chunks beyond limits::kMaxBagRatio times their compressed bytes
    /// (above limits::kMaxBagFreeBytes). A bz2 chunk of zeros reaches a ratio of 10^6.
    void checkDecompression(std::uint64_t raw, std::uint64_t compressed) {
        if (raw > limits::kMaxBagChunkFreeBytes && raw > limits::kMaxBagChunkRatio * compressed)
            throw InputError(path, "ROS bag chunk of " + std::to_string(compressed) + " compressed bytes announces " +
                                       std::to_string(raw) + " bytes, beyond the limit of " +
                                       std::to_string(limits::kMaxBagChunkRatio) +
                                       " times its size (a decompression bomb?)");
        const std::uint64_t total = decompressed_total + raw, from = compressed_total + compressed;
        if (total > limits::kMaxBagFreeBytes && total > limits::kMaxBagRatio * from)
            throw InputError(path, "ROS bag chunks decompress to more than " +
                                       std::to_string(limits::kMaxBagFreeBytes >> 20) + " MiB at over " +
                                       std::to_string(limits::kMaxBagRatio) +
                                       " times their compressed size, beyond the limit (a decompression bomb?)");
        decompressed_total = total;
        compressed_total = from;
    }

    /// The uncompressed data of the chunk record at `pos`.
    const std::string &chunk(std::uint64_t pos) {
        if (pos == cached_chunk && pos != 0) return cached;
        std::uint64_t next = 0;
        const Record r = recordAt(pos, next);
        const std::string &compression = fieldString(path, r, "compression");
        const std::uint32_t raw = fieldU32(path, r, "size");
        if (raw > limits::kMaxBagRecordBytes)
            throw InputError(path, "ROS bag chunk of " + std::to_string(raw) + " bytes exceeds the limit of " +
                                       std::to_string(limits::kMaxBagRecordBytes) + " bytes");
        if (r.data_len > limits::kMaxBagRecordBytes)
            throw InputError(path,
                             "ROS bag chunk of " + std::to_string(r.data_len) + " compressed bytes exceeds the limit");
        if (compression != "none") checkDecompression(raw, r.data_len);
        std::string data(r.data_len, '\0');
        readAt(r.data_pos, data.data(), data.size());
        cached_chunk = 0;
        if (compression == "none") {
            if (raw != data.size())
                throw InputError(path, "corrupt ROS bag: an uncompressed chunk's size does not match its data");
            cached.swap(data);
#ifdef PROJSURF_HAVE_BZIP2
        } else if (compression == "bz2") {
            cached.assign(raw, '\0');
            unsigned int out_len = raw;
            const int rc = BZ2_bzBuffToBuffDecompress(cached.data(), &out_len, data.data(),
                                                      static_cast<unsigned int>(data.size()), 0, 0);
            if (rc != BZ_OK || out_len != raw)
                throw InputError(path, "corrupt ROS bag: a bz2 chunk does not decompress to its size");
#endif
#ifdef PROJSURF_HAVE_ROSLZ4
        } else if (compression == "lz4") {
            cached.assign(raw, '\0');
            unsigned int out_len = raw;
            const int rc = roslz4_buffToBuffDecompress(data.data(), static_cast<unsigned int>(data.size()),
                                                       cached.data(), &out_len);
            if (rc != ROSLZ4_OK || out_len != raw)
                throw InputError(path, "corrupt ROS bag: an lz4 chunk does not decompress to its size");
#endif
        } else {
            std::string shown;
            for (char c : compression.substr(0, 20))
                shown.push_back(std::isprint(static_cast<unsigned char>(c)) ? c : '?');
            throw InputError(path, "ROS bag chunk compression '" + shown + "' is not supported by this build");
        }
        cached_chunk = pos;
        return cached;
    }

    /// Opens the file and checks its format line.
    void open() {
        requireReadable(path);
        in.open(path, std::ios::binary);
        in.seekg(0, std::ios::end);
        const std::streamoff end = in.tellg();
        if (!in || end < 0) throw InputError(path, "cannot read the file");
        size = static_cast<std::uint64_t>(end);
        char magic[kMagicSize];
        if (size < kMagicSize) throw InputError(path, "not a ROS bag (too short)");
        readAt(0, magic, kMagicSize);
        if (std::memcmp(magic, kMagic, kMagicSize) != 0) {
            if (std::memcmp(magic, "#ROSBAG V", 9) == 0)
                throw InputError(path, "ROS bag format other than 2.0 (re-record it, or run `rosbag fix`)");
            throw InputError(path, "not a ROS bag (no '#ROSBAG V2.0' line)");
        }
    }

    /// Walks every record of the file in order, the bag header first, into `index`.
    void indexRecords(BagIndex &index) {
        bool have_header = false;
        std::uint64_t pos = kMagicSize;
        while (pos < size) {
            std::uint64_t next = 0;
            const Record r = recordAt(pos, next);
            if (!have_header && r.op != kOpBagHeader)
                throw InputError(path, "corrupt ROS bag: the first record is not the bag header");
            switch (r.op) {
            case kOpBagHeader:
                if (have_header) throw InputError(path, "corrupt ROS bag: a second bag header");
                have_header = true;
                checkBagHeader(path, r, size);
                break;
            case kOpConnection: {
                if (r.data_len > limits::kMaxBagHeaderBytes)
                    throw InputError(path, "corrupt ROS bag: connection header too long");
                std::string data(r.data_len, '\0');
                readAt(r.data_pos, data.data(), data.size());
                index.addConnection(r, data.data(), data.size());
                break;
            }
            case kOpMessage: index.addMessage(r, 0); break;
            case kOpChunk: index.addChunk(chunk(pos), pos); break;
            // The index is not needed (the records are all read in order), but it must agree.
            case kOpIndex: index.checkIndexData(r); break;
            case kOpChunkInfo: {
                if (r.data_len > limits::kMaxBagHeaderBytes)
                    throw InputError(path, "corrupt ROS bag: chunk info record too long");
                std::string data(r.data_len, '\0');
                readAt(r.data_pos, data.data(), data.size());
                index.checkChunkInfo(r, data.data());
                break;
            }
            default: throw InputError(path, "corrupt ROS bag: unknown record type " + std::to_string(r.op));
            }
            pos = next;
        }
        if (!have_header) throw InputError(path, "corrupt ROS bag: no bag header record");
    }
};

BagFile::BagFile(const std::string &path, const std::string &want_topic) : impl_(new Impl) {
    impl_->path = path;
    try {
        impl_->open();
        BagIndex index{path, want_topic, connections_, messages_, {}, {}, 0};
        impl_->indexRecords(index);
        std::stable_sort(messages_.begin(), messages_.end(), [](const BagMessageRef &a, const BagMessageRef &c) {
            return a.sec < c.sec || (a.sec == c.sec && a.nsec < c.nsec);
        });
    } catch (...) {
        delete impl_;
        throw;
    }
}

BagFile::~BagFile() { delete impl_; }

std::string BagFile::read(const BagMessageRef &m) {
    if (m.chunk_pos == 0) {
        std::string out(m.size, '\0');
        impl_->readAt(m.offset, out.data(), out.size());
        return out;
    }
    const std::string &data = impl_->chunk(m.chunk_pos);
    if (m.offset > data.size() || m.size > data.size() - m.offset)
        throw InputError(impl_->path, "corrupt ROS bag chunk");
    return data.substr(static_cast<std::size_t>(m.offset), m.size);
}

void RosReader::need(std::size_t n) {
    if (n > bytes_.size() - pos_) throw InputError(source_, "message is shorter than its fields say");
}

std::uint8_t RosReader::u8() {
    need(1);
    return static_cast<std::uint8_t>(bytes_[pos_++]);
}

std::uint32_t RosReader::u32() {
    need(4);
    const std::uint32_t v = le32(bytes_.data() + pos_);
    pos_ += 4;
    return v;
}

std::string RosReader::string() {
    const std::uint32_t n = u32();
    need(n);
    std::string s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
}

std::string RosReader::text(const char *field) {
    std::string s = string();
    if (!isUtf8(s)) throw InputError(source_, std::string(field) + " is not UTF-8 text");
    return s;
}

std::size_t RosReader::bytes(std::size_t &length) {
    length = u32();
    need(length);
    const std::size_t at = pos_;
    pos_ += length;
    return at;
}

}  // namespace projsurf
