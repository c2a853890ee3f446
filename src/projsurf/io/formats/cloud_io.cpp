#include "projsurf/io/formats/cloud_io.hpp"

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/formats/cloud_format_parsing.hpp"
#include "projsurf/io/formats/pcd_file.hpp"
#include "projsurf/io/formats/ply_file.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/types/camera.hpp"

namespace projsurf {
namespace {

std::string readWholeFile(const std::string &path) {
    requireReadable(path);
    std::ifstream in(path, std::ios::binary);
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (!in || size < 0) throw InputError(path, "cannot read the file");
    if (static_cast<std::uint64_t>(size) > limits::kMaxCloudFileBytes)
        throw InputError(path, "point-cloud file of " + std::to_string(size) + " bytes exceeds the limit of " +
                                   std::to_string(limits::kMaxCloudFileBytes) + " bytes");
    in.seekg(0, std::ios::beg);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), size);
    if (in.gcount() != size) throw InputError(path, "cannot read the file");
    return bytes;
}

std::string lowerExtension(const std::string &path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char &c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

const char *depthName(int depth) {
    switch (depth) {
    case CV_8U: return "8-bit unsigned";
    case CV_8S: return "8-bit signed";
    case CV_16U: return "16-bit unsigned";
    case CV_16S: return "16-bit signed";
    case CV_32S: return "32-bit integer";
    case CV_32F: return "32-bit float";
    case CV_64F: return "64-bit float";
    default: return "unusual";
    }
}

}  // namespace

Cloud readCloud(const std::string &path) {
    const std::string ext = lowerExtension(path);
    if (ext != ".pcd" && ext != ".ply")
        throw InputError(path,
                         "unknown point-cloud file extension " + cloud_format::shown(ext) + " (expected .pcd or .ply)");
    const std::string bytes = readWholeFile(path);
    if (bytes.empty()) throw InputError(path, "empty file");
    Cloud cloud = ext == ".pcd" ? readPcd(path, bytes) : readPly(path, bytes);
    if (cloud.points.empty()) throw InputError(path, "the cloud has zero points");
    // A cloud whose points are all NaN is a valid frame (NaN points are allowed): the
    // detector answers found: false with its reason.
    return cloud;
}

Cloud readDepthCloud(const std::string &depth_png, const std::string &camera_yaml) {
    const CameraIntrinsics camera = readCamera(camera_yaml);
    const cv::Mat depth = readImage(depth_png, cv::IMREAD_UNCHANGED, limits::kMaxDepthPixels);
    if (depth.type() != CV_16UC1)
        throw InputError(depth_png, std::string("expected a 16-bit single-channel depth image, got ") +
                                        depthName(depth.depth()) + " with " + std::to_string(depth.channels()) +
                                        " channel(s)");
    if (depth.cols != camera.width || depth.rows != camera.height)
        throw InputError(depth_png, "depth image is " + std::to_string(depth.cols) + "x" + std::to_string(depth.rows) +
                                        " but " + camera_yaml + " says " + std::to_string(camera.width) + "x" +
                                        std::to_string(camera.height));
    if (cv::countNonZero(depth) == 0) throw InputError(depth_png, "no valid depth reading (every pixel is 0)");
    return depthToCloud(depth, camera);
}

}  // namespace projsurf
