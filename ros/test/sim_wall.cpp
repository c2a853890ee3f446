#include "sim_wall.hpp"

#include <cmath>
#include <limits>
#include <random>

#include "projsurf/io/yaml_files.hpp"

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

Cloud renderScene(const Eigen::Isometry3d &odom_from_camera, const SceneOptions &o) {
    const int w = 320, h = 240;
    const double f = 262.5, cx = 159.5, cy = 119.5;
    std::mt19937 rng(o.seed);
    std::normal_distribution<double> unit(0.0, 1.0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Cloud cloud;
    cloud.width = w;
    cloud.height = h;
    cloud.points.resize(static_cast<std::size_t>(w) * h);
    const Eigen::Vector3d origin = odom_from_camera.translation();
    for (int v = 0; v < h; ++v) {
        for (int u = 0; u < w; ++u) {
            const Eigen::Vector3d ray_cam((u - cx) / f, (v - cy) / f, 1.0);  // z = 1: t is the depth
            const Eigen::Vector3d ray = odom_from_camera.linear() * ray_cam;
            double best = 8.0;
            auto hit = [&](double t, const Eigen::Vector3d &p, bool inside) {
                if (t > 0.05 && t < best && inside) best = t;
                (void)p;
            };
            if (o.front_wall && std::abs(ray.x()) > 1e-9) {
                const double t = (2.0 - origin.x()) / ray.x();
                const Eigen::Vector3d p = origin + t * ray;
                hit(t, p, p.y() > -1.2 && p.y() < 3.0 && p.z() > 0.0 && p.z() < 2.6);
            }
            if (o.side_wall && std::abs(ray.y()) > 1e-9) {
                const double t = (-1.2 - origin.y()) / ray.y();
                const Eigen::Vector3d p = origin + t * ray;
                hit(t, p, p.x() < (o.front_wall ? 2.0 : 8.0) && p.x() > -2.0 && p.z() > 0.0 && p.z() < 2.6);
            }
            if (std::abs(ray.z()) > 1e-9) {
                const double t = (0.0 - origin.z()) / ray.z();
                const Eigen::Vector3d p = origin + t * ray;
                const double far = o.front_wall ? 2.0 : 8.0;
                hit(t, p, p.x() < far && (!o.side_wall || p.y() > -1.2));
            }
            if (o.person && std::abs(ray.x()) > 1e-9) {
                const double t = (o.person_x - origin.x()) / ray.x();
                const Eigen::Vector3d p = origin + t * ray;
                hit(t, p, std::abs(p.y() - o.person_y) <= 0.22 && p.z() >= 0.0 && p.z() <= 1.7);
            }
            Point &out = cloud.points[static_cast<std::size_t>(v) * w + u];
            if (best >= 8.0) {
                out = Point(nan, nan, nan);
                continue;
            }
            const double z = best + o.noise_k * best * best * unit(rng);  // depth noise along the ray
            out = (z * ray_cam).cast<float>();
        }
    }
    return cloud;
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
