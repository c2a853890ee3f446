// projsurf bag: depth PNG frames and their camera.yaml -> a ROS 1 bag of depth images and
// camera_infos (as a depth camera's driver publishes them), for `detect --bag` and the node.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <opencv2/imgcodecs.hpp>

#include "cli/commands.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/utf8_text.hpp"
#include "projsurf/io/rosbag/bag_writer.hpp"
#include "projsurf/io/rosbag/ros_messages.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace fs = std::filesystem;

namespace projsurf::cli {
namespace {

struct BagOptions {
    std::string depth_dir, camera, out;
    std::string topic = "/camera/depth/image_rect";  // the node's depth/image_rect under /camera
    std::string info_topic;                          // default: camera_info beside the depth topic
    std::string frame_id = "camera_depth_optical_frame";
    double fps = 30.0;   // Hz, a depth camera's usual rate
    double start = 1.0;  // s, the first frame's stamp (0 would read as "no stamp")
};

/// The depth PNGs of `dir`, in name order (0001.png, 0002.png, ... or any names that sort).
std::vector<fs::path> depthFrames(const std::string &dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(dir, "not a directory (--depth-dir)");
    std::vector<fs::path> out;
    for (const auto &e : fs::directory_iterator(dir, ec)) {
        std::string ext = e.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
        if (ext != ".png") continue;
        requireReadable(e.path().string());  // a FIFO, folder or broken link named .png: one line, never a wait
        out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    if (out.empty()) throw InputError(dir, "holds no .png depth frames");
    if (out.size() > limits::kMaxBagMessages) throw InputError(dir, "more frames than one bag topic may hold");
    return out;
}

void run(const BagOptions &o) {
    if (!(o.fps > 0 && o.fps <= 1000)) throw InputError("--fps", "must be within (0, 1000] Hz");
    if (!(o.start > 0 && o.start < 4e9)) throw InputError("--start", "must be a positive stamp in seconds");
    const std::string info_topic =
        !o.info_topic.empty() ? o.info_topic : o.topic.substr(0, o.topic.find_last_of('/') + 1) + "camera_info";
    if (info_topic == o.topic) throw InputError("--camera-info-topic", "must differ from --topic");
    // ROS strings are UTF-8: a bag with other bytes there would be refused by every reader of it.
    for (const auto &[name, text] : {std::pair<const char *, const std::string &>{"--topic", o.topic},
                                     {"--camera-info-topic", info_topic},
                                     {"--frame-id", o.frame_id}})
        if (!isUtf8(text)) throw InputError(name, "must be UTF-8 text (ROS strings are)");
    const CameraIntrinsics camera = readCamera(o.camera);
    const std::vector<fs::path> frames = depthFrames(o.depth_dir);
    requireWritableFile(o.out);

    BagWriter bag;
    const std::uint32_t depth_conn = bag.addConnection(o.topic, kImageType, kImageMd5, kImageDefinition);
    const std::uint32_t info_conn =
        bag.addConnection(info_topic, kCameraInfoType, kCameraInfoMd5, kCameraInfoDefinition);
    const double to_mm = 1000.0 / camera.depth_scale;  // the bag holds millimetres (16UC1, REP 118)
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const std::string name = frames[k].string();
        // Another size is named with both sizes from the header (not as a size limit).
        const cv::Mat raw = readImageOfSize(name, cv::IMREAD_UNCHANGED, camera.width, camera.height, o.camera);
        if (raw.type() != CV_16UC1) throw InputError(name, "expected a 16-bit single-channel depth PNG");
        cv::Mat mm;
        raw.convertTo(mm, CV_16UC1, to_mm);  // rounds, saturates at 65.535 m
        RosHeader h;
        h.seq = static_cast<std::uint32_t>(k);
        const double t = o.start + static_cast<double>(k) / o.fps;
        h.sec = static_cast<std::uint32_t>(std::floor(t));
        h.nsec = std::min<std::uint32_t>(999999999u, static_cast<std::uint32_t>(std::lround((t - h.sec) * 1e9)));
        h.frame_id = o.frame_id;
        // camera_info first, as drivers publish it; both with the frame's stamp.
        bag.addMessage(info_conn, h.sec, h.nsec, serializeCameraInfo(h, camera));
        bag.addMessage(depth_conn, h.sec, h.nsec, serializeDepthImage(h, mm));
    }
    OutputGroup outputs;
    outputs.addFile(o.out, bag.bytes());
    outputs.commit();
    std::printf("projsurf bag: %zu depth frames of %s -> %s (%s, %s; %.0f Hz)\n", frames.size(), o.depth_dir.c_str(),
                o.out.c_str(), o.topic.c_str(), info_topic.c_str(), o.fps);
}

}  // namespace

void addBagCommand(CLI::App &app) {
    auto o = std::make_shared<BagOptions>();
    auto *sub = app.add_subcommand("bag", "write depth PNG frames as a ROS 1 bag of depth images and camera_infos");
    sub->add_option("--depth-dir", o->depth_dir, "folder of 16-bit depth PNGs, taken in name order")->required();
    sub->add_option("--camera", o->camera, "camera intrinsics YAML of the frames (its depth_scale is converted to mm)")
        ->required();
    sub->add_option("--out", o->out, "bag to write")->required();
    sub->add_option("--topic", o->topic, "depth image topic (sensor_msgs/Image, 16UC1 in mm)")->capture_default_str();
    sub->add_option("--camera-info-topic", o->info_topic,
                    "camera_info topic (default: camera_info beside --topic, e.g. /camera/depth/camera_info)");
    sub->add_option("--frame-id", o->frame_id, "header frame_id of every message")->capture_default_str();
    sub->add_option("--fps", o->fps, "frame rate the stamps are spaced by, Hz")->capture_default_str();
    sub->add_option("--start", o->start, "stamp of the first frame, s")->capture_default_str();
    sub->callback([o] { run(*o); });
}

}  // namespace projsurf::cli
