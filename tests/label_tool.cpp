// projsurf_label_tool: helps make and refresh the real-frame labels (labels/real/<half>/*.yaml).
//   grid   <frame_dir> <out.png>             colour-mapped depth and colour with a 40 px grid
//   init   <frame_dir> <label.yaml>          a label with the floor's gravity and the example projector
//   update <frame_dir> <label.yaml> [--holes N] [--aim u,v] [--overlay out.png]
//          --holes N: replace the "no reading" obstacles by the holes of >= N pixels in the surfaces
//          --aim u,v: aim the projector at the surface point seen at pixel (u, v)
//          --refine "name;name": shrink every obstacle drawn as a box, except those named, to what the
//                   depth shows inside it: readings more than 2.5 cm in front of the plane of the
//                   surface whose regions hold the pixel (else the nearest plane), or no reading (closed 5x5, grown by
//                   3 px within the box, pieces of >= 20 px)
//          then fits the surfaces, recomputes the reference best rectangle (and, when the label has a
//          colour section, the colour-aware best: the unsuitable polygons as further obstacles) and
//          writes the label.
//   score <frame_dir> <label.yaml> x,y,z x,y,z x,y,z x,y,z
//          scores a rectangle (camera frame, corners TL TR BR BL) by eval/real/real_scoring's rules, the
//          detector's: prints "valid 0|1 free F surface NAME why ..." (scripts/plan_labels.py)
//   baseline <real_dir> <labels_dir> [margin]  prints the regression baseline (labels/baseline.yaml); a frame
//          not in real_dir is looked for in data/real (run from the repository root):
//          today's detector per frame, right or not, and its area ratio minus `margin` (default 0.05),
//          at most 0.90 (the target)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>

#include "projsurf/detection/gravity.hpp"
#include "eval/real/label_overlay.hpp"
#include "eval/real/label_reference.hpp"
#include "eval/real/labelled_eval.hpp"
#include "eval/real/real_labels.hpp"
#include "eval/real/real_scoring.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

using namespace projsurf::eval;  // the evaluation under test

namespace fs = std::filesystem;
using namespace projsurf;

