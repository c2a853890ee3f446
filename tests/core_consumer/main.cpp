// Detection and keystone with projsurf::core only: a flat wall 2 m ahead of a level camera,
// the contract's example projector. Exits 0 when a rectangle is found and can be shown.
#include <iostream>

#include "projsurf/detector.hpp"
#include "projsurf/keystone.hpp"

int main() {
    projsurf::Cloud cloud;
    for (int y = -60; y <= 60; ++y)
        for (int x = -100; x <= 100; ++x) cloud.points.emplace_back(0.01f * x, 0.01f * y, 2.0f);
    cloud.width = static_cast<int>(cloud.points.size());

    projsurf::Projector projector;  // 1280x800, 39.3 x 24.0 deg, lens 0.12 m below the camera
    projector.direction = Eigen::Vector3d(0.0, -0.05, 1.0).normalized();
    const projsurf::Detection det = projsurf::detectSurface(cloud, projector, projsurf::DetectorConfig{});
    if (!det.found) {
        std::cerr << "core_consumer: no surface: " << det.reason << "\n";
        return 1;
    }
    const projsurf::KeystoneResult k = projsurf::computeKeystone(projector, det.rectangle, {1280, 720});
    if (!k.keystone) {
        std::cerr << "core_consumer: no keystone: " << k.problem << "\n";
        return 1;
    }
    std::cout << "core_consumer: rectangle " << det.rectangle.width << " x " << det.rectangle.height << " m\n";
    return 0;
}
