#include "projsurf/frontend/render/overlay.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <tuple>
#include "projsurf/detection/default/observed_free_space.hpp"
#include "projsurf/detection/method_names.hpp"

#include "projsurf/io/files/limits.hpp"
#include "projsurf/types/formatted.hpp"

namespace projsurf {
namespace {

const cv::Scalar kInlier(80, 200, 80), kFree(0, 220, 255), kWorkspace(255, 160, 40), kRect(255, 0, 255),
    kOutlier(40, 40, 255), kText(255, 255, 255), kInFront(0, 130, 255), kSeenThrough(220, 80, 200),
    kNoReading(150, 150, 150), kGlare(255, 255, 160), kDark(90, 40, 20), kTextured(0, 60, 160), kSaturated(160, 0, 90),
    kCandidate(255, 255, 0), kProud(0, 0, 140);

/// Where camera-frame points land in the picture.
struct View {
    CameraIntrinsics cam;
    double scale = 1.0;  // picture pixels per camera pixel
    cv::Point2f operator()(const Eigen::Vector3d &p) const {
        const double z = std::max(p.z(), 1e-3);
        // Far off the picture is as good as anywhere off it: kept where the drawing code's
        // int and fixed-point conversions are defined (NaN goes to the corner).
        auto fit = [](double v) { return static_cast<float>(v >= -1e5 ? std::min(v, 1e5) : -1e5); };
        return {fit((cam.fx * p.x() / z + cam.cx + 0.5) * scale - 0.5),
                fit((cam.fy * p.y() / z + cam.cy + 0.5) * scale - 0.5)};
    }
};

void polyline(cv::Mat &img, const View &view, const std::vector<Eigen::Vector3d> &pts, bool closed,
              const cv::Scalar &color, int thickness) {
    if (pts.size() < 2) return;
    std::vector<cv::Point> px;
    for (const auto &p : pts) {
        const cv::Point2f q = view(p);
        px.emplace_back(cvRound(q.x * 16), cvRound(q.y * 16));
    }
    cv::polylines(img, std::vector<std::vector<cv::Point>>{px}, closed, color, thickness, cv::LINE_AA, 4);
}

/// The raster cells in `state` painted on the picture, translucent, where they lie on the wall.
void paintCells(cv::Mat &img, const View &view, const DetectionDebug &debug, CellState state, const cv::Scalar &color) {
    if (debug.cell_state.empty() || debug.grid_cell <= 0) return;
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(debug.cell_state == static_cast<int>(state), contours, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
    if (contours.empty()) return;
    for (auto &contour : contours)
        for (cv::Point &p : contour) {
            const Eigen::Vector2d uv(debug.grid_origin.x() + (p.x + 0.5) * debug.grid_cell,
                                     debug.grid_origin.y() - (p.y + 0.5) * debug.grid_cell);
            const cv::Point2f q = view(debug.frame.toCamera(uv));
            p = {cvRound(q.x), cvRound(q.y)};
        }
    cv::Mat layer = img.clone();
    cv::fillPoly(layer, contours, color, cv::LINE_8);
    cv::addWeighted(layer, 0.45, img, 0.55, 0.0, img);
}

/// The legend's text size for a picture `cols` wide.
double legendScale(int cols) { return std::max(0.45, cols / 1700.0); }

/// `text` broken at spaces into lines that fit `cols` pixels in the legend's font.
void wrapLine(const std::string &text, int cols, std::vector<std::string> &lines) {
    const double fs = legendScale(cols);
    std::string line, word;
    auto fits = [&](const std::string &s) {
        int base = 0;
        return cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, fs, 1, &base).width <= cols - 20;
    };
    std::size_t at = 0;
    while (at <= text.size()) {
        const std::size_t end = std::min(text.find(' ', at), text.size());
        word = text.substr(at, end - at);
        if (!line.empty() && !fits(line + " " + word)) {
            lines.push_back(line);
            line = "    " + word;
        } else {
            line += (line.empty() ? "" : " ") + word;
        }
        at = end + 1;
    }
    if (!line.empty()) lines.push_back(line);
}

/// --explain: each candidate's seen extent outlined (the losers), clipped to the picture, and
/// numbered at the centre of what is in view; its outcome in words as status lines.
void drawCandidates(cv::Mat &img, const View &view, const Detection &det, std::vector<std::string> &lines) {
    const Rectangle winner = winningRectangle(det.candidates, det.rectangle);
    for (std::size_t k = 0; k < det.candidates.size(); ++k) {
        const CandidateOutcome &o = det.candidates[k];
        const bool chosen = o.verdict == CandidateVerdict::Chosen;
        const std::string tag = "#" + std::to_string(k + 1);
        const std::vector<cv::Point2f> outline = outlineInView(o.seen, view.cam, view.scale, img.size());
        if (!chosen && outline.size() > 2) {
            std::vector<cv::Point> px;
            for (const cv::Point2f &q : outline) px.emplace_back(cvRound(q.x * 16), cvRound(q.y * 16));
            cv::polylines(img, std::vector<std::vector<cv::Point>>{px}, true, kCandidate, 2, cv::LINE_AA, 4);
        }
        cv::Point2f at = view(0.25 * (o.seen[0] + o.seen[1] + o.seen[2] + o.seen[3]));  // its centre
        if (outline.size() > 2) {  // the centre of what is in view
            const cv::Moments m = cv::moments(outline);
            if (m.m00 > 1.0) at = cv::Point2f(static_cast<float>(m.m10 / m.m00), static_cast<float>(m.m01 / m.m00));
        }
        const cv::Point label(std::clamp(cvRound(at.x) - 12, 4, std::max(4, img.cols - 40)),
                              std::clamp(cvRound(at.y) + 10, 24, std::max(24, img.rows - 6)));
        cv::putText(img, tag, label, cv::FONT_HERSHEY_SIMPLEX, 0.8, chosen ? kRect : kCandidate, 2, cv::LINE_AA);
        wrapLine(tag + " " + formatted("%.2f m away", std::abs(o.plane.d)) + ": " + outcomeWords(o, winner), img.cols,
                 lines);
    }
}

/// Appends a panel below the picture: status lines, then the colour key in two columns (one
/// when they do not fit side by side).
cv::Mat withLegend(const cv::Mat &img, const std::vector<std::pair<cv::Scalar, std::string>> &items,
                   const std::vector<std::string> &lines) {
    const double fs = legendScale(img.cols);
    const int lh = static_cast<int>(std::round(26 * fs / 0.5));
    std::vector<std::string> entries;
    for (const auto &item : items) entries.push_back(item.second);
    const int second = legendSecondColumn(entries, img.cols);
    const int columns = second > 0 ? 2 : 1;
    const int key_rows = static_cast<int>((items.size() + columns - 1) / columns);
    cv::Mat out(img.rows + lh * static_cast<int>(lines.size() + key_rows) + lh / 2, img.cols, CV_8UC3,
                cv::Scalar(32, 32, 32));
    img.copyTo(out(cv::Rect(0, 0, img.cols, img.rows)));
    int y = img.rows + lh;
    for (const auto &l : lines) {
        cv::putText(out, l, {10, y - lh / 4}, cv::FONT_HERSHEY_SIMPLEX, fs, kText, 1, cv::LINE_AA);
        y += lh;
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
        const int x = i % columns == 0 ? 10 : second;
        const int yy = y + static_cast<int>(i / columns) * lh;
        cv::rectangle(out, cv::Rect(x, yy - lh + lh / 4, lh / 2, lh / 2), items[i].first, cv::FILLED);
        cv::putText(out, items[i].second, {x + lh, yy - lh / 4}, cv::FONT_HERSHEY_SIMPLEX, fs, kText, 1, cv::LINE_AA);
    }
    return out;
}

}  // namespace

std::vector<cv::Point2f> outlineInView(const std::array<Eigen::Vector3d, 4> &box, const CameraIntrinsics &camera,
                                       double scale, cv::Size size) {
    // The box before the camera: cut where it crosses z = 5 cm (a corner behind the camera
    // would be cast across the whole picture).
    constexpr double kNear = 0.05;
    std::vector<Eigen::Vector3d> front;
    for (std::size_t i = 0; i < box.size(); ++i) {
        const Eigen::Vector3d &a = box[i], &b = box[(i + 1) % box.size()];
        if (!a.allFinite() || !b.allFinite()) return {};
        if (a.z() >= kNear) front.push_back(a);
        if ((a.z() >= kNear) != (b.z() >= kNear)) front.push_back(a + (kNear - a.z()) / (b.z() - a.z()) * (b - a));
    }
    if (front.size() < 3 || size.width < 2 || size.height < 2) return {};
    View view;
    view.cam = camera;
    view.scale = scale;
    std::vector<cv::Point2f> px, out;
    for (const Eigen::Vector3d &p : front) px.push_back(view(p));
    // A plane's convex box seen from in front of it stays convex; the picture is convex.
    const std::vector<cv::Point2f> picture{{0.f, 0.f},
                                           {static_cast<float>(size.width - 1), 0.f},
                                           {static_cast<float>(size.width - 1), static_cast<float>(size.height - 1)},
                                           {0.f, static_cast<float>(size.height - 1)}};
    if (std::abs(cv::contourArea(px)) < 1e-6) return {};
    cv::intersectConvexConvex(px, picture, out, true);
    return out;
}

int legendSecondColumn(const std::vector<std::string> &entries, int cols) {
    const double fs = legendScale(cols);
    const int lh = static_cast<int>(std::round(26 * fs / 0.5));
    int left = 0, right = 0;  // the widest entry of each column, with its swatch
    for (std::size_t i = 0; i < entries.size(); ++i) {
        int base = 0;
        const int width = lh + cv::getTextSize(entries[i], cv::FONT_HERSHEY_SIMPLEX, fs, 1, &base).width;
        (i % 2 == 0 ? left : right) = std::max(i % 2 == 0 ? left : right, width);
    }
    const int x = std::max(cols / 2, 10 + left + lh);  // a swatch's width of space between the columns
    return entries.size() > 1 && x + right + 10 <= cols ? x : 0;
}

CameraIntrinsics estimateIntrinsics(const Cloud &cloud) {
    CameraIntrinsics cam;
    cam.fx = 0.0;
    if (!cloud.organized()) return cam;
    // core's pinhole fit on every 4th pixel of every 4th row; any residual (a view, not a measurement).
    std::vector<int> grid;
    for (int v = 0; v < cloud.height; v += 4)
        for (int u = 0; u < cloud.width; u += 4) grid.push_back(v * cloud.width + u);
    int used = 0;
    for (int i : grid) used += isFinite(cloud.points[i]) && cloud.points[i].z() > 0 ? 1 : 0;
    if (used < 50) return cam;
    const auto fit = fitIntrinsics(cloud, grid, std::numeric_limits<double>::infinity());
    if (!fit || !(fit->fx > 0 && fit->fy > 0 && std::isfinite(fit->cx) && std::isfinite(fit->cy))) return cam;
    return *fit;
}

namespace {

/// The cell states colour refuses, their colours and their legend's words.
const std::vector<std::tuple<CellState, cv::Scalar, const char *>> &unfitStates() {
    static const std::vector<std::tuple<CellState, cv::Scalar, const char *>> unfit{
        {CellState::Glare, kGlare, "not fit: glare (specular, emissive)"},
        {CellState::Dark, kDark, "not fit: too dark (low albedo)"},
        {CellState::Textured, kTextured, "not fit: textured (picture, pattern)"},
        {CellState::Saturated, kSaturated, "not fit: too saturated a colour"}};
    return unfit;
}

/// The camera the overlay is drawn from and its enlargement.
View overlayView(const Cloud &cloud, const CameraIntrinsics *camera) {
    View view;
    if (camera)
        view.cam = *camera;
    else
        view.cam = estimateIntrinsics(cloud);
    if (!(view.cam.fx > 0)) view.cam = CameraIntrinsics{};  // a virtual Kinect-like view
    if (static_cast<std::uint64_t>(view.cam.width) * view.cam.height > limits::kMaxImagePixels || view.cam.width < 1 ||
        view.cam.height < 1)
        view.cam = CameraIntrinsics{};  // no picture that large: the virtual view
    const int w = view.cam.width, h = view.cam.height;
    // Small frames are enlarged to about 960 pixels across, by both sides (a 1 x 2000 frame
    // must not become 960 x 1920000), never beyond the image limit.
    view.scale = std::clamp(std::min(960.0 / w, 960.0 / h * 4.0 / 3.0), 1.0, 16.0);
    while (view.scale > 1.0 && w * view.scale * h * view.scale > static_cast<double>(limits::kMaxImagePixels))
        view.scale = std::max(1.0, view.scale / 2.0);

    return view;
}

/// The frame at the camera's resolution: the colour image (or the depth in grey), outliers
/// red, the wall's inliers green.
cv::Mat shadedFrame(const Cloud &cloud, const Detection &det, const DetectorConfig &config, const View &view,
                    const cv::Mat &color) {
    const int w = view.cam.width, h = view.cam.height;
    // Background: the colour image, or the depth shaded grey (near = bright).
    cv::Mat base(h, w, CV_8UC3, cv::Scalar(30, 30, 30));
    const bool use_color = !color.empty() && color.cols == w && color.rows == h && color.type() == CV_8UC3;
    if (use_color) base = color * 0.6;
    const Eigen::Vector3f n = det.plane.normal.cast<float>();
    const float d = static_cast<float>(det.plane.d);
    std::vector<char> outlier(cloud.points.size(), 0);
    for (int i : det.debug.outliers)
        if (i >= 0 && i < static_cast<int>(outlier.size())) outlier[i] = 1;
    const bool organized_match = cloud.organized() && cloud.width == w && cloud.height == h;
    for (std::size_t i = 0; i < cloud.points.size(); ++i) {
        const Point &p = cloud.points[i];
        if (!isFinite(p) || p.z() <= 0) continue;
        int u, v;
        if (organized_match) {
            u = static_cast<int>(i % w);
            v = static_cast<int>(i / w);
        } else {
            const double fu = std::round(view.cam.fx * p.x() / p.z() + view.cam.cx),
                         fv = std::round(view.cam.fy * p.y() / p.z() + view.cam.cy);
            if (!(fu >= 0 && fv >= 0 && fu < w && fv < h)) continue;  // tested before converting
            u = static_cast<int>(fu);
            v = static_cast<int>(fv);
        }
        cv::Vec3b &px = base.at<cv::Vec3b>(v, u);
        if (!use_color) {
            const int g = static_cast<int>(std::clamp(255.0f - 40.0f * p.z(), 40.0f, 230.0f));
            px = cv::Vec3b(g, g, g);
        }
        if (outlier[i]) {
            px = cv::Vec3b(40, 40, 255);
        } else if (det.inliers > 0) {
            const bool paper = config.method == Method::Paper;
            const float band =
                paper ? static_cast<float>(config.paper.ransac_distance) : det.debug.tolerance.band(p.z());
            const float bend =
                paper ? 0.0f
                      : static_cast<float>(det.debug.wall_shape.height(det.debug.frame.toPlane(p.cast<double>())));
            if (std::abs(n.dot(p) + d - bend) <= band)
                px = cv::Vec3b(static_cast<uchar>(px[0] * 0.5 + 40), static_cast<uchar>(px[1] * 0.5 + 100),
                               static_cast<uchar>(px[2] * 0.5 + 40));
        }
    }
    return base;
}

/// The free-space cells, the outlines, the workspace and the rectangle, on the enlarged frame.
void drawDetection(cv::Mat &img, const View &view, const Detection &det) {
    paintCells(img, view, det.debug, CellState::InFront, kInFront);
    paintCells(img, view, det.debug, CellState::SeenThrough, kSeenThrough);
    paintCells(img, view, det.debug, CellState::NoReading, kNoReading);
    paintCells(img, view, det.debug, CellState::Proud, kProud);
    for (const auto &[state, colour, text] : unfitStates()) paintCells(img, view, det.debug, state, colour);
    for (const auto &outline : det.debug.hull) polyline(img, view, outline, outline.size() > 2, kFree, 2);
    if (det.debug.has_workspace)
        polyline(img, view, {det.debug.workspace.begin(), det.debug.workspace.end()}, true, kWorkspace, 2);
    if (det.rectangle.area() > 0) {
        polyline(img, view, {det.rectangle.corners.begin(), det.rectangle.corners.end()}, true,
                 det.found ? kRect : cv::Scalar(128, 0, 128), 4);
        const cv::Point2f tl = view(det.rectangle.corners[0]);
        cv::putText(img, "TL", tl + cv::Point2f(6, 22), cv::FONT_HERSHEY_SIMPLEX, 0.6, kRect, 2, cv::LINE_AA);
    }
}

/// The caption: found or why not, the plane, the surface check.
std::vector<std::string> captionLines(const Detection &det, const DetectorConfig &config) {
    char line[256];
    std::vector<std::string> lines;
    if (det.found) {
        std::snprintf(line, sizeof line, "found: %.2f x %.2f m = %.2f m^2", det.rectangle.width, det.rectangle.height,
                      det.rectangle.area());
    } else {
        std::snprintf(line, sizeof line, "not found: %s", det.reason.c_str());
    }
    lines.emplace_back(line);
    if (det.inliers > 0) {
        std::snprintf(line, sizeof line, "plane %.2f m away, %.1f deg to the optical axis, %d inliers", det.plane.d,
                      det.orientation_deg, det.inliers);
        lines.emplace_back(line);
    }
    std::snprintf(line, sizeof line, "surface check: %d outliers / %d points; method %s; %.1f ms",
                  det.surface_check.outliers, det.surface_check.points, methodName(config.method),
                  det.timing_ms.count("total") ? det.timing_ms.at("total") : 0.0);
    lines.emplace_back(line);
    return lines;
}

/// The legend: what each colour means (the cells' states only when there are cells).
std::vector<std::pair<cv::Scalar, std::string>> legendKey(const Detection &det, const DetectorConfig &config,
                                                          bool explain) {
    std::vector<std::pair<cv::Scalar, std::string>> key{
        {kInlier, "wall points (on the wall as fitted)"},
        {kFree, config.method == Method::Paper ? "plane hull" : "free space on the wall"},
        {kWorkspace, "projector workspace"},
        {kRect, "picture rectangle"},
        {kOutlier, "surface-check outliers"}};
    if (!det.debug.cell_state.empty()) {
        key.push_back({kInFront, "not free: something in front (its shadow)"});
        key.push_back({kSeenThrough, "not free: seen through (hole, door, glass)"});
        key.push_back({kNoReading, "not free: no wall reading"});
        if (cv::countNonZero(det.debug.cell_state == static_cast<int>(CellState::Proud)) > 0)
            key.push_back({kProud, "not free: stands proud of the wall (frame, switch)"});
        for (const auto &[state, colour, text] : unfitStates())
            if (cv::countNonZero(det.debug.cell_state == static_cast<int>(state)) > 0) key.push_back({colour, text});
    }
    if (explain) key.push_back({kCandidate, "candidate planes as seen (#: see above)"});
    return key;
}

}  // namespace

cv::Mat renderOverlay(const Cloud &cloud, const Detection &det, const DetectorConfig &config,
                      const CameraIntrinsics *camera, const cv::Mat &color, bool explain) {
    const View view = overlayView(cloud, camera);
    cv::Mat img;
    cv::resize(shadedFrame(cloud, det, config, view, color), img, {}, view.scale, view.scale, cv::INTER_NEAREST);
    drawDetection(img, view, det);
    std::vector<std::string> lines = captionLines(det, config);
    if (explain) drawCandidates(img, view, det, lines);
    return withLegend(img, legendKey(det, config, explain), lines);
}

}  // namespace projsurf