namespace {

cv::Mat background(const std::string &dir, const Cloud &cloud) {
    const fs::path rgb = fs::path(dir) / "rgb.png";
    if (fs::exists(rgb)) {
        cv::Mat c = cv::imread(rgb.string(), cv::IMREAD_COLOR);
        if (c.cols == cloud.width && c.rows == cloud.height) return c;
    }
    return depthColour(cloud);
}

void gridLines(cv::Mat &img) {
    for (int x = 0; x < img.cols; x += 40) {
        cv::line(img, {x, 0}, {x, img.rows - 1}, {255, 255, 255}, 1);
        cv::putText(img, std::to_string(x), {x + 2, 10}, cv::FONT_HERSHEY_SIMPLEX, 0.3, {255, 255, 255}, 1);
    }
    for (int y = 0; y < img.rows; y += 40) {
        cv::line(img, {0, y}, {img.cols - 1, y}, {255, 255, 255}, 1);
        cv::putText(img, std::to_string(y), {2, y + 10}, cv::FONT_HERSHEY_SIMPLEX, 0.3, {255, 255, 255}, 1);
    }
}

void holes(RealLabel &l, const Cloud &cloud, int min_pixels) {
    std::vector<LabelPolygon> kept;
    for (auto &o : l.obstacles)
        if (o.name != "no reading") kept.push_back(o);
    l.obstacles = kept;
    cv::Mat region(cloud.height, cloud.width, CV_8U, cv::Scalar(0));
    auto pts = [](const LabelPolygon &p) {
        std::vector<cv::Point> out;
        for (const auto &q : p.pixels)
            out.emplace_back(static_cast<int>(std::lround(q.x())), static_cast<int>(std::lround(q.y())));
        return std::vector<std::vector<cv::Point>>{out};
    };
    for (const auto &s : l.surfaces)
        for (const auto &r : s.regions) cv::fillPoly(region, pts(r), 255);
    for (const auto &o : l.obstacles) cv::fillPoly(region, pts(o), 0);
    cv::Mat hole(cloud.height, cloud.width, CV_8U, cv::Scalar(0));
    for (int v = 0; v < cloud.height; ++v)
        for (int u = 0; u < cloud.width; ++u)
            if (region.at<uchar>(v, u) && !isFinite(cloud.points[static_cast<std::size_t>(v) * cloud.width + u]))
                hole.at<uchar>(v, u) = 255;
    cv::morphologyEx(hole, hole, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_RECT, {5, 5}));
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(hole, labels, stats, centroids, 8);
    for (int k = 1; k < n; ++k) {
        if (stats.at<int>(k, cv::CC_STAT_AREA) < min_pixels) continue;
        cv::Mat one = labels == k;
        cv::dilate(one, one, cv::getStructuringElement(cv::MORPH_RECT, {5, 5}));
        std::vector<std::vector<cv::Point>> contours;
        cv::findContours(one, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
        for (auto &c : contours) {
            std::vector<cv::Point> a;
            cv::approxPolyDP(c, a, 1.5, true);
            if (a.size() < 3) continue;
            LabelPolygon p;
            p.name = "no reading";
            for (const auto &q : a) p.pixels.emplace_back(q.x, q.y);
            l.obstacles.push_back(p);
        }
    }
}

/// See --refine above. Needs the surfaces' planes (run after a fit).
void refineObstacles(RealLabel &l, const Cloud &cloud, const std::string &keep_list) {
    std::vector<std::string> keep;
    std::stringstream ss(keep_list);
    for (std::string k; std::getline(ss, k, ';');)
        if (!k.empty()) keep.push_back(k);
    auto pts = [](const LabelPolygon &p) {
        std::vector<cv::Point> out;
        for (const auto &q : p.pixels)
            out.emplace_back(static_cast<int>(std::lround(q.x())), static_cast<int>(std::lround(q.y())));
        return std::vector<std::vector<cv::Point>>{out};
    };
    cv::Mat proud(cloud.height, cloud.width, CV_8U, cv::Scalar(0));
    for (int v = 0; v < cloud.height; ++v)
        for (int u = 0; u < cloud.width; ++u) {
            const Point &p = cloud.points[static_cast<std::size_t>(v) * cloud.width + u];
            if (!isFinite(p)) {
                proud.at<uchar>(v, u) = 255;
                continue;
            }
            // Against the plane of the surface whose regions hold the pixel, else the nearest.
            double r = 1e9;
            bool held = false;
            for (const auto &s : l.surfaces) {
                if (!s.has_plane) continue;
                const double d = s.plane.signedDistance(p.cast<double>());
                const bool in = std::any_of(s.regions.begin(), s.regions.end(), [&](const LabelPolygon &g) {
                    return insidePolygon(g.pixels, Eigen::Vector2d(u, v));
                });
                if (in && !held) {
                    r = d;
                    held = true;
                } else if (!held && std::abs(d) < std::abs(r)) {
                    r = d;
                }
            }
            if (r > 0.025) proud.at<uchar>(v, u) = 255;
        }
    std::vector<LabelPolygon> out;
    for (const auto &o : l.obstacles) {
        if (o.name == "no reading" || std::find(keep.begin(), keep.end(), o.name) != keep.end()) {
            out.push_back(o);
            continue;
        }
        cv::Mat box(cloud.height, cloud.width, CV_8U, cv::Scalar(0));
        cv::fillPoly(box, pts(o), 255);
        cv::Mat m = proud & box;
        cv::morphologyEx(m, m, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_RECT, {5, 5}));
        cv::dilate(m, m, cv::getStructuringElement(cv::MORPH_RECT, {7, 7}));
        m &= box;  // never larger than what was drawn
        std::vector<std::vector<cv::Point>> contours;
        cv::findContours(m, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
        for (auto &c : contours) {
            if (cv::contourArea(c) < 20) continue;
            std::vector<cv::Point> a;
            cv::approxPolyDP(c, a, 1.0, true);
            if (a.size() < 3) continue;
            LabelPolygon p;
            p.name = o.name;
            for (const auto &q : a) p.pixels.emplace_back(q.x, q.y);
            out.push_back(p);
        }
    }
    l.obstacles = out;
}

}  // namespace

/// `score`: one rectangle against the label (argv as in the comment at the top).
int scoreRectangle(int argc, char **argv) {
    if (argc != 8) throw std::runtime_error("score <frame_dir> <label.yaml> x,y,z x,y,z x,y,z x,y,z");
    const CameraIntrinsics cam = readCamera((fs::path(argv[2]) / "camera.yaml").string());
    const RealLabel l = readRealLabel(argv[3]);
    Rectangle r;
    for (int k = 0; k < 4; ++k) {
        char comma;
        std::istringstream in(argv[4 + k]);
        in >> r.corners[k].x() >> comma >> r.corners[k].y() >> comma >> r.corners[k].z();
        if (!in) throw std::runtime_error(std::string("not a point x,y,z: ") + argv[4 + k]);
    }
    r.width = (r.corners[1] - r.corners[0]).norm();
    r.height = (r.corners[3] - r.corners[0]).norm();
    const RealScore s = scoreRealRectangle(l, cam, true, r);
    std::printf("valid %d free %.3f surface %s why %s\n", s.valid ? 1 : 0, s.free_fraction, s.surface.c_str(),
                s.why.c_str());
    return 0;
}

