#include "projsurf/frontend/inputs/chessboard_calibration.hpp"

#include "projsurf/calibration/chessboard_pose.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/io/files/errors.hpp"

namespace projsurf::frontend {

ChessboardCalibration calibrateChessboard(const ProcamFolder &folder, double square_m) {
    ChessboardCalibration out;
    out.square_m = square_m;
    out.width = folder.width;
    out.height = folder.height;
    const std::vector<GrayPattern> order = openCvGrayPatterns(folder.width, folder.height);
    std::vector<StereoView> views;
    int boards = 0;
    double share_sum = 0;
    for (const ProcamPose &pose : folder.poses) {
        const std::vector<cv::Mat> captures = readProcamPose(pose, folder.camera_width, folder.camera_height);
        out.camera_size = captures[0].size();
        ChessboardPoseConfig cfg;
        cfg.square = square_m;
        if (out.inner.area() > 0) cfg.board_sizes = {out.inner};  // the first board found fixes the count
        const projsurf::ChessboardPose found = chessboardPose(captures, order, folder.width, folder.height, cfg);
        ChessboardPose r;
        r.dir = pose.dir;
        r.decoded = found.decoded_pixels;
        if (found.board_found) {
            out.inner = found.inner;
            r.board = true;
            r.corners = found.corners;
            r.carried = static_cast<int>(found.view.board.size());
            r.board_share = found.decoded_board_share;
            ++boards;
            share_sum += r.board_share;
            // A view with a few corners not carried is still a view of the planar board.
            if (r.carried * 2 >= r.corners) views.push_back(found.view);
        }
        out.poses.push_back(r);
    }
    if (boards == 0)
        throw InputError(folder.poses.front().dir,
                         "no chessboard found in the white-pattern capture of any pose (graycode_" +
                             std::to_string(order.size() - 2) + ")");
    out.decoded_board_share = share_sum / boards;
    if (views.size() < 3)
        throw InputError(folder.poses.front().dir,
                         std::to_string(views.size()) +
                             " pose(s) with a chessboard whose corners decoded; capture 3 or more board poses");
    out.fit = fitStereo(views, out.camera_size, cv::Size(folder.width, folder.height));
    if (!out.fit.ok) throw InputError(folder.poses.front().dir, out.fit.problem);
    return out;
}

}  // namespace projsurf::frontend
