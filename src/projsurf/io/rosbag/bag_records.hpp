#pragma once
// ROS 1 bag files (format 2.0) read by a small bounded reader of our own: every length in
// the file is checked against the bytes that are really there (and against io/files/limits.hpp)
// before anything is allocated or parsed, so that a file from a stranger never reaches the
// rosbag library. Chunks may be uncompressed, bz2 or lz4 (lz4 when built with ROS).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace projsurf {

/// One topic of the bag (a connection record).
struct BagConnection {
    std::uint32_t id = 0;
    std::string topic;
    std::string type;    ///< e.g. "sensor_msgs/PointCloud2"
    std::string md5sum;  ///< of the message definition ("" when the record has none)
};

/// One message record: where it is and when it was recorded.
struct BagMessageRef {
    std::uint32_t connection = 0;
    std::uint32_t sec = 0, nsec = 0;  ///< receive time
    std::uint64_t chunk_pos = 0;      ///< file offset of its chunk record (0: not in a chunk)
    std::uint64_t offset = 0;         ///< offset of its data in the chunk's (uncompressed) data, or in the file
    std::uint32_t size = 0;           ///< bytes of message data
};

/// The structure of a bag: checked once, read message by message afterwards.
class BagFile {
public:
    /// Opens and checks the whole record structure; throws InputError(path, problem).
    /// `want_topic`: only messages of connections on this topic are indexed.
    BagFile(const std::string &path, const std::string &want_topic);
    ~BagFile();
    BagFile(const BagFile &) = delete;
    BagFile &operator=(const BagFile &) = delete;

    const std::vector<BagConnection> &connections() const { return connections_; }
    /// The indexed messages of the topic, in receive-time order (file order for ties).
    const std::vector<BagMessageRef> &messages() const { return messages_; }
    /// The serialized bytes of one message (decompressing its chunk when needed).
    std::string read(const BagMessageRef &m);

private:
    struct Impl;
    Impl *impl_;
    std::vector<BagConnection> connections_;
    std::vector<BagMessageRef> messages_;
};

/// A view of serialized ROS 1 message bytes, read with every length checked.
class RosReader {
public:
    RosReader(const std::string &bytes, const std::string &source) : bytes_(bytes), source_(source) {}
    std::uint8_t u8();
    std::uint32_t u32();
    std::string string();
    /// A string that becomes text (JSON): not UTF-8 is an InputError naming `field`.
    std::string text(const char *field);
    /// A uint8[] array: its length, and the position of its first byte in the message.
    std::size_t bytes(std::size_t &length);
    std::size_t remaining() const { return bytes_.size() - pos_; }

private:
    void need(std::size_t n);
    const std::string &bytes_;
    const std::string &source_;
    std::size_t pos_ = 0;
};

}  // namespace projsurf
