#pragma once
// An unorganized cloud in the camera frame (a filtered PCD, an Open3D export) as the depth image
// a pinhole at the camera's origin would have taken of it, so that it takes the depth-image path
// of the default method (image neighbourhoods, what stands free, where the wall is seen). The
// projector sits beside the camera, so what that pinhole cannot see (behind the nearest surface)
// the projector could not light either.
#include <optional>
#include <vector>

#include "projsurf/detection/pixel_lattice.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf {

struct VirtualImageConfig {
    bool enabled = true;               ///< unorganized clouds as a pinhole's depth image; false: sequential RANSAC
    double max_half_angle_deg = 70.0;  ///< (0, 89] deg off the optical axis kept (the projector's beam is < 30)
    double fill =
        1.0;  ///< (0, 16] clouds on no pixel grid: pixels per point over the covered view (1: the cloud's own density)
    int max_pixels = 1 << 20;     ///< [1, 2^24] px, image size cap (about 1.3 x 1280x800)
    int min_points = 500;         ///< [1, 2^24] fewer points in front of the camera: no image
    PixelLatticeOptions lattice;  ///< how a cloud's own pixel grid (a depth image's) is recognised
};

struct VirtualDepthImage {
    Cloud cloud;              ///< organized, the input's own points (nearest per pixel), NaN elsewhere
    std::vector<int> source;  ///< per pixel, the index of its point in the input cloud; -1 where none
};

/// The z-buffered image (nearest point per pixel). A cloud whose points lie on a pinhole's pixel
/// grid (a depth image's points, shuffled, filtered or cropped: x/z and y/z on lattices of step
/// 1 / fx and 1 / fy) comes back on that grid, pixel for pixel, from its first to its last
/// column and row holding a point; any other cloud at its own angular density, over the
/// points' extent (the outermost 0.1 % on each side left out). Nullopt when the cloud is
/// organized already, has too few points in front of the camera, or `config.enabled` is false.
std::optional<VirtualDepthImage> virtualDepthImage(const Cloud &cloud, const VirtualImageConfig &config);

}  // namespace projsurf
