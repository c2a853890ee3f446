#pragma once
// The same real frame handed over as users also have it: as an unorganized cloud (its finite
// points in any order, as a PCD export or a filtered cloud is), and as the depth image cropped
// by a pixel or three (a robot never sees the same pixel grid twice). The answer should not
// change with either.
#include <Eigen/Core>
#include <vector>

#include "projsurf/detector/detector.hpp"

namespace projsurf::eval {

/// A variant's answer against the organized frame's.
struct VariantRun {
    bool found = false;
    double area = 0.0;       ///< m^2
    double angle_deg = 0.0;  ///< between the two planes' normals
    double offset = 0.0;     ///< m, the organized rectangle's centre from the variant's plane
    bool agrees = false;     ///< both nothing, or plane <= 1 deg and <= 2 cm and area within 10 %
};

/// The finite points of `cloud` shuffled (fixed seed), detected with the same settings.
VariantRun unorganizedVariant(const Cloud &cloud, const Detection &organized, const Projector &projector,
                              const DetectorConfig &config, const Eigen::Vector3d &gravity);

/// The depth image cropped by (1, 1), (2, 0) and (0, 3) pixels at its top-left corner, detected
/// with the same settings.
std::vector<VariantRun> shiftedVariants(const Cloud &cloud, const Detection &organized, const Projector &projector,
                                        const DetectorConfig &config, const Eigen::Vector3d &gravity);

}  // namespace projsurf::eval
