#include "pcl_reference.hpp"

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/Vertices.h>
#include <pcl/common/transforms.h>
#include <pcl/filters/crop_box.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/filters/project_inliers.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>
#include <pcl/surface/concave_hull.h>
#include <pcl/surface/convex_hull.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "projsurf/detection/rectangle_search.hpp"

namespace projsurf::bench {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

std::vector<std::vector<Eigen::Vector3d>> loops(const PclCloud &points, const std::vector<pcl::Vertices> &polygons) {
    std::vector<std::vector<Eigen::Vector3d>> out;
    for (const auto &poly : polygons) {
        std::vector<Eigen::Vector3d> loop;
        loop.reserve(poly.vertices.size());
        for (const auto i : poly.vertices) loop.emplace_back(points[i].getVector3fMap().cast<double>());
        if (loop.size() >= 3) out.push_back(std::move(loop));
    }
    return out;
}

}  // namespace

const std::vector<std::string> &stockStageNames() {
    static const std::vector<std::string> names = {"voxel_grid",   "ransac",      "extract_project",
                                                   "concave_hull", "convex_hull", "workspace_raster",
                                                   "rectangle",    "crop",        "outliers"};
    return names;
}

PclCloud::Ptr toPcl(const Cloud &cloud) {
    PclCloud::Ptr out(new PclCloud);
    out->resize(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const Point &p = cloud.points[i];
        (*out)[i].x = p.x();
        (*out)[i].y = p.y();
        (*out)[i].z = p.z();
    }
    out->width = static_cast<std::uint32_t>(cloud.width);
    out->height = static_cast<std::uint32_t>(cloud.height);
    out->is_dense = false;
    return out;
}

PclCloud::Ptr voxelGrid(const PclCloud::ConstPtr &cloud, double leaf) {
    PclCloud::Ptr out(new PclCloud);
    pcl::VoxelGrid<pcl::PointXYZ> grid;
    grid.setInputCloud(cloud);
    const float l = static_cast<float>(leaf);
    grid.setLeafSize(l, l, l);
    grid.filter(*out);
    return out;
}

SacPlane segmentVerticalPlane(const PclCloud::ConstPtr &cloud, const StockConfig &config) {
    SacPlane result;
    if (cloud->size() < 3) return result;
    pcl::SACSegmentation<pcl::PointXYZ> seg;
    seg.setOptimizeCoefficients(true);
    seg.setModelType(pcl::SACMODEL_PARALLEL_PLANE);  // plane parallel to the axis: a vertical plane
    seg.setMethodType(pcl::SAC_RANSAC);
    seg.setAxis(config.gravity.normalized().cast<float>());
    seg.setEpsAngle(config.eps_angle);
    seg.setDistanceThreshold(config.distance);
    seg.setMaxIterations(config.max_iterations);
    seg.setInputCloud(cloud);
    pcl::PointIndices inliers;
    pcl::ModelCoefficients coefficients;
    seg.segment(inliers, coefficients);
    if (inliers.indices.empty() || coefficients.values.size() != 4) return result;
    result.coefficients =
        Eigen::Vector4d(coefficients.values[0], coefficients.values[1], coefficients.values[2], coefficients.values[3]);
    result.inliers.assign(inliers.indices.begin(), inliers.indices.end());
    return result;
}

PclCloud::Ptr extractAndProject(const PclCloud::ConstPtr &cloud, const SacPlane &plane) {
    pcl::PointIndices::Ptr indices(new pcl::PointIndices);
    indices->indices.assign(plane.inliers.begin(), plane.inliers.end());
    PclCloud::Ptr inliers(new PclCloud);
    pcl::ExtractIndices<pcl::PointXYZ> extract;
    extract.setInputCloud(cloud);
    extract.setIndices(indices);
    extract.setNegative(false);
    extract.filter(*inliers);

    pcl::ModelCoefficients::Ptr coefficients(new pcl::ModelCoefficients);
    for (int i = 0; i < 4; ++i) coefficients->values.push_back(static_cast<float>(plane.coefficients[i]));
    PclCloud::Ptr projected(new PclCloud);
    pcl::ProjectInliers<pcl::PointXYZ> project;
    project.setModelType(pcl::SACMODEL_PLANE);
    project.setInputCloud(inliers);
    project.setModelCoefficients(coefficients);
    project.filter(*projected);
    return projected;
}

