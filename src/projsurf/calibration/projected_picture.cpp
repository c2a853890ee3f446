#include "projsurf/calibration/projected_picture.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>

#include "projsurf/calibration/greyscale.hpp"

namespace projsurf {

namespace {

/// The card's disc (grey 160 on white 255, 0.63) must read at least this much darker than the
/// rest of the lit picture in the camera, allowing for exposure and blur.
constexpr double kCardDiscDarker = 0.85;
/// The card is a filled quadrilateral: its outline fills at least this share of the
/// quadrilateral fitted to it (blur and the rounded corners of a defocused projection cost a
/// few per cent; a lit scene's bright pixels are ragged and fill much less).
constexpr double kCardMinFill = 0.9;

cv::Mat grey8(const cv::Mat &m) {
    cv::Mat g = greyscale(m);
    if (g.depth() != CV_8U) g.convertTo(g, CV_8U);
    return g;
}

/// The corner of `pts` extreme in direction (sx, sy): TL = (-1,-1), TR = (1,-1), ...
cv::Point2f extreme(const std::vector<cv::Point> &pts, int sx, int sy) {
    cv::Point2f best = pts.front();
    double score = -HUGE_VAL;
    for (const auto &p : pts) {
        const double s = sx * p.x + sy * p.y;
        if (s > score) score = s, best = p;
    }
    return best;
}

/// The largest bright region's outline (CHAIN_APPROX_NONE); empty if none.
std::vector<cv::Point> largestContour(const cv::Mat &mask) {
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    std::size_t best = contours.size();
    double area = 0;
    for (std::size_t i = 0; i < contours.size(); ++i) {
        const double a = cv::contourArea(contours[i]);
        if (a > area) area = a, best = i;
    }
    return best < contours.size() ? contours[best] : std::vector<cv::Point>{};
}

}  // namespace

std::optional<Corners2> litFramebufferCorners(const cv::Mat &framebuffer) {
    const cv::Mat g = grey8(framebuffer);
    cv::Mat mask = g > 0;
    const auto c = largestContour(mask);
    if (c.size() < 4) return std::nullopt;
    const int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    Corners2 out;
    for (int i = 0; i < 4; ++i) {
        const cv::Point2f p = extreme(c, sx[i], sy[i]);
        // Outer pixel corner: half a pixel outwards.
        out[i] = Eigen::Vector2d(p.x + 0.5 * sx[i], p.y + 0.5 * sy[i]);
    }
    return out;
}

cv::Mat verificationCard(int width, int height) {
    cv::Mat card(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::circle(card, {width / 2, height / 2}, std::max(2, std::min(width, height) / 10), cv::Scalar(160, 160, 160),
               cv::FILLED);
    return card;
}

namespace {

/// The brightest region of a colour image and the quadrilateral around it.
struct BrightRegion {
    cv::Mat smooth, mask;                  ///< the grey image blurred, and its Otsu mask
    std::vector<cv::Point> contour, quad;  ///< the region's outline; 4 points
};

/// The bright region, wholly in view, clearly brighter than its surroundings and filling its
/// quadrilateral; "" or why not.
std::string findBrightRegion(const cv::Mat &colour, double min_area_px, BrightRegion &r) {
    const cv::Mat g = grey8(colour);
    cv::GaussianBlur(g, r.smooth, cv::Size(3, 3), 0.0);
    const double level = cv::threshold(r.smooth, r.mask, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
    cv::morphologyEx(r.mask, r.mask, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_ELLIPSE, {5, 5}));
    r.contour = largestContour(r.mask);
    if (r.contour.size() < 8 || cv::contourArea(r.contour) < min_area_px)
        return "no bright picture in the colour image";
    // Bright against dark: the lit level must clearly exceed the ambient one.
    cv::Mat inside(r.mask.size(), CV_8U, cv::Scalar(0));
    cv::drawContours(inside, std::vector<std::vector<cv::Point>>{r.contour}, 0, cv::Scalar(255), cv::FILLED);
    const double lit = cv::mean(r.smooth, inside)[0], dark = cv::mean(r.smooth, ~inside)[0];
    if (!(lit - dark > 30.0) || level <= 0) return "the picture is not clearly brighter than its surroundings";
    std::vector<cv::Point> hull;
    cv::convexHull(r.contour, hull);
    const double perimeter = cv::arcLength(hull, true);
    for (double eps = 0.01; eps <= 0.1 && r.quad.size() != 4; eps += 0.005)
        cv::approxPolyDP(hull, r.quad, eps * perimeter, true);
    if (r.quad.size() != 4) return "the bright region is not a quadrilateral";
    // Wholly in view and filled: a bright region cut by the image's edge, or whose outline fills
    // its quadrilateral poorly (a lit scene with nothing projected), is not the card.
    const cv::Rect bounds = cv::boundingRect(r.contour);
    if (bounds.x <= 0 || bounds.y <= 0 || bounds.br().x >= r.mask.cols || bounds.br().y >= r.mask.rows)
        return "the bright region reaches the edge of the colour image (the whole test card must be in view)";
    const double fill = cv::contourArea(r.contour) / std::max(1.0, cv::contourArea(r.quad));
    if (!(fill >= kCardMinFill))
        return "the bright region fills only " + std::to_string(static_cast<int>(100 * fill)) +
               " % of its quadrilateral: not a projected test card";
    return "";
}

/// The picture's corners (TL, TR, BR, BL) where lines fitted to its outline's edges meet;
/// "" or why not.
std::string cornersFromEdges(const BrightRegion &r, Corners2 &image_px) {
    // Order the rough corners TL, TR, BR, BL.
    std::array<cv::Point2f, 4> rough;
    const int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int i = 0; i < 4; ++i) rough[i] = extreme(r.quad, sx[i], sy[i]);
    cv::Point2f centroid(0, 0);
    for (const auto &c : rough) centroid += 0.25f * c;
    // Each edge: the outline's points in its middle 80 %, a line, moved half a pixel out (the
    // outline runs through the centres of the outermost bright pixels).
    std::array<cv::Vec3d, 4> lines;  // a x + b y = c, (a, b) unit, pointing outwards
    for (int e = 0; e < 4; ++e) {
        const cv::Point2f a = rough[e], b = rough[(e + 1) % 4];
        const cv::Point2f d = b - a;
        const double len2 = d.dot(d);
        if (!(len2 > 16)) return "the picture is too small in the colour image";
        std::vector<cv::Point2f> pts;
        for (const auto &p : r.contour) {
            const cv::Point2f q = cv::Point2f(p) - a;
            const double t = q.dot(d) / len2;
            const double off = std::abs(q.x * d.y - q.y * d.x) / std::sqrt(len2);
            if (t > 0.1 && t < 0.9 && off < 4.0) pts.push_back(p);
        }
        if (pts.size() < 5) return "an edge of the picture is not visible";
        cv::Vec4f l;
        cv::fitLine(pts, l, cv::DIST_HUBER, 0, 0.01, 0.01);
        cv::Vec2d n(-l[1], l[0]);
        double c = n[0] * l[2] + n[1] * l[3];
        if (n[0] * centroid.x + n[1] * centroid.y > c) n = -n, c = -c;  // outwards
        lines[e] = cv::Vec3d(n[0], n[1], c + 0.5);
    }
    for (int i = 0; i < 4; ++i) {
        const cv::Vec3d &l1 = lines[(i + 3) % 4], &l2 = lines[i];  // the edges meeting at corner i
        const double det = l1[0] * l2[1] - l1[1] * l2[0];
        if (!(std::abs(det) > 1e-9)) return "two edges of the picture are parallel";
        image_px[i] = Eigen::Vector2d((l1[2] * l2[1] - l1[1] * l2[2]) / det, (l1[0] * l2[2] - l1[2] * l2[0]) / det);
    }
    return "";
}

/// The test card's signature: its grey disc at the picture's centre (where the diagonals
/// cross, in perspective too). A bright quadrilateral without it (a window, a lit wall) is
/// not the card.
bool showsCardDisc(const BrightRegion &r, const Corners2 &image_px) {
    const Eigen::Vector2d &p0 = image_px[0], &p1 = image_px[1], &p2 = image_px[2], &p3 = image_px[3];
    const Eigen::Vector2d d1 = p2 - p0, d2 = p3 - p1, s = p1 - p0;
    const double den = d1.x() * d2.y() - d1.y() * d2.x();
    const Eigen::Vector2d centre = p0 + (std::abs(den) > 1e-9 ? (s.x() * d2.y() - s.y() * d2.x()) / den : 0.5) * d1;
    const double side = std::min({(p1 - p0).norm(), (p2 - p3).norm(), (p3 - p0).norm(), (p2 - p1).norm()});
    const int radius = std::max(1, static_cast<int>(0.4 * side / 10.0));  // the card's disc: 1/10 of its side
    cv::Mat disc(r.mask.size(), CV_8U, cv::Scalar(0)), lit_mask;
    cv::circle(disc, {cvRound(centre.x()), cvRound(centre.y())}, radius, cv::Scalar(255), cv::FILLED);
    cv::bitwise_and(r.mask, ~disc, lit_mask);
    const double centre_level = cv::mean(r.smooth, disc)[0], lit = cv::mean(r.smooth, lit_mask)[0];
    return centre_level < kCardDiscDarker * lit;
}

/// The depth readings inside the picture (shrunk away from its edges), every 2nd pixel, as
/// camera-frame points.
std::vector<Eigen::Vector3d> depthInside(const cv::Mat &depth, const CameraIntrinsics &camera, cv::Size size,
                                         const Corners2 &image_px) {
    cv::Mat inside(size, CV_8U, cv::Scalar(0));
    std::vector<cv::Point> quad;
    for (const auto &p : image_px) quad.emplace_back(cvRound(p.x()), cvRound(p.y()));
    cv::fillConvexPoly(inside, quad, cv::Scalar(255));
    cv::erode(inside, inside, cv::getStructuringElement(cv::MORPH_RECT, {9, 9}));
    std::vector<Eigen::Vector3d> pts;
    for (int y = 0; y < depth.rows; y += 2)
        for (int x = 0; x < depth.cols; x += 2) {
            if (!inside.at<uchar>(y, x)) continue;
            const int raw = depth.at<std::uint16_t>(y, x);
            if (raw > 0) pts.push_back(camera.backProject(x, y, raw / camera.depth_scale));
        }
    return pts;
}

/// Least squares, then once more without points more than 3 cm off; the normal towards the camera.
Plane fitPlaneTwice(const std::vector<Eigen::Vector3d> &pts) {
    Plane plane;
    for (int pass = 0; pass < 2; ++pass) {
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        int n = 0;
        for (const auto &p : pts)
            if (pass == 0 || std::abs(plane.signedDistance(p)) < 0.03) mean += p, ++n;
        if (n < 50) break;
        mean /= n;
        Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
        for (const auto &p : pts)
            if (pass == 0 || std::abs(plane.signedDistance(p)) < 0.03) cov += (p - mean) * (p - mean).transpose();
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
        Eigen::Vector3d normal = es.eigenvectors().col(0);
        if (normal.dot(mean) > 0) normal = -normal;  // towards the camera
        plane = makePlane(normal, -normal.dot(mean));
    }
    return plane;
}

}  // namespace

FoundPicture findProjectedPicture(const cv::Mat &colour, const cv::Mat &depth, const CameraIntrinsics &camera,
                                  double min_area_px) {
    FoundPicture f;
    BrightRegion region;
    f.reason = findBrightRegion(colour, min_area_px, region);
    if (f.reason.empty()) f.reason = cornersFromEdges(region, f.image_px);
    if (!f.reason.empty()) return f;
    if (!showsCardDisc(region, f.image_px)) {
        f.reason = "a bright quadrilateral, but not the test card (no grey disc at its centre)";
        return f;
    }
    const std::vector<Eigen::Vector3d> pts = depthInside(depth, camera, region.mask.size(), f.image_px);
    if (pts.size() < 50) {
        f.reason = "too few depth readings inside the picture";
        return f;
    }
    f.plane = fitPlaneTwice(pts);
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector3d ray = camera.backProject(f.image_px[i].x(), f.image_px[i].y(), 1.0).normalized();
        const auto hit = intersectRay(f.plane, Eigen::Vector3d::Zero(), ray);
        if (!hit) {
            f.reason = "a corner's camera ray misses the fitted plane";
            return f;
        }
        f.corners[i] = *hit;
    }
    f.found = true;
    return f;
}

double calibrationTolerance(const Projector &projector, const Corners3 &expected) {
    double distance = 0;
    for (const Eigen::Vector3d &c : expected) distance += 0.25 * (c - projector.origin).norm();
    return std::max(kCalibrationToleranceM, std::tan(kCalibrationToleranceDeg * M_PI / 180.0) * distance);
}

std::optional<LandingCheck> checkLanding(const Projector &projector, const Corners2 &lit_px, const FoundPicture &found,
                                         const Corners3 &meant) {
    LandingCheck c;
    for (int i = 0; i < 4; ++i) {
        const auto hit = castToWall(projector, lit_px[i], found.plane);
        if (!hit) return std::nullopt;
        c.expected[i] = *hit;
        c.calibration_error_m[i] = (found.corners[i] - c.expected[i]).norm();
        c.detection_error_m[i] = (found.corners[i] - meant[i]).norm();
        c.max_calibration_error_m = std::max(c.max_calibration_error_m, c.calibration_error_m[i]);
        c.max_detection_error_m = std::max(c.max_detection_error_m, c.detection_error_m[i]);
        c.detection_off_m = std::max(c.detection_off_m, std::abs(found.plane.signedDistance(meant[i])));
    }
    return c;
}

}  // namespace projsurf
