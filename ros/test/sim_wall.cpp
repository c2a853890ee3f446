#include "sim_wall.hpp"

#include <cmath>
#include <limits>
#include <random>

#include "projsurf/io/yaml/yaml_files.hpp"

namespace projsurf::sim_test {

Eigen::Isometry3d cameraPose(double x, double y, double yaw) {
    // Optical axes in a z-up frame heading along +x: z_opt = x, x_opt = -y, y_opt = -z.
    Eigen::Matrix3d base;
    base.col(0) = Eigen::Vector3d(0, -1, 0);
    base.col(1) = Eigen::Vector3d(0, 0, -1);
    base.col(2) = Eigen::Vector3d(1, 0, 0);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * base;
    T.translation() = Eigen::Vector3d(x, y, 1.0);
    return T;
}

namespace {

constexpr int kWidth = 320, kHeight = 240;
constexpr double kF = 262.5, kCx = 159.5, kCy = 119.5;

enum class Surface { None, FrontWall, SideWall, Floor, Person };

/// The nearest surface along pixel (u, v)'s ray within 8 m; `t` is its depth (camera z).
Surface castRay(const Eigen::Isometry3d &odom_from_camera, const SceneOptions &o, int u, int v, double &t_out,
                Eigen::Vector3d &hit_out) {
    const Eigen::Vector3d origin = odom_from_camera.translation();
    const Eigen::Vector3d ray_cam((u - kCx) / kF, (v - kCy) / kF, 1.0);  // z = 1: t is the depth
    const Eigen::Vector3d ray = odom_from_camera.linear() * ray_cam;
    double best = 8.0;
    Surface what = Surface::None;
    auto hit = [&](double t, const Eigen::Vector3d &p, bool inside, Surface s) {
        if (t > 0.05 && t < best && inside) best = t, what = s, hit_out = p;
    };
    if (o.front_wall && std::abs(ray.x()) > 1e-9) {
        const double t = (2.0 - origin.x()) / ray.x();
        const Eigen::Vector3d p = origin + t * ray;
        hit(t, p, p.y() > -1.2 && p.y() < 3.0 && p.z() > 0.0 && p.z() < 2.6, Surface::FrontWall);
    }
    if (o.side_wall && std::abs(ray.y()) > 1e-9) {
        const double t = (-1.2 - origin.y()) / ray.y();
        const Eigen::Vector3d p = origin + t * ray;
        hit(t, p, p.x() < (o.front_wall ? 2.0 : 8.0) && p.x() > -2.0 && p.z() > 0.0 && p.z() < 2.6, Surface::SideWall);
    }
    if (std::abs(ray.z()) > 1e-9) {
        const double t = (0.0 - origin.z()) / ray.z();
        const Eigen::Vector3d p = origin + t * ray;
        const double far = o.front_wall ? 2.0 : 8.0;
        hit(t, p, p.x() < far && (!o.side_wall || p.y() > -1.2), Surface::Floor);
    }
    if (o.person && std::abs(ray.x()) > 1e-9) {
        const double t = (o.person_x - origin.x()) / ray.x();
        const Eigen::Vector3d p = origin + t * ray;
        hit(t, p, std::abs(p.y() - o.person_y) <= 0.22 && p.z() >= 0.0 && p.z() <= 1.7, Surface::Person);
    }
    t_out = best;
    return what;
}

}  // namespace

Cloud renderScene(const Eigen::Isometry3d &odom_from_camera, const SceneOptions &o) {
    std::mt19937 rng(o.seed);
    std::normal_distribution<double> unit(0.0, 1.0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Cloud cloud;
    cloud.width = kWidth;
    cloud.height = kHeight;
    cloud.points.resize(static_cast<std::size_t>(kWidth) * kHeight);
    for (int v = 0; v < kHeight; ++v) {
        for (int u = 0; u < kWidth; ++u) {
            double best = 0.0;
            Eigen::Vector3d p;
            const Surface s = castRay(odom_from_camera, o, u, v, best, p);
            Point &out = cloud.points[static_cast<std::size_t>(v) * kWidth + u];
            if (s == Surface::None) {
                out = Point(nan, nan, nan);
                continue;
            }
            const double z = best + o.noise_k * best * best * unit(rng);  // depth noise along the ray
            out = (z * Eigen::Vector3d((u - kCx) / kF, (v - kCy) / kF, 1.0)).cast<float>();
        }
    }
    return cloud;
}

cv::Mat renderColour(const Eigen::Isometry3d &odom_from_camera, const SceneOptions &o) {
    std::mt19937 rng(o.seed + 7919u);
    std::normal_distribution<double> noise(0.0, 2.0);
    cv::Mat bgr(kHeight, kWidth, CV_8UC3, cv::Scalar::all(0));
    // The picture's blocks: 4 cm squares, each its own colour (a fixed hash of the block).
    auto block = [](int i, int j, int channel) {
        const unsigned h = static_cast<unsigned>(i * 73856093) ^ static_cast<unsigned>(j * 19349663) ^
                           static_cast<unsigned>(channel * 83492791);
        return 30.0 + static_cast<double>((h * 2654435761u) >> 24) * 200.0 / 255.0;
    };
    for (int v = 0; v < kHeight; ++v) {
        for (int u = 0; u < kWidth; ++u) {
            double t = 0.0;
            Eigen::Vector3d p;
            const Surface s = castRay(odom_from_camera, o, u, v, t, p);
            cv::Vec3d c(0, 0, 0);
            switch (s) {
                case Surface::FrontWall: c = {215, 220, 222}; break;  // white paint
                case Surface::SideWall: c = {150, 185, 210}; break;   // beige paint
                case Surface::Floor: c = {105, 110, 112}; break;      // grey floor
                case Surface::Person: c = {45, 40, 60}; break;        // dark clothes
                case Surface::None: break;
            }
            if (s == Surface::FrontWall && o.picture && p.y() >= o.picture_y0 && p.y() <= o.picture_y1 &&
                p.z() >= o.picture_z0 && p.z() <= o.picture_z1) {
                const double frame = 0.04;  // m, the frame's width
                if (p.y() < o.picture_y0 + frame || p.y() > o.picture_y1 - frame || p.z() < o.picture_z0 + frame ||
                    p.z() > o.picture_z1 - frame) {
                    c = {25, 40, 60};  // dark wood
                } else {
                    const int i = static_cast<int>(std::floor(p.y() / 0.04)), j = static_cast<int>(std::floor(p.z() / 0.04));
                    c = {block(i, j, 0), block(i, j, 1), block(i, j, 2)};
                }
            }
            if (s != Surface::None)
                for (int k = 0; k < 3; ++k) c[k] += noise(rng);
            for (int k = 0; k < 3; ++k) bgr.at<cv::Vec3b>(v, u)[k] = cv::saturate_cast<uchar>(c[k]);
        }
    }
    return bgr;
}

bool hitsPerson(const SceneOptions &o, const Eigen::Vector3d &origin, const Eigen::Vector3d &dir) {
    if (!o.person || std::abs(dir.x()) < 1e-9) return false;
    const double t = (o.person_x - origin.x()) / dir.x();
    if (t <= 0.0) return false;
    const Eigen::Vector3d p = origin + t * dir;
    return std::abs(p.y() - o.person_y) <= 0.22 && p.z() >= 0.0 && p.z() <= 1.7;  // nearer than the wall at x = 2
}

Projector testProjector() {
    Projector p;
    p.width = 1280;
    p.height = 800;
    p.fov_h = 39.3 * M_PI / 180.0;
    p.fov_v = 24.0 * M_PI / 180.0;
    p.origin = Eigen::Vector3d(0.0, 0.12, 0.0);
    p.direction = Eigen::Vector3d(0.0, -0.05, 1.0).normalized();
    return p;
}

void writeTestCalibration(const std::string &path) { writeCalibration(path, testProjector()); }

}  // namespace projsurf::sim_test
