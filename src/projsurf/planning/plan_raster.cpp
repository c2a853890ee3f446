#include "projsurf/planning/plan_raster.hpp"

#include <cmath>

#include "projsurf/types/clamp_to_int.hpp"

namespace projsurf {

RasterFrame planRaster(const Eigen::Vector2d &lo, const Eigen::Vector2d &hi, double cell) {
    return makeRasterFrame(lo, hi, cell);
}

int floorGridHalf(double reach, double cell) { return clampToInt(std::ceil(reach / cell), 0, 1000); }

int cellIndex(double v, double cell) { return clampToInt(std::floor(v / cell + 0.5), -1000000, 1000000); }

}  // namespace projsurf
