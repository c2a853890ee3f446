#pragma once
// Writing a ROS 1 bag (format 2.0) without ROS: connections, messages in time order,
// uncompressed chunks with their index records, and the index section (connections and chunk
// infos) that rosbag and projsurf's reader (bag_records.hpp) use.
#include <cstdint>
#include <string>
#include <vector>

namespace projsurf {

class BagWriter {
public:
    /// A topic of `type` (e.g. "sensor_msgs/Image", with its md5sum and definition); its id.
    std::uint32_t addConnection(const std::string &topic, const std::string &type, const std::string &md5sum,
                                const std::string &definition);
    /// One serialized message on connection `conn`, recorded at sec.nsec (messages are kept
    /// in the order given; give them in time order).
    void addMessage(std::uint32_t conn, std::uint32_t sec, std::uint32_t nsec, const std::string &bytes);
    /// The bag's bytes (chunks of about 4 MiB).
    std::string bytes() const;

private:
    struct Connection {
        std::string topic, type, md5sum, definition;
    };
    struct Message {
        std::uint32_t conn, sec, nsec;
        std::string bytes;
    };
    std::vector<Connection> connections_;
    std::vector<Message> messages_;
};

}  // namespace projsurf
