#include "projsurf/calibration/decoded_points.hpp"

#include <algorithm>
#include <stdexcept>

namespace projsurf {

std::vector<ProjectorCorrespondence> liftDecoding(const GrayDecoding &d, const cv::Mat &depth,
                                                  const CameraIntrinsics &camera, double edge_m) {
    std::vector<ProjectorCorrespondence> out;
    liftDecoding(d, depth, camera, out, edge_m);
    return out;
}

void liftDecoding(const GrayDecoding &d, const cv::Mat &depth, const CameraIntrinsics &camera,
                  std::vector<ProjectorCorrespondence> &out, double edge_m) {
    if (depth.type() != CV_16UC1 || depth.size() != d.confidence.size())
        throw std::invalid_argument("structured light: the depth image must be 16-bit and of the colour images' size");
    const double scale = 1.0 / camera.depth_scale;
    for (int y = 1; y + 1 < depth.rows; ++y)
        for (int x = 1; x + 1 < depth.cols; ++x) {
            if (!d.confidence.at<uchar>(y, x)) continue;
            const int raw = depth.at<std::uint16_t>(y, x);
            if (raw == 0) continue;
            int lo = raw, hi = raw;
            bool hole = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int q = depth.at<std::uint16_t>(y + dy, x + dx);
                    if (q == 0) hole = true;
                    lo = std::min(lo, q);
                    hi = std::max(hi, q);
                }
            if (hole || (hi - lo) * scale > edge_m) continue;
            ProjectorCorrespondence c;
            c.point = camera.backProject(x, y, raw * scale);
            c.pixel = {d.column.at<double>(y, x), d.row.at<double>(y, x)};
            out.push_back(c);
        }
}

}  // namespace projsurf
