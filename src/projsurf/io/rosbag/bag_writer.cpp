#include "projsurf/io/rosbag/bag_writer.hpp"

#include <map>
#include <utility>

namespace projsurf {
namespace {

constexpr std::size_t kChunkBytes = std::size_t{4} << 20;  ///< a chunk is closed past this size (rosbag: 768 KiB)
constexpr std::size_t kBagHeaderBytes = 4096;              ///< the bag header record is padded to this (as rosbag)

void putU32(std::string &s, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
void putU64(std::string &s, std::uint64_t v) {
    putU32(s, static_cast<std::uint32_t>(v));
    putU32(s, static_cast<std::uint32_t>(v >> 32));
}
std::string u32(std::uint32_t v) {
    std::string s;
    putU32(s, v);
    return s;
}
std::string u64(std::uint64_t v) {
    std::string s;
    putU64(s, v);
    return s;
}
std::string time(std::uint32_t sec, std::uint32_t nsec) { return u32(sec) + u32(nsec); }

using Fields = std::vector<std::pair<std::string, std::string>>;

std::string fields(const Fields &f) {
    std::string h;
    for (const auto &[k, v] : f) {
        putU32(h, static_cast<std::uint32_t>(k.size() + 1 + v.size()));
        h += k + "=" + v;
    }
    return h;
}
std::string record(const Fields &f, const std::string &data) {
    std::string r;
    const std::string h = fields(f);
    putU32(r, static_cast<std::uint32_t>(h.size()));
    r += h;
    putU32(r, static_cast<std::uint32_t>(data.size()));
    r += data;
    return r;
}

}  // namespace

std::uint32_t BagWriter::addConnection(const std::string &topic, const std::string &type, const std::string &md5sum,
                                       const std::string &definition) {
    connections_.push_back({topic, type, md5sum, definition});
    return static_cast<std::uint32_t>(connections_.size() - 1);
}

void BagWriter::addMessage(std::uint32_t conn, std::uint32_t sec, std::uint32_t nsec, const std::string &bytes) {
    messages_.push_back({conn, sec, nsec, bytes});
}

std::string BagWriter::bytes() const {
    auto connectionRecord = [&](std::uint32_t id) {
        const Connection &c = connections_[id];
        const std::string header =
            fields({{"topic", c.topic}, {"type", c.type}, {"md5sum", c.md5sum}, {"message_definition", c.definition}});
        return record({{"op", "\x07"}, {"conn", u32(id)}, {"topic", c.topic}}, header);
    };
    struct ChunkInfo {
        std::uint64_t pos;
        std::uint32_t start_sec, start_nsec, end_sec, end_nsec;
        std::map<std::uint32_t, std::uint32_t> counts;  // connection -> messages
    };
    std::string body;  // everything after the bag header record
    std::vector<ChunkInfo> infos;
    const std::uint64_t body_start = 13 + kBagHeaderBytes;  // "#ROSBAG V2.0\n" + the header record
    std::size_t next = 0;
    bool connections_written = false;
    while (next < messages_.size() || !connections_written) {
        std::string chunk;
        if (!connections_written)
            for (std::uint32_t id = 0; id < connections_.size(); ++id) chunk += connectionRecord(id);
        connections_written = true;
        ChunkInfo info{body_start + body.size(), 0, 0, 0, 0, {}};
        std::map<std::uint32_t, std::string> index;  // connection -> (time, offset) entries
        bool first = true;
        while (next < messages_.size() && (chunk.size() < kChunkBytes || first)) {
            const Message &m = messages_[next++];
            if (first || m.sec < info.start_sec || (m.sec == info.start_sec && m.nsec < info.start_nsec))
                info.start_sec = m.sec, info.start_nsec = m.nsec;
            if (first || m.sec > info.end_sec || (m.sec == info.end_sec && m.nsec > info.end_nsec))
                info.end_sec = m.sec, info.end_nsec = m.nsec;
            first = false;
            index[m.conn] += time(m.sec, m.nsec) + u32(static_cast<std::uint32_t>(chunk.size()));
            ++info.counts[m.conn];
            chunk += record({{"op", "\x02"}, {"conn", u32(m.conn)}, {"time", time(m.sec, m.nsec)}}, m.bytes);
        }
        body += record(
            {{"op", "\x05"}, {"compression", "none"}, {"size", u32(static_cast<std::uint32_t>(chunk.size()))}}, chunk);
        for (const auto &[conn, entries] : index)
            body += record({{"op", "\x04"}, {"ver", u32(1)}, {"conn", u32(conn)}, {"count", u32(info.counts[conn])}},
                           entries);
        infos.push_back(std::move(info));
    }
    const std::uint64_t index_pos = body_start + body.size();
    for (std::uint32_t id = 0; id < connections_.size(); ++id) body += connectionRecord(id);
    for (const ChunkInfo &c : infos) {
        std::string data;
        for (const auto &[conn, count] : c.counts) data += u32(conn) + u32(count);
        body += record({{"op", "\x06"},
                        {"ver", u32(1)},
                        {"chunk_pos", u64(c.pos)},
                        {"start_time", time(c.start_sec, c.start_nsec)},
                        {"end_time", time(c.end_sec, c.end_nsec)},
                        {"count", u32(static_cast<std::uint32_t>(c.counts.size()))}},
                       data);
    }
    const Fields header_fields = {{"op", "\x03"},
                                  {"index_pos", u64(index_pos)},
                                  {"conn_count", u32(static_cast<std::uint32_t>(connections_.size()))},
                                  {"chunk_count", u32(static_cast<std::uint32_t>(infos.size()))}};
    const std::size_t header_fields_bytes = 4 + fields(header_fields).size() + 4;
    const std::string header = record(header_fields, std::string(kBagHeaderBytes - header_fields_bytes, ' '));
    return "#ROSBAG V2.0\n" + header + body;
}

}  // namespace projsurf
