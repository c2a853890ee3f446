// What became of every candidate plane (`detect --explain`'s data): every plane considered is
// reported, one is chosen when something is found, the others say why they lost.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "projsurf/detection/default/observed_free_space.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/settings/minimum_size.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/types/formatted.hpp"

using namespace projsurf;

namespace {

Detection detectScene(const std::string &name, double distance, double angle, Method method = Method::Default) {
    const sim::Scenario sc = sim::makeScenario(name, distance, angle);
    const sim::RgbdFrame frame = sim::renderFrame(sc.scene, sim::SensorModel{}, 3);
    DetectorConfig cfg;
    cfg.method = method;
    return detectSurface(frame.cloud, sim::exampleProjector(), cfg, sc.gravity);
}

int countVerdict(const Detection &det, CandidateVerdict v) {
    return static_cast<int>(std::count_if(det.candidates.begin(), det.candidates.end(),
                                          [&](const CandidateOutcome &o) { return o.verdict == v; }));
}

/// The rules every detection's candidates keep, whatever the scene.
void expectConsistent(const Detection &det, const std::string &scene) {
    SCOPED_TRACE(scene);
    ASSERT_EQ(det.candidates.size(), det.debug.candidates.size());
    EXPECT_EQ(countVerdict(det, CandidateVerdict::Chosen), det.found ? 1 : 0);
    const Rectangle winner = winningRectangle(det.candidates, det.rectangle);
    for (const CandidateOutcome &o : det.candidates) {
        EXPECT_FALSE(outcomeWords(o, winner).empty());
        EXPECT_GT(o.seen_width, 0.0);
        EXPECT_GT(o.seen_height, 0.0);
        for (const auto &corner : o.seen) EXPECT_NEAR(o.plane.signedDistance(corner), 0.0, 1e-6);
        if (o.verdict == CandidateVerdict::Chosen) {
            EXPECT_EQ(o.rectangle.corners, det.rectangle.corners);
        } else if (det.found) {
            EXPECT_LE(o.rectangle.area(), det.rectangle.area() + 1e-12) << outcomeWords(o, winner);
        }
    }
}

}  // namespace

TEST(CandidateOutcome, EveryPlaneConsideredIsReportedAndOneChosen) {
    for (const char *scene : {"wall", "desk", "closet", "corner", "door", "person"}) {
        const Detection det = detectScene(scene, 2.0, 17.19);
        EXPECT_FALSE(det.candidates.empty()) << scene;
        expectConsistent(det, scene);
    }
}

TEST(CandidateOutcome, TheBigBoxIsNamedFurniture) {
    // Paper 4.3's big obstacle: a box 0.45 m deep standing on the floor before the wall.
    const Detection det = detectScene("big_obstacle", 2.0, 0.0);
    expectConsistent(det, "big_obstacle");
    ASSERT_TRUE(det.found) << det.reason;
    EXPECT_GE(countVerdict(det, CandidateVerdict::Object), 1);
    for (const CandidateOutcome &o : det.candidates)
        if (o.verdict == CandidateVerdict::Object) {
            EXPECT_LT(std::abs(o.plane.d), std::abs(det.plane.d));  // in front of the wall
        }
}

TEST(CandidateOutcome, TheSideWallOfACornerIsNotReachedOrSmaller) {
    const Detection det = detectScene("corner", 2.0, 17.19);
    expectConsistent(det, "corner");
    ASSERT_GE(det.candidates.size(), 2u);
    EXPECT_EQ(countVerdict(det, CandidateVerdict::Chosen), 1);
}

TEST(CandidateOutcome, ThePaperMethodReportsItsOnePlane) {
    const Detection det = detectScene("wall", 2.0, 17.19, Method::Paper);
    ASSERT_TRUE(det.found) << det.reason;
    ASSERT_EQ(det.candidates.size(), 1u);
    EXPECT_EQ(det.candidates[0].verdict, CandidateVerdict::Chosen);
    EXPECT_EQ(det.candidates[0].inliers, det.inliers);
    EXPECT_GT(det.candidates[0].seen_width, det.rectangle.width);
}