std::vector<std::vector<Eigen::Vector3d>> concaveHull(const PclCloud::ConstPtr &projected, double alpha) {
    if (projected->size() < 3) return {};
    pcl::ConcaveHull<pcl::PointXYZ> hull;
    hull.setInputCloud(projected);
    hull.setAlpha(alpha);
    hull.setDimension(2);  // the points were projected onto the plane
    PclCloud points;
    std::vector<pcl::Vertices> polygons;
    hull.reconstruct(points, polygons);
    return loops(points, polygons);
}

std::vector<std::vector<Eigen::Vector3d>> convexHull(const PclCloud::ConstPtr &projected) {
    if (projected->size() < 3) return {};
    pcl::ConvexHull<pcl::PointXYZ> hull;
    hull.setInputCloud(projected);
    hull.setDimension(2);
    PclCloud points;
    std::vector<pcl::Vertices> polygons;
    hull.reconstruct(points, polygons);
    return loops(points, polygons);
}

FreeRaster rasterFreeSpace(const PlaneFrame &frame, const std::vector<std::vector<Eigen::Vector3d>> &hull,
                           const Projector &projector, double cell) {
    FreeRaster r;
    r.cell = cell;
    if (hull.empty()) return r;
    // Projector workspace on the plane (paper eqs. 5-6).
    std::array<Eigen::Vector2d, 4> workspace;
    const auto rays = projector.cornerRays();
    Plane plane;
    plane.normal = frame.normal;
    plane.d = -frame.normal.dot(frame.origin);
    for (int i = 0; i < 4; ++i) {
        const auto hit = intersectRay(plane, projector.origin, rays[i]);
        if (!hit) return r;
        workspace[i] = frame.toPlane(*hit);
    }
    // Grid over both outlines (paper: M1 and M2 span the plane and the workspace).
    std::vector<std::vector<Eigen::Vector2d>> hull2d;
    Eigen::Vector2d lo = workspace[0], hi = workspace[0];
    for (const auto &w : workspace) {
        lo = lo.cwiseMin(w);
        hi = hi.cwiseMax(w);
    }
    for (const auto &loop : hull) {
        hull2d.emplace_back();
        for (const auto &p : loop) {
            hull2d.back().push_back(frame.toPlane(p));
            lo = lo.cwiseMin(hull2d.back().back());
            hi = hi.cwiseMax(hull2d.back().back());
        }
    }
    const double cols = std::ceil((hi.x() - lo.x()) / cell), rows = std::ceil((hi.y() - lo.y()) / cell);
    if (!(cols >= 1 && rows >= 1) || cols * rows > 4e7) return r;
    r.origin = {lo.x(), hi.y()};
    constexpr int kShift = 8;  // fillPoly fixed-point bits
    auto toPx = [&](const Eigen::Vector2d &uv) {
        const double x = (uv.x() - lo.x()) / cell - 0.5, y = (hi.y() - uv.y()) / cell - 0.5;  // cell centres
        return cv::Point(static_cast<int>(std::lround(x * (1 << kShift))),
                         static_cast<int>(std::lround(y * (1 << kShift))));
    };
    cv::Mat m1 = cv::Mat::zeros(static_cast<int>(rows), static_cast<int>(cols), CV_8U);
    cv::Mat m2 = m1.clone();
    std::vector<std::vector<cv::Point>> polys;
    for (const auto &loop : hull2d) {
        polys.emplace_back();
        for (const auto &uv : loop) polys.back().push_back(toPx(uv));
    }
    cv::fillPoly(m1, polys, cv::Scalar(255), cv::LINE_8, kShift);  // boundary + row scan, even-odd
    std::vector<cv::Point> ws;
    for (const auto &w : workspace) ws.push_back(toPx(w));
    cv::fillConvexPoly(m2, ws, cv::Scalar(255), cv::LINE_8, kShift);
    cv::bitwise_and(m1, m2, r.free);  // M3: free in both
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto &w : workspace) centre += 0.25 * w;
    r.prefer = {(centre.x() - lo.x()) / cell, (hi.y() - centre.y()) / cell};
    r.ok = true;
    return r;
}

