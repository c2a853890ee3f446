#include "conversions.hpp"

#include <sensor_msgs/image_encodings.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "projsurf/detection/default/observed_free_space.hpp"
#include "projsurf/frontend/inputs/camera_info_intrinsics.hpp"
#include "projsurf/frontend/inputs/depth_image_cloud.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/rosbag/depth_image_bytes.hpp"
#include "projsurf/io/rosbag/pointcloud2.hpp"

namespace projsurf::ros_node {
namespace enc = sensor_msgs::image_encodings;

Cloud toCloud(const sensor_msgs::PointCloud2 &msg) { return cloudFromPointCloud2(viewOfMessage(msg), "points"); }

Cloud toCloud(const sensor_msgs::Image &depth, const sensor_msgs::CameraInfo &info) {
    // The message's pixels in this machine's byte order (io/rosbag/depth_image_bytes.hpp, as for bags).
    const cv::Mat image = depthImageFromBytes("depth", depth.encoding, depth.width, depth.height, depth.step,
                                              depth.is_bigendian != 0, depth.data.data(), depth.data.size());
    std::array<double, 9> K;
    std::copy(info.K.begin(), info.K.end(), K.begin());
    const CameraIntrinsics cam = frontend::cameraInfoIntrinsics("camera_info", info.width, info.height, K, depth.encoding);
    return frontend::depthImageToCloud("depth", image, cam);  // refuses an image of another size than camera_info's
}

cv::Mat colourToBgr(const sensor_msgs::Image &msg, const std::string &topic) {
    if (msg.encoding == enc::MONO8) throw InputError(topic, "its encoding is mono8; need bgr8, rgb8, bgra8 or rgba8");
    return toBgr(msg, topic);
}

cv::Mat toBgr(const sensor_msgs::Image &msg, const std::string &what) {
    int type, code = -1;
    if (msg.encoding == enc::BGR8)
        type = CV_8UC3;
    else if (msg.encoding == enc::RGB8)
        type = CV_8UC3, code = cv::COLOR_RGB2BGR;
    else if (msg.encoding == enc::BGRA8)
        type = CV_8UC4, code = cv::COLOR_BGRA2BGR;
    else if (msg.encoding == enc::RGBA8)
        type = CV_8UC4, code = cv::COLOR_RGBA2BGR;
    else if (msg.encoding == enc::MONO8)
        type = CV_8UC1, code = cv::COLOR_GRAY2BGR;
    else
        throw InputError(what, "encoding '" + msg.encoding + "' (expected bgr8, rgb8, bgra8, rgba8 or mono8)");
    if (msg.width == 0 || msg.height == 0) throw InputError(what, "is empty");
    const std::size_t row = static_cast<std::size_t>(msg.width) * CV_ELEM_SIZE(type);
    if (msg.step < row || msg.data.size() < static_cast<std::size_t>(msg.step) * msg.height)
        throw InputError(what, "data is shorter than its size says");
    const cv::Mat view(static_cast<int>(msg.height), static_cast<int>(msg.width), type,
                       const_cast<std::uint8_t *>(msg.data.data()), msg.step);
    cv::Mat out;
    if (code < 0)
        out = view.clone();
    else
        cv::cvtColor(view, out, code);
    return out;
}

sensor_msgs::Image toImageMsg(const cv::Mat &bgr, const std_msgs::Header &header) {
    CV_Assert(bgr.type() == CV_8UC3);
    sensor_msgs::Image msg;
    msg.header = header;
    msg.width = static_cast<std::uint32_t>(bgr.cols);
    msg.height = static_cast<std::uint32_t>(bgr.rows);
    msg.encoding = enc::BGR8;
    msg.is_bigendian = 0;
    msg.step = static_cast<std::uint32_t>(bgr.cols * 3);
    msg.data.resize(static_cast<std::size_t>(msg.step) * msg.height);
    for (int r = 0; r < bgr.rows; ++r) std::memcpy(&msg.data[r * msg.step], bgr.ptr(r), msg.step);
    return msg;
}

sensor_msgs::PointCloud2 toPointCloud2(const Cloud &cloud, const std_msgs::Header &header) {
    sensor_msgs::PointCloud2 msg;
    msg.header = header;
    msg.height = static_cast<std::uint32_t>(cloud.organized() ? cloud.height : 1);
    msg.width = static_cast<std::uint32_t>(cloud.organized() ? cloud.width : cloud.size());
    msg.is_bigendian = 0;
    msg.is_dense = 0;
    msg.point_step = 12;
    msg.row_step = msg.point_step * msg.width;
    for (int i = 0; i < 3; ++i) {
        sensor_msgs::PointField f;
        f.name = std::string(1, static_cast<char>('x' + i));
        f.offset = static_cast<std::uint32_t>(4 * i);
        f.datatype = sensor_msgs::PointField::FLOAT32;
        f.count = 1;
        msg.fields.push_back(f);
    }
    msg.data.resize(static_cast<std::size_t>(msg.row_step) * msg.height);
    for (std::size_t i = 0; i < cloud.size(); ++i) std::memcpy(&msg.data[i * 12], cloud.points[i].data(), 12);
    return msg;
}

geometry_msgs::PolygonStamped toPolygon(const Rectangle &rect, const std_msgs::Header &header) {
    geometry_msgs::PolygonStamped msg;
    msg.header = header;
    for (const auto &c : rect.corners) {
        geometry_msgs::Point32 p;
        p.x = static_cast<float>(c.x());
        p.y = static_cast<float>(c.y());
        p.z = static_cast<float>(c.z());
        msg.polygon.points.push_back(p);
    }
    return msg;
}

namespace {

geometry_msgs::Point point(const Eigen::Vector3d &v) {
    geometry_msgs::Point p;
    p.x = v.x();
    p.y = v.y();
    p.z = v.z();
    return p;
}

visualization_msgs::Marker marker(const std_msgs::Header &header, const std::string &ns, int id, int type, float r,
                                  float g, float b, float a) {
    visualization_msgs::Marker m;
    m.header = header;
    m.ns = ns;
    m.id = id;
    m.type = type;
    m.action = visualization_msgs::Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = m.scale.y = m.scale.z = 1.0;
    m.color.r = r;
    m.color.g = g;
    m.color.b = b;
    m.color.a = a;
    return m;
}

visualization_msgs::Marker outline(const std_msgs::Header &header, const std::string &ns, int id,
                                   const std::array<Eigen::Vector3d, 4> &corners, float r, float g, float b) {
    auto m = marker(header, ns, id, visualization_msgs::Marker::LINE_STRIP, r, g, b, 1.0f);
    m.scale.x = 0.01;  // line width, m
    for (int i = 0; i <= 4; ++i) m.points.push_back(point(corners[i % 4]));
    return m;
}

/// Cells the picture must not cover, one square point per cell, coloured by reason as in the
/// CLI's overlay (frontend/render/overlay.cpp's legend, RGB here): what stands in front of or proud of
/// the wall, the wall seen through, and (with colour) what is unfit to project on. Cells
/// without a reading are left out (beyond the wall's edge there are many).
visualization_msgs::Marker notFreeCells(const DetectionDebug &g, const std_msgs::Header &header,
                                        const std::string &ns) {
    auto m = marker(header, ns, 5, visualization_msgs::Marker::POINTS, 1.0f, 1.0f, 1.0f, 0.8f);
    if (g.cell_state.empty() || g.grid_cell <= 0.0) return m;
    m.scale.x = m.scale.y = g.grid_cell;  // point size, m
    auto rgba = [](float r, float g, float b) {
        std_msgs::ColorRGBA c;
        c.r = r / 255.0f, c.g = g / 255.0f, c.b = b / 255.0f, c.a = 0.8f;
        return c;
    };
    for (int r = 0; r < g.cell_state.rows; ++r)
        for (int c = 0; c < g.cell_state.cols; ++c) {
            const auto state = static_cast<CellState>(g.cell_state.at<uchar>(r, c));
            std_msgs::ColorRGBA colour;
            switch (state) {
            case CellState::InFront: colour = rgba(255, 130, 0); break;       // orange: in front (its shadow)
            case CellState::SeenThrough: colour = rgba(200, 80, 220); break;  // violet: seen through
            case CellState::Proud: colour = rgba(140, 0, 0); break;           // dark red: proud of the wall
            case CellState::Glare: colour = rgba(160, 255, 255); break;       // pale cyan: glare
            case CellState::Dark: colour = rgba(20, 40, 90); break;           // dark blue: too dark
            case CellState::Textured: colour = rgba(160, 60, 0); break;       // brown: textured
            case CellState::Saturated: colour = rgba(90, 0, 160); break;      // purple: saturated
            default: continue;
            }
            const Eigen::Vector2d uv(g.grid_origin.x() + (c + 0.5) * g.grid_cell,
                                     g.grid_origin.y() - (r + 0.5) * g.grid_cell);
            m.points.push_back(point(g.frame.toCamera(uv)));
            m.colors.push_back(colour);
        }
    return m;
}

}  // namespace

visualization_msgs::MarkerArray toMarkers(const Detection &det, const Rectangle *shown, const std_msgs::Header &header,
                                          const std::string &ns) {
    visualization_msgs::MarkerArray out;
    visualization_msgs::Marker clear;
    clear.header = header;
    clear.ns = ns;
    clear.action = visualization_msgs::Marker::DELETEALL;
    out.markers.push_back(clear);
    if (!det.found && shown == nullptr) {
        auto text = marker(header, ns, 0, visualization_msgs::Marker::TEXT_VIEW_FACING, 1.0f, 0.3f, 0.2f, 1.0f);
        text.pose.position.z = 1.0;
        text.scale.z = 0.1;  // text height, m
        text.text = "no projection surface: " + det.reason;
        out.markers.push_back(text);
        return out;
    }
    if (det.found || det.inliers > 0) {
        // The plane: a translucent 3 m x 3 m patch around the rectangle (or the workspace).
        const PlaneFrame &f = det.debug.frame;
        const Eigen::Vector3d centre =
            det.found ? det.rectangle.center() : (shown != nullptr ? shown->center() : f.origin);
        const Eigen::Vector3d o = det.plane.project(centre);
        const double h = 1.5;
        std::array<Eigen::Vector3d, 4> q = {o - h * f.right + h * f.up, o + h * f.right + h * f.up,
                                            o + h * f.right - h * f.up, o - h * f.right - h * f.up};
        auto plane = marker(header, ns, 1, visualization_msgs::Marker::TRIANGLE_LIST, 0.2f, 0.5f, 1.0f, 0.25f);
        for (int i : {0, 1, 2, 0, 2, 3}) plane.points.push_back(point(q[i]));
        if (f.right.norm() > 0.5) out.markers.push_back(plane);
        if (det.debug.has_workspace)
            out.markers.push_back(outline(header, ns, 2, det.debug.workspace, 0.1f, 0.9f, 0.1f));
        auto blocked = notFreeCells(det.debug, header, ns);
        if (!blocked.points.empty()) out.markers.push_back(blocked);
    }
    const Rectangle *rect = shown != nullptr ? shown : (det.found ? &det.rectangle : nullptr);
    if (rect != nullptr) {
        out.markers.push_back(outline(header, ns, 3, rect->corners, 1.0f, 0.6f, 0.0f));
        auto fill = marker(header, ns, 4, visualization_msgs::Marker::TRIANGLE_LIST, 1.0f, 0.6f, 0.0f, 0.35f);
        for (int i : {0, 1, 2, 0, 2, 3}) fill.points.push_back(point(rect->corners[i]));
        out.markers.push_back(fill);
    }
    return out;
}

}  // namespace projsurf::ros_node