TEST(CandidateOutcome, BeamCellsAreSharesAndTheMainBlockerIsTheCommonest) {
    cv::Mat state(2, 4, CV_8U, cv::Scalar(static_cast<int>(CellState::Free)));
    state.at<uchar>(0, 0) = static_cast<uchar>(CellState::InFront);
    state.at<uchar>(0, 1) = static_cast<uchar>(CellState::InFront);
    state.at<uchar>(0, 2) = static_cast<uchar>(CellState::Dark);
    state.at<uchar>(1, 3) = static_cast<uchar>(CellState::Edge);
    cv::Mat beam(2, 4, CV_8U, cv::Scalar(255));
    beam.at<uchar>(1, 0) = 0;  // outside the beam: not counted
    CandidateOutcome o;
    setBeamCells(state, beam, o);
    EXPECT_DOUBLE_EQ(o.beam_cells[static_cast<int>(CellState::InFront)], 2.0 / 7.0);
    EXPECT_DOUBLE_EQ(o.beam_cells[static_cast<int>(CellState::Free)], 3.0 / 7.0);
    EXPECT_EQ(mainBlocker(o), static_cast<int>(CellState::InFront));
    o.verdict = CandidateVerdict::NoFreeArea;
    EXPECT_EQ(outcomeName(o), "shadowed");
    EXPECT_NE(outcomeWords(o, Rectangle{}).find("29 %"), std::string::npos) << outcomeWords(o, Rectangle{});
}

TEST(ComparedPair, DifferentValuesNeverPrintAlike) {
    EXPECT_EQ(comparedPair(0.14997, 0.15), std::make_pair(std::string("0.14997"), std::string("0.15000")));
    EXPECT_EQ(comparedPair(0.1234, 0.5), std::make_pair(std::string("0.123"), std::string("0.500")));
    EXPECT_EQ(comparedPair(0.2, 0.2), std::make_pair(std::string("0.200"), std::string("0.200")));
    EXPECT_EQ(comparedPair(0.622222, 0.6225), std::make_pair(std::string("0.622"), std::string("0.623")));
    EXPECT_EQ(limitPair(0.622222, 0.6225), std::make_pair(std::string("0.6222"), std::string("0.6225")));
    EXPECT_EQ(limitPair(0.1, 0.2), std::make_pair(std::string("0.100"), std::string("0.200")));
}

TEST(MinimumSize, TheReasonsNumbersDifferAndTheCandidateIsTooSmall) {
    Detection det;
    det.found = true;
    det.rectangle.width = 0.14996;
    det.rectangle.height = 0.0844;
    // Rectangle leaves its corners uninitialised (Eigen): give them, as the detector does, since
    // the winner is matched by its corners.
    det.rectangle.corners = {Eigen::Vector3d(-0.075, -0.042, 2.0), Eigen::Vector3d(0.075, -0.042, 2.0),
                             Eigen::Vector3d(0.075, 0.042, 2.0), Eigen::Vector3d(-0.075, 0.042, 2.0)};
    CandidateOutcome chosen;
    chosen.verdict = CandidateVerdict::Chosen;
    chosen.rectangle = det.rectangle;
    det.candidates = {chosen};
    ASSERT_TRUE(frontend::enforceMinimumSize(det, frontend::MinimumSize{}, "--min-width", "--min-area"));
    EXPECT_FALSE(det.found);
    EXPECT_NE(det.reason.find("0.14996 x 0.084 m, is narrower than --min-width 0.15000 m"), std::string::npos)
        << det.reason;
    EXPECT_EQ(det.candidates[0].verdict, CandidateVerdict::TooSmall);
    EXPECT_NE(det.candidates[0].detail.find("0.14996"), std::string::npos) << det.candidates[0].detail;
    // The winner it lost to is still the detection's rectangle.
    EXPECT_EQ(winningRectangle(det.candidates, det.rectangle).width, det.rectangle.width);
}

TEST(MinimumSize, ARectangleOfTheMinimumRoundedIsNotBelowIt) {
    Detection det;
    det.found = true;
    det.rectangle.width = 0.15 - 1e-10;  // 15 cells of 1 cm, as computed
    det.rectangle.height = 0.084;
    EXPECT_FALSE(frontend::enforceMinimumSize(det, frontend::MinimumSize{}, "--min-width", "--min-area"));
    EXPECT_TRUE(det.found);
}