PclCloud::Ptr cropToRectangle(const PclCloud::ConstPtr &cloud, const PlaneFrame &frame, const Rectangle &rect) {
    // Paper 3.2.3: rotate the cloud so the screen is perpendicular to z, then cut it to the
    // rectangle's limits.
    Eigen::Matrix3f rot;
    rot.row(0) = frame.right.cast<float>();
    rot.row(1) = frame.up.cast<float>();
    rot.row(2) = frame.normal.cast<float>();
    Eigen::Affine3f to_plane = Eigen::Affine3f::Identity();
    to_plane.linear() = rot;
    to_plane.translation() = -(rot * frame.origin.cast<float>());
    PclCloud::Ptr rotated(new PclCloud);
    pcl::transformPointCloud(*cloud, *rotated, to_plane);

    const Eigen::Vector2d bl = frame.toPlane(rect.corners[3]), tr = frame.toPlane(rect.corners[1]);
    const float far = 1e9f;
    pcl::CropBox<pcl::PointXYZ> crop;
    crop.setInputCloud(rotated);
    crop.setMin(Eigen::Vector4f(static_cast<float>(bl.x()), static_cast<float>(bl.y()), -far, 1.0f));
    crop.setMax(Eigen::Vector4f(static_cast<float>(tr.x()), static_cast<float>(tr.y()), far, 1.0f));
    PclCloud::Ptr out(new PclCloud);
    crop.filter(*out);
    return out;
}

CheckCounts countOutliers(const PclCloud &cropped, double outlier_distance) {
    CheckCounts c;
    c.points = static_cast<int>(cropped.size());
    if (cropped.empty()) return c;
    double mean = 0.0;
    for (const auto &p : cropped) mean += p.z;
    mean /= static_cast<double>(cropped.size());
    const double limit = outlier_distance * outlier_distance;
    for (const auto &p : cropped) {
        const double e = p.z - mean;
        c.outliers += e * e > limit;
    }
    return c;
}

StockPipeline::StockPipeline(const Projector &projector, const StockConfig &config)
    : projector_(projector), config_(config) {}

StockResult StockPipeline::run(const PclCloud::ConstPtr &cloud) const {
    StockResult res;
    double total = 0.0;
    auto stage = [&](const char *name, Clock::time_point t0, bool counted = true) {
        const double ms = msSince(t0);
        res.timing_ms.emplace_back(name, ms);
        if (counted) total += ms;
    };
    auto finish = [&](const std::string &reason) {
        res.reason = reason;
        res.timing_ms.emplace_back("total", total);
        return res;
    };

    auto t = Clock::now();
    const PclCloud::Ptr voxels = voxelGrid(cloud, config_.voxel_leaf);
    stage("voxel_grid", t);

    t = Clock::now();
    const SacPlane sac = segmentVerticalPlane(voxels, config_);
    stage("ransac", t);
    if (sac.inliers.size() < 3) return finish("no vertical plane");
    res.plane = makePlane(sac.coefficients.head<3>(), sac.coefficients[3]);
    res.inliers = static_cast<int>(sac.inliers.size());

    t = Clock::now();
    const PclCloud::Ptr projected = extractAndProject(voxels, sac);
    stage("extract_project", t);

    t = Clock::now();
    const auto hull = concaveHull(projected, config_.alpha);
    stage("concave_hull", t);
    if (config_.convex_too) {
        t = Clock::now();
        const auto convex = convexHull(projected);
        stage("convex_hull", t, false);
    }
    if (hull.empty()) return finish("no hull");

    t = Clock::now();
    Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
    std::size_t n = 0;
    for (const auto &loop : hull)
        for (const auto &p : loop) {
            anchor += p;
            ++n;
        }
    const PlaneFrame frame = makePlaneFrame(res.plane, config_.gravity, anchor / static_cast<double>(n));
    const FreeRaster raster = rasterFreeSpace(frame, hull, projector_, config_.cell);
    stage("workspace_raster", t);
    if (!raster.ok) return finish("projector workspace misses the plane");

    t = Clock::now();
    const double aspect = config_.aspect > 0.0 ? config_.aspect : projector_.aspect();
    const auto cells = largestAspectRect(raster.free, aspect, raster.prefer);
    if (cells) {
        const double c = raster.cell;
        const double height = cells->rows * c, width = height * aspect;
        const double u0 = raster.origin.x() + (cells->col + 0.5 * cells->cols) * c - 0.5 * width;
        const double v1 = raster.origin.y() - cells->row * c;
        res.rectangle = makeRectangle(frame, {u0, v1 - height}, {u0 + width, v1});
    }
    stage("rectangle", t);
    if (!cells) return finish("no free rectangle");

    t = Clock::now();
    const PclCloud::Ptr cropped = cropToRectangle(cloud, frame, res.rectangle);
    stage("crop", t);

    t = Clock::now();
    const CheckCounts counts = countOutliers(*cropped, config_.outlier_distance);
    stage("outliers", t);
    res.check_points = counts.points;
    res.outliers = counts.outliers;
    res.accepted = counts.outliers <= config_.max_outliers;
    res.found = res.accepted;
    return finish(res.accepted ? "" : "surface check rejected the rectangle");
}

}  // namespace projsurf::bench
