#include "eval/real/real_gallery.hpp"

#include "projsurf/detection/gravity.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "eval/plot/plot.hpp"
#include "projsurf/frontend/render/overlay.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace fs = std::filesystem;

namespace projsurf::eval {

std::vector<std::string> listFrameFolders(const std::string &dir) {
    std::vector<std::string> out;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return out;
    for (const auto &e : fs::directory_iterator(dir, ec)) {
        if (!e.is_directory(ec)) continue;
        if (fs::exists(e.path() / "depth.png", ec) && fs::exists(e.path() / "camera.yaml", ec))
            out.push_back(e.path().string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

GalleryEntry detectRealFrame(const std::string &folder, const Projector &projector, const DetectorConfig &config,
                             const std::optional<Eigen::Vector3d> &gravity) {
    GalleryEntry g;
    g.name = fs::path(folder).filename().string();
    const std::string depth = (fs::path(folder) / "depth.png").string();
    const std::string camera_yaml = (fs::path(folder) / "camera.yaml").string();
    CameraIntrinsics camera;
    Cloud cloud;
    cv::Mat color;
    try {
        camera = readCamera(camera_yaml);
        cloud = readDepthCloud(depth, camera_yaml);
        const fs::path rgb = fs::path(folder) / "rgb.png";  // registered colour only
        std::error_code ec;
        if (fs::exists(rgb, ec)) {
            color = readImage(rgb.string(), cv::IMREAD_COLOR);
            if (color.cols != cloud.width || color.rows != cloud.height) color.release();
        }
    } catch (const std::exception &e) {
        g.problem = e.what();
        return g;
    }
    g.read = true;
    // These recordings have no IMU: take "down" from the floor when one is in view
    // (as `projsurf detect --gravity auto` does).
    Eigen::Vector3d down = gravity.value_or(SurfaceDetector::levelGravity());
    if (!gravity)
        if (const auto floor = estimateGravityFromFloor(cloud, down)) down = floor->gravity;
    const Detection det = detectSurface(cloud, projector, config, down);
    g.found = det.found;
    g.reason = det.reason;
    if (det.found) {
        g.width = det.rectangle.width;
        g.height = det.rectangle.height;
        g.area = det.rectangle.area();
        g.distance = det.plane.d;
        g.orientation_deg = det.orientation_deg;
        g.rectangle = det.rectangle;
    }
    g.points = det.surface_check.points;
    g.outliers = det.surface_check.outliers;
    const auto total = det.timing_ms.find("total");
    g.time_ms = total != det.timing_ms.end() ? total->second : 0.0;
    g.overlay = renderOverlay(cloud, det, config, &camera, color);
    return g;
}

cv::Mat contactSheet(const std::vector<GalleryEntry> &entries, int columns, int thumb_width) {
    std::vector<cv::Mat> panels;
    for (const auto &g : entries) {
        cv::Mat thumb;
        if (!g.overlay.empty()) {
            const double s = static_cast<double>(thumb_width) / g.overlay.cols;
            cv::resize(g.overlay, thumb, cv::Size(thumb_width, static_cast<int>(g.overlay.rows * s)), 0, 0,
                       cv::INTER_AREA);
        } else {
            thumb = cv::Mat(thumb_width * 3 / 4, thumb_width, CV_8UC3, cv::Scalar(60, 60, 60));
        }
        char line[160];
        if (!g.read)
            std::snprintf(line, sizeof line, "%s: unreadable", g.name.c_str());
        else if (g.found)
            std::snprintf(line, sizeof line, "%s: %.2f m^2, %.0f ms", g.name.c_str(), g.area, g.time_ms);
        else
            std::snprintf(line, sizeof line, "%s: not found", g.name.c_str());
        cv::Mat p = withCaption(thumb, line, 0.5);
        cv::copyMakeBorder(p, p, 4, 4, 4, 4, cv::BORDER_CONSTANT, cv::Scalar(255, 255, 255));
        panels.push_back(p);
    }
    return tilePanels(panels, columns,
                      "Detection on real RGB-D frames (default method, example calibration, gravity from the floor)");
}

}  // namespace projsurf::eval