namespace {

/// `baseline`: prints the regression floor of the labelled real-frame suite (argv as in the
/// comment at the top).
int writeBaseline(int argc, char **argv) {
    const double margin = argc > 4 ? std::stod(argv[4]) : 0.05;
    std::printf(
        "# Regression floor of the labelled real-frame suite, checked by "
        "tests/eval/real/test_real_labels.cpp.\n"
        "# Per frame: whether today's default detector is right (valid, or nothing found where the\n"
        "# label has no usable surface) and its area ratio to the label's best minus %.2f\n"
        "# (at most 0.90, the target: a valid answer may exceed the best, see labels/README.md).\n"
        "# Made by: build/tests/projsurf_label_tool baseline %s %s %.2f\n"
        "# Raise it as the detector improves.\nframes:\n",
        margin, argv[2], argv[3], margin);
    for (const auto &path : listLabelFiles(argv[3])) {
        // The frame is in real_dir, else in the repository's data/real (run from its root).
        const std::string frame = readRealLabel(path).frame;
        std::string parent = argv[2];
        if (!fs::is_directory(fs::path(parent) / frame) && fs::is_directory(fs::path("data/real") / frame))
            parent = "data/real";
        const LabelledFrame f = evaluateLabelledFrame(path, parent, DetectorConfig{}, {});
        std::printf("  %s: {right: %s, min_ratio: %.2f}  # ratio %.3f\n", f.name.c_str(),
                    f.score.right ? "true" : "false",
                    std::clamp(std::floor((f.score.ratio - margin) * 100) / 100, 0.0, 0.9), f.score.ratio);
    }
    return 0;
}

/// `grid`: the depth in colour above the colour picture, both with a pixel grid, into `file`.
int writeGrid(const std::string &dir, const Cloud &cloud, const std::string &file) {
    cv::Mat a = depthColour(cloud), b = background(dir, cloud);
    const fs::path un = fs::path(dir) / "rgb_unregistered.png";
    if (fs::exists(un)) b = cv::imread(un.string(), cv::IMREAD_COLOR);
    cv::resize(b, b, a.size());
    gridLines(a);
    gridLines(b);
    cv::Mat both;
    cv::vconcat(a, b, both);
    cv::imwrite(file, both);
    return 0;
}

/// `init`: a new label for the frame in `dir`, gravity estimated from its floor when it can be.
int initLabel(const std::string &dir, const Cloud &cloud, const std::string &file) {
    RealLabel l;
    l.frame = fs::path(dir).filename().string();
    l.projector = sim::exampleProjector();
    const auto g = estimateGravityFromFloor(cloud, Eigen::Vector3d(0, 1, 0));
    l.gravity_source = g ? "auto" : "stated";
    if (g) l.gravity = g->gravity;
    std::printf("gravity %s: %.4f %.4f %.4f (%d floor points)\n", l.gravity_source.c_str(), l.gravity.x(),
                l.gravity.y(), l.gravity.z(), g ? g->floor_points : 0);
    writeRealLabel(file, l);
    return 0;
}

/// `--aim u,v`: points the label's projector at the plane of the surface seen at pixel (u, v).
void aimProjector(RealLabel &l, const Cloud &cloud, const CameraIntrinsics &cam, const char *pixel) {
    double u = 0, v = 0;
    if (std::sscanf(pixel, "%lf,%lf", &u, &v) != 2) throw std::runtime_error("--aim u,v");
    int s = 0;
    for (int k = 0; k < static_cast<int>(l.surfaces.size()); ++k)
        for (const auto &r : l.surfaces[k].regions)
            if (insidePolygon(r.pixels, {u, v})) s = k;
    const SurfaceFit fit = fitLabelSurface(cloud, cam, l, s);
    if (!fit.ok) throw std::runtime_error("--aim: surface has no plane");
    const Eigen::Vector3d ray = cam.backProject(u, v, 1.0);
    const auto hit = intersectRay(fit.plane, Eigen::Vector3d::Zero(), ray);
    if (!hit) throw std::runtime_error("--aim: the pixel does not see the plane");
    l.projector.direction = (*hit - l.projector.origin).normalized();
}

/// Prints each surface's plane (tilt, points, rms) and the label's best rectangles.
void printLabelSummary(const RealLabel &l, const Cloud &cloud, const CameraIntrinsics &cam) {
    for (const auto &s : l.surfaces) {
        if (!s.has_plane) {
            std::printf("surface %s: no plane\n", s.name.c_str());
            continue;
        }
        const SurfaceFit f = fitLabelSurface(cloud, cam, l, static_cast<int>(&s - &l.surfaces[0]));
        const double tilt = std::asin(std::min(1.0, std::abs(s.plane.normal.dot(l.gravity)))) * 180 / M_PI;
        std::printf("surface %s: n %.3f %.3f %.3f d %.3f, tilt vs gravity %.1f deg, %d points, rms %.1f mm\n",
                    s.name.c_str(), s.plane.normal.x(), s.plane.normal.y(), s.plane.normal.z(), s.plane.d, tilt,
                    f.points, 1000 * f.rms);
    }
    if (l.best.found)
        std::printf("best on %s: %.3f x %.3f m = %.4f m^2\n", l.best.surface.c_str(), l.best.width, l.best.height,
                    l.best.area());
    else
        std::printf("best: none\n");
    if (l.colour.judged && l.colour.best.found)
        std::printf("colour best on %s: %.3f x %.3f m = %.4f m^2 (%zu unsuitable polygons)\n",
                    l.colour.best.surface.c_str(), l.colour.best.width, l.colour.best.height, l.colour.best.area(),
                    l.colour.unsuitable.size());
    else if (l.colour.judged)
        std::printf("colour best: none\n");
}

/// Distance of every reading to the planes of the surfaces (nearest): grey within 2 cm, yellow
/// 2-4 cm, red > 4 cm in front, blue > 4 cm behind, black no reading; with the label drawn over
/// it and a pixel grid, into `path`.
void writeResidualImage(const std::string &path, const RealLabel &l, const Cloud &cloud, const CameraIntrinsics &cam) {
    cv::Mat img(cloud.height, cloud.width, CV_8UC3, cv::Scalar(0, 0, 0));
    for (int v = 0; v < cloud.height; ++v)
        for (int u = 0; u < cloud.width; ++u) {
            const Point &p = cloud.points[static_cast<std::size_t>(v) * cloud.width + u];
            if (!isFinite(p)) continue;
            double r = 1e9;
            for (const auto &s : l.surfaces)
                if (s.has_plane) {
                    const double d = s.plane.signedDistance(p.cast<double>());
                    if (std::abs(d) < std::abs(r)) r = d;
                }
            cv::Vec3b c(90, 90, 90);
            if (std::abs(r) < 0.02)
                c = cv::Vec3b(200, 200, 200);
            else if (std::abs(r) < 0.04)
                c = cv::Vec3b(0, 220, 255);
            else if (r > 0 && r < 0.5)
                c = cv::Vec3b(0, 0, 255);
            else if (r < 0 && r > -0.5)
                c = cv::Vec3b(255, 80, 0);
            img.at<cv::Vec3b>(v, u) = c;
        }
    cv::Mat over = renderLabelOverlay(img, l, cam, nullptr, 0.0);
    gridLines(over);
    cv::imwrite(path, over);
}

}  // namespace

