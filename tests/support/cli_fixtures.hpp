#pragma once
// Input files for CLI tests: disc-calibration captures and a detection JSON of the contract's shape.
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "projsurf/calibration/calibration.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf::test {

/// Writes captures to `dir` as `calibrate --captures` reads them: camera.yaml (the default
/// intrinsics) and capture_<k>_rgb.png + capture_<k>_depth.png.
inline void writeCaptures(const std::filesystem::path &dir, const std::vector<CaptureImages> &caps) {
    std::filesystem::create_directories(dir);
    writeCamera((dir / "camera.yaml").string(), CameraIntrinsics{});
    for (std::size_t k = 0; k < caps.size(); ++k) {
        cv::imwrite((dir / ("capture_" + std::to_string(k) + "_rgb.png")).string(), caps[k].color);
        cv::imwrite((dir / ("capture_" + std::to_string(k) + "_depth.png")).string(), caps[k].depth);
    }
}

/// A detection JSON of the contract's shape for `rect` on `plane`.
inline void writeDetection(const std::filesystem::path &path, const Rectangle &rect, const Plane &plane) {
    nlohmann::json j;
    j["found"] = true;
    j["reason"] = nullptr;
    j["plane"]["coefficients"] = {plane.normal.x(), plane.normal.y(), plane.normal.z(), plane.d};
    j["plane"]["orientation_deg"] = orientationDeg(plane);
    j["plane"]["inliers"] = 1000;
    for (const auto &c : rect.corners) j["rectangle"]["corners"].push_back({c.x(), c.y(), c.z()});
    j["rectangle"]["width_m"] = rect.width;
    j["rectangle"]["height_m"] = rect.height;
    j["rectangle"]["area_m2"] = rect.area();
    j["surface_check"] = {{"points", 1000}, {"outliers", 0}, {"accepted", true}};
    j["timing_ms"]["total"] = 1.0;
    std::ofstream(path) << j.dump(2);
}

}  // namespace projsurf::test
