#include "projsurf/calibration/chessboard_pose.hpp"

#include "projsurf/calibration/chessboard_corners.hpp"

namespace projsurf {

ChessboardPose chessboardPose(const std::vector<cv::Mat> &captures, const std::vector<GrayPattern> &order, int width,
                              int height, const ChessboardPoseConfig &cfg) {
    ChessboardPose pose;
    const GrayDecoding d = decodeGray(captures, order, width, height, cfg.decode);
    pose.decoded_pixels = d.decoded;
    std::size_t white = 0;
    while (white < order.size() && order[white].kind != GrayPattern::Kind::White) ++white;
    const ChessboardCorners board = findChessboard(captures.at(white), cfg.board_sizes);
    if (!board.found) return pose;
    pose.board_found = true;
    pose.inner = board.inner;
    pose.corners = static_cast<int>(board.corners.size());
    pose.decoded_board_share = decodedBoardShare(d, board.corners, board.inner);
    const auto object = chessboardObjectPoints(board.inner, cfg.square);
    const auto carried = cornersInProjector(d, board.corners, cfg.homography);
    for (std::size_t i = 0; i < carried.size(); ++i) {
        if (!carried[i].ok) continue;
        pose.view.board.push_back(object[i]);
        pose.view.camera.push_back(board.corners[i]);
        pose.view.projector.push_back(carried[i].projector);
    }
    return pose;
}

}  // namespace projsurf