int main(int argc, char **argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: see the comment at the top of tests/label_tool.cpp\n");
        return 2;
    }
    try {
        if (std::string(argv[1]) == "score") return scoreRectangle(argc, argv);
        if (std::string(argv[1]) == "baseline") return writeBaseline(argc, argv);
        const std::string cmd = argv[1], file = argv[3];
        std::string dir = argv[2];
        while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
        const std::string cam_yaml = (fs::path(dir) / "camera.yaml").string();
        const CameraIntrinsics cam = readCamera(cam_yaml);
        const Cloud cloud = readDepthCloud((fs::path(dir) / "depth.png").string(), cam_yaml);
        if (cmd == "grid") return writeGrid(dir, cloud, file);
        if (cmd == "init") return initLabel(dir, cloud, file);
        RealLabel l = readRealLabel(file);
        std::string overlay, residual, refine;
        bool do_refine = false;
        for (int i = 4; i < argc; ++i) {
            const std::string a = argv[i];
            if (a == "--holes" && i + 1 < argc)
                holes(l, cloud, std::stoi(argv[++i]));
            else if (a == "--overlay" && i + 1 < argc)
                overlay = argv[++i];
            else if (a == "--residual" && i + 1 < argc)
                residual = argv[++i];
            else if (a == "--refine" && i + 1 < argc) {
                refine = argv[++i];
                do_refine = true;
            } else if (a == "--aim" && i + 1 < argc)
                aimProjector(l, cloud, cam, argv[++i]);
            else
                throw std::runtime_error("unknown option " + a);
        }
        l.best = referenceBest(cloud, cam, l);
        if (do_refine) {
            refineObstacles(l, cloud, refine);
            l.best = referenceBest(cloud, cam, l);
        }
        if (l.colour.judged) l.colour.best = colourReferenceBest(cam, l);
        printLabelSummary(l, cloud, cam);
        writeRealLabel(file, l);
        if (!residual.empty()) writeResidualImage(residual, l, cloud, cam);
        if (!overlay.empty()) {
            cv::Mat img = renderLabelOverlay(background(dir, cloud), l, cam, nullptr);
            cv::imwrite(overlay, img);
        }
        return 0;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "projsurf_label_tool: error: %s\n", e.what());
        return 2;
    }
}
