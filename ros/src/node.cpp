#include "node.hpp"

#include <geometry_msgs/PolygonStamped.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>

#include "conversions.hpp"
#include "ignored_params.hpp"
#include "projsurf/frontend/answer/continuous_json.hpp"
#include "projsurf/frontend/answer/detect_answer.hpp"
#include "projsurf/frontend/answer/detection_document.hpp"
#include "projsurf/frontend/answer/detection_summary.hpp"
#include "projsurf/frontend/inputs/registered_colour.hpp"
#include "projsurf/frontend/render/framebuffer_render.hpp"
#include "projsurf/frontend/render/test_card.hpp"
#include "projsurf/frontend/settings/depth_range_check.hpp"
#include "projsurf/frontend/settings/gravity_warnings.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"

namespace projsurf::ros_node {
namespace {

/// ~gravity as the node's users write it, in the CLI's and Python's warnings.
const frontend::GravityWords kGravityWords{"~gravity", "~gravity auto"};

Eigen::Isometry3d toEigen(const geometry_msgs::Transform &t) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() =
        Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z).normalized().toRotationMatrix();
    T.translation() = Eigen::Vector3d(t.translation.x, t.translation.y, t.translation.z);
    return T;
}

}  // namespace

ProjsurfNode::ProjsurfNode(ros::NodeHandle nh, ros::NodeHandle pnh, NodeParams params)
    : params_(std::move(params)), nh_(nh), pnh_(pnh), detector_(params_.projector, params_.detector) {
    if (!params_.image.empty())
        picture_ = readImage(params_.image, cv::IMREAD_COLOR);
    else
        picture_ = frontend::testCard({params_.projector.width, params_.projector.height});
    if (!params_.gravity_frame.empty() || !params_.fixed_frame.empty()) {
        tf_buffer_ = std::make_unique<tf2_ros::Buffer>(ros::Duration(30.0));
        tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_, nh_);
    }
    if (params_.continuous)
        continuous_ = std::make_unique<ContinuousTracker>(
            ContinuousSettings{params_.projector, detector_.config(), params_.steady, params_.fit_margin_px});

    result_pub_ = pnh_.advertise<std_msgs::String>("result", 1, true);
    rectangle_pub_ = pnh_.advertise<geometry_msgs::PolygonStamped>("rectangle", 1, true);
    framebuffer_pub_ = pnh_.advertise<sensor_msgs::Image>("framebuffer", 1, true);
    markers_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
    detect_srv_ = pnh_.advertiseService("detect", &ProjsurfNode::onDetect, this);
    blanking_ = std::make_unique<NodeBlanking>(pnh_, params_.projector, params_.continuous && params_.blank);
    planner_ = std::make_unique<NodePlanner>(pnh_, params_.projector, params_.detector, params_.plan);
    plan_srv_ = pnh_.advertiseService("plan", &ProjsurfNode::onPlan, this);
    // Queue of 1: in continuous mode a slow frame drops the ones behind it, never lags.
    cloud_sub_ = nh_.subscribe("points", 1, &ProjsurfNode::onCloud, this);
    depth_sub_ = nh_.subscribe("depth/image_rect", 1, &ProjsurfNode::onDepth, this);
    // camera_info is small and paired by stamp: a few are kept (frontend/inputs/stamp_pairing.hpp).
    info_sub_ = nh_.subscribe("depth/camera_info", 10, &ProjsurfNode::onCameraInfo, this);
    image_sub_ = nh_.subscribe("image", 1, &ProjsurfNode::onImage, this);
    if (params_.use_colour && params_.detector.suitability.mode == SuitabilityMode::Off) {
        ROS_WARN("projsurf_node: ~use_colour with ~suitability off: the colour is not used");
    } else if (params_.use_colour) {
        // A couple queued: the colour image of a depth image's stamp may come just after it.
        colour_sub_ = nh_.subscribe("rgb/image_rect_color", 2, &ProjsurfNode::onColour, this);
        colour_ = std::make_unique<ColourInput>(colour_sub_.getTopic(), params_.detector.suitability.registration);
        ROS_INFO("projsurf_node: colour from %s (suitability %s)", colour_sub_.getTopic().c_str(),
                 suitabilityModeName(params_.detector.suitability.mode));
    } else if (params_.suitability_given && params_.detector.suitability.mode != SuitabilityMode::Off) {
        ROS_WARN("projsurf_node: %s", frontend::suitabilityWithoutColourWarning("~suitability", "~use_colour").c_str());
    }
    for (const std::string &w : params_.calib_warnings) ROS_WARN("projsurf_node: %s", w.c_str());
    for (const std::string &w : ignoredParamWarnings(pnh_, params_.detector.method))
        ROS_WARN("projsurf_node: %s", w.c_str());
    ROS_INFO("projsurf_node: projector %dx%d from %s; %s mode; listening on %s (or %s + %s)", params_.projector.width,
             params_.projector.height, params_.calib.c_str(), params_.continuous ? "continuous" : "on-demand (~detect)",
             cloud_sub_.getTopic().c_str(), depth_sub_.getTopic().c_str(), info_sub_.getTopic().c_str());
}

void ProjsurfNode::onImage(const sensor_msgs::ImageConstPtr &msg) {
    try {
        picture_ = toBgr(*msg);
        picture_from_topic_ = true;
    } catch (const InputError &e) {
        ROS_WARN_THROTTLE(5.0, "projsurf_node: ignoring picture on %s: %s", image_sub_.getTopic().c_str(), e.what());
    }
}

void ProjsurfNode::onColour(const sensor_msgs::ImageConstPtr &msg) {
    colour_->add(msg);
    colourless_ = 0;
    // The latest cloud came first and waits for this one.
    if (colour_wait_ && std::abs(msg->header.stamp.toSec() - cloud_header_.stamp.toSec()) <= frontend::kSameStampS) {
        colour_wait_ = false;
        useColour(*msg);
        if (continuous_) runContinuous();
    }
}

void ProjsurfNode::useColour(const sensor_msgs::Image &colour) {
    const ros::WallTime start = ros::WallTime::now();
    colour_note_ = colour_->attach(cloud_, colour, depth_stream_);
    colour_ms_ = (ros::WallTime::now() - start).toSec() * 1e3;
}

void ProjsurfNode::settleColourWait() {
    if (!colour_wait_) return;
    colour_wait_ = false;
    double offset = 0.0;
    if (const sensor_msgs::ImageConstPtr near = colour_->near(cloud_header_.stamp, offset)) {
        ROS_WARN_THROTTLE(5.0,
                          "projsurf_node: no colour image with the depth's stamp %.3f on %s; using one %.3f s away",
                          cloud_header_.stamp.toSec(), colour_sub_.getTopic().c_str(), offset);
        useColour(*near);
        return;
    }
    char text[160];
    std::snprintf(text, sizeof text, "no colour image within %.3f s of the depth's stamp %.3f", kColourMaxOffsetS,
                  cloud_header_.stamp.toSec());
    colour_note_ = text;
    ++colourless_;
    ROS_WARN_THROTTLE(5.0, "projsurf_node: %s on %s; detecting without colour", text, colour_sub_.getTopic().c_str());
}

void ProjsurfNode::onCameraInfo(const sensor_msgs::CameraInfoConstPtr &msg) {
    camera_infos_.add(msg->header.stamp.toSec(), msg);
    // The depth image of this stamp came first: now it has its camera_info.
    if (pending_depth_ &&
        std::abs(pending_depth_->header.stamp.toSec() - msg->header.stamp.toSec()) <= frontend::kSameStampS) {
        const sensor_msgs::ImageConstPtr depth = pending_depth_;
        pending_depth_.reset();
        takeDepth(*depth, *msg);
    }
}

void ProjsurfNode::onDepth(const sensor_msgs::ImageConstPtr &msg) {
    // The camera_info of the same stamp (a driver publishes both per frame), not the latest.
    if (const auto *info = camera_infos_.exact(msg->header.stamp.toSec())) {
        pending_depth_.reset();
        takeDepth(*msg, **info);
        return;
    }
    // An older image still waiting gets the nearest camera_info there is (a driver whose
    // stamps differ); this one waits for its own.
    double at = 0.0;
    if (pending_depth_) {
        if (const auto *info = camera_infos_.nearest(pending_depth_->header.stamp.toSec(), at)) {
            ROS_WARN_THROTTLE(
                5.0, "projsurf_node: no camera_info with the depth image's stamp %.3f on %s; using the one of %.3f",
                pending_depth_->header.stamp.toSec(), info_sub_.getTopic().c_str(), at);
            takeDepth(*pending_depth_, **info);
        } else {
            ROS_WARN_THROTTLE(5.0, "projsurf_node: depth image without camera_info on %s yet",
                              info_sub_.getTopic().c_str());
        }
    }
    pending_depth_ = msg;
}

void ProjsurfNode::takeDepth(const sensor_msgs::Image &depth, const sensor_msgs::CameraInfo &info) {
    // The stream's geometry: the colour's registration is checked again when it changes.
    char stream[200];
    std::snprintf(stream, sizeof stream, "depth %ux%u K %.2f %.2f %.2f %.2f %s", info.width, info.height, info.K[0],
                  info.K[4], info.K[2], info.K[5], depth.header.frame_id.c_str());
    try {
        takeCloud(toCloud(depth, info), depth.header, stream, depth_sub_.getTopic());
    } catch (const InputError &e) {
        rejectCloud("depth image", e.what(), depth.header);
    }
}

void ProjsurfNode::onCloud(const sensor_msgs::PointCloud2ConstPtr &msg) {
    try {
        takeCloud(toCloud(*msg), msg->header,
                  "cloud " + std::to_string(msg->width) + "x" + std::to_string(msg->height) + " " + msg->header.frame_id,
                  cloud_sub_.getTopic());
    } catch (const InputError &e) {
        rejectCloud("cloud", e.what(), msg->header);
    }
}

void ProjsurfNode::rejectCloud(const std::string &what, const std::string &problem, const std_msgs::Header &header) {
    ROS_WARN_THROTTLE(5.0, "projsurf_node: ignoring %s: %s", what.c_str(), problem.c_str());
    char stamp[64];
    std::snprintf(stamp, sizeof stamp, "%.3f", header.stamp.toSec());
    rejected_ = "the latest " + what + " (stamp " + stamp + ") was rejected: " + problem;
}

void ProjsurfNode::takeCloud(Cloud cloud, const std_msgs::Header &header, const std::string &stream,
                             const std::string &topic) {
    if (colour_wait_ && continuous_) {  // the previous cloud's colour never came: the nearest, or none
        settleColourWait();
        runContinuous();
    }
    colour_wait_ = false;  // on demand, the previous cloud is simply replaced
    depth_stream_ = stream;
    cloud_ = std::move(cloud);
    cloud_header_ = header;
    if (topic != cloud_topic_) range_checked_ = false;
    cloud_topic_ = topic;
    have_cloud_ = true;
    rejected_.clear();
    colour_ms_ = 0.0;
    if (colour_) {
        colour_note_.clear();
        if (const sensor_msgs::ImageConstPtr colour = colour_->exact(header.stamp)) {
            useColour(*colour);
        } else if (colourless_ < kColourlessToStopWaiting) {
            colour_wait_ = true;  // its colour image is on its way (until the next cloud or ~detect)
            return;
        } else {
            colour_note_ = "no colour image has come on " + colour_sub_.getTopic() + " lately";
            ROS_WARN_THROTTLE(5.0, "projsurf_node: %s; detecting without colour until some comes",
                              colour_note_.c_str());
        }
    }
    if (continuous_) runContinuous();
}

bool ProjsurfNode::lookup(const std::string &target, const std::string &source, const ros::Time &stamp,
                          Eigen::Isometry3d &pose, std::string &problem) {
    if (target == source) {
        pose = Eigen::Isometry3d::Identity();
        return true;
    }
    try {
        const auto t = tf_buffer_->lookupTransform(target, source, stamp, ros::Duration(params_.tf_timeout));
        pose = toEigen(t.transform);
        if (!pose.matrix().allFinite() || !(pose.translation().norm() <= limits::kMaxPoseTranslationM)) {
            problem = "the transform from " + source + " to " + target + " is not finite or more than " +
                      std::to_string(static_cast<int>(limits::kMaxPoseTranslationM)) + " m long";
            return false;
        }
        return true;
    } catch (const tf2::TransformException &e) {
        problem = "no transform from " + source + " to " + target + ": " + e.what();
        return false;
    }
}

frontend::GravityChoice ProjsurfNode::gravityChoiceFor(const std_msgs::Header &header, std::string &problem) {
    frontend::GravityChoice choice = params_.gravity;
    if (!params_.gravity_frame.empty()) {
        Eigen::Isometry3d camera_from_gravity;
        if (lookup(header.frame_id, params_.gravity_frame, header.stamp, camera_from_gravity, problem)) {
            choice.gravity = camera_from_gravity.linear() * Eigen::Vector3d(0.0, 0.0, -1.0);  // -z of a z-up frame
            choice.from_floor = false;
        } else {
            problem += " (using ~gravity instead)";
        }
    }
    // With ~gravity auto and no tf: "down" from the floor when one is in view, else a level camera.
    return choice;
}

frontend::GravityDetection ProjsurfNode::detectLatest() {
    std::string tf_problem;
    const frontend::GravityChoice choice = gravityChoiceFor(cloud_header_, tf_problem);
    if (!tf_problem.empty()) ROS_WARN_THROTTLE(5.0, "projsurf_node: %s", tf_problem.c_str());
    frontend::GravityDetection answer = frontend::detectWithGravity(detector_, cloud_, choice, params_.minimum,
                                                                    "the latest cloud", "~min_width", "~min_area");
    // The CLI's words on ~gravity (not on tf's: ~gravity_frame gave it). ~gravity's default,
    // the launch file's too, is the level camera's vector: a level camera assumed.
    const bool from_tf = !params_.gravity_frame.empty() && tf_problem.empty();
    const bool level = !choice.from_floor && choice.gravity == SurfaceDetector::levelGravity();
    const bool check_floor = !from_tf && !floor_checked_;
    const frontend::GravityUsed used{choice, level, answer.gravity};
    for (const std::string &w : frontend::gravityUsedWarnings(kGravityWords, used, cloud_, check_floor))
        warnThrottled(warnings_, w);
    floor_checked_ = floor_checked_ || check_floor;
    if (!range_checked_)
        if (const auto w = frontend::depthRangeWarning(cloud_, cloud_topic_, false))
            warnThrottled(warnings_, *w, "depth range");
    range_checked_ = true;
    return answer;
}

void ProjsurfNode::publishBlack(const std_msgs::Header &header) {
    cv::Mat black(params_.projector.height, params_.projector.width, CV_8UC3, cv::Scalar::all(0));
    framebuffer_pub_.publish(toImageMsg(black, header));
    writeFramebufferFile(black);
}

void ProjsurfNode::writeFramebufferFile(const cv::Mat &image) {
    if (params_.framebuffer_file.empty()) return;
    // For `projsurf show` on the projector's display; at most 5 writes a second.
    const ros::WallTime now = ros::WallTime::now();
    if ((now - last_file_write_).toSec() < 0.2) return;
    try {
        writeImageAtomic(params_.framebuffer_file, image);
        last_file_write_ = now;
    } catch (const InputError &e) {
        ROS_WARN_THROTTLE(10.0, "projsurf_node: %s", e.what());
    }
}

std::string ProjsurfNode::publishFramebuffer(const Rectangle &rect, const std_msgs::Header &header) {
    const frontend::FramebufferRender fb =
        frontend::renderFramebuffer(params_.projector, rect, picture_, params_.keystone_tolerance_px);
    if (fb.image.empty()) return fb.problem;
    framebuffer_pub_.publish(toImageMsg(fb.image, header));
    writeFramebufferFile(fb.image);
    return {};
}

std::string ProjsurfNode::colourSummary(const Detection &det) const {
    if (!colour_) return {};
    if (!colour_note_.empty()) return "; colour not used: " + colour_note_;
    if (!det.suitability.used) return {};
    char buf[160];
    std::snprintf(buf, sizeof buf, "; colour (%s): mean albedo %.2f, texture %.2f, %.0f %% of it unfit",
                  det.suitability.mode.c_str(), det.suitability.mean_albedo, det.suitability.texture,
                  100.0 * det.suitability.unsuitable_share);
    return buf;
}

ProjsurfNode::Outcome ProjsurfNode::detectOnce() {
    Outcome out;
    if (!have_cloud_) {
        out.message = "no cloud received yet on " + cloud_sub_.getTopic() + " (or " + depth_sub_.getTopic() + ")";
        if (!rejected_.empty()) out.message = "no valid cloud received yet: " + rejected_;
        return out;
    }
    settleColourWait();
    out = detectOnValidCloud();
    // Say so when this answer is not about the latest cloud.
    if (!rejected_.empty()) {
        char stamp[64];
        std::snprintf(stamp, sizeof stamp, "%.3f", cloud_header_.stamp.toSec());
        out.message = rejected_ + "; this answer is from the last valid cloud (stamp " + stamp + "): " + out.message;
    }
    return out;
}

ProjsurfNode::Outcome ProjsurfNode::detectOnValidCloud() {
    Outcome out;
    const Detection det = detectLatest().detection;
    const nlohmann::json result =
        frontend::detectionDocument(det, detector_.config(), params_.projector, params_.explain);
    std_msgs::String json;
    json.data = result.dump();
    result_pub_.publish(json);
    markers_pub_.publish(toMarkers(det, nullptr, cloud_header_, params_.marker_ns));
    if (!det.found) {
        // The paper's robot shows an error message and moves on (section 5).
        out.message = (det.reason.empty() ? "no projection surface found" : det.reason) + colourSummary(det);
        publishBlack(cloud_header_);
        ROS_INFO("projsurf_node: no surface: %s", out.message.c_str());
        return out;
    }
    out.success = true;
    out.message = frontend::detectionSummary(det) + colourSummary(det);
    rectangle_pub_.publish(toPolygon(det.rectangle, cloud_header_));
    blanking_->publishFocus(det.rectangle);
    const std::string problem = publishFramebuffer(det.rectangle, cloud_header_);
    if (!problem.empty()) out.message += "; but the picture cannot be shown there: " + problem;
    ROS_INFO("projsurf_node: %s", out.message.c_str());
    return out;
}

bool ProjsurfNode::onDetect(std_srvs::Trigger::Request &, std_srvs::Trigger::Response &res) {
    Outcome o;
    try {
        o = detectOnce();
    } catch (const std::exception &e) {  // never take the node down for one bad frame
        o.success = false;
        o.message = std::string("detection failed: ") + e.what();
        ROS_ERROR("projsurf_node: %s", o.message.c_str());
    }
    res.success = o.success;
    res.message = o.message;
    return true;
}

bool ProjsurfNode::onPlan(std_srvs::Trigger::Request &, std_srvs::Trigger::Response &res) {
    res.success = false;
    if (!have_cloud_) {
        res.message = "no cloud received yet";
        return true;
    }
    try {
        std::string problem;
        Eigen::Isometry3d fixed_from_camera = Eigen::Isometry3d::Identity();
        std::string frame = cloud_header_.frame_id;
        if (!params_.fixed_frame.empty() &&
            lookup(params_.fixed_frame, cloud_header_.frame_id, cloud_header_.stamp, fixed_from_camera, problem))
            frame = params_.fixed_frame;
        // Today's answer is ~detect's, by the same call.
        const frontend::GravityDetection today = detectLatest();
        const NodePlanner::Answer a = planner_->plan(cloud_, today.gravity.gravity, today.detection, fixed_from_camera,
                                                     frame, cloud_header_.stamp);
        res.success = a.found;
        res.message = a.message;
    } catch (const std::exception &e) {  // never take the node down for one bad frame
        res.message = std::string("plan failed: ") + e.what();
    }
    ROS_INFO("projsurf_node: ~plan: %s", res.message.c_str());
    return true;
}

void ProjsurfNode::runContinuous() {
    const ros::WallTime start = ros::WallTime::now();
    const std_msgs::Header header = cloud_header_;
    Eigen::Isometry3d fixed_from_camera = Eigen::Isometry3d::Identity();
    std::string problem;
    if (!params_.fixed_frame.empty() &&
        !lookup(params_.fixed_frame, header.frame_id, header.stamp, fixed_from_camera, problem)) {
        ROS_WARN_THROTTLE(5.0, "projsurf_node: skipping a cloud: %s", problem.c_str());
        return;
    }
    Detection det;
    try {
        det = detectLatest().detection;
    } catch (const std::exception &e) {
        ROS_ERROR_THROTTLE(5.0, "projsurf_node: detection failed: %s", e.what());
        return;
    }
    const ContinuousFrame o = continuous_->update(det, cloud_, fixed_from_camera);
    // Re-warp every frame: the robot moved, so the same place on the wall has new pixels.
    frontend::FramebufferRender fb;
    if (o.has_target)
        fb = frontend::renderFramebuffer(params_.projector, o.shown, picture_, params_.keystone_tolerance_px);
    if (fb.image.empty())
        fb.image = cv::Mat(params_.projector.height, params_.projector.width, CV_8UC3, cv::Scalar::all(0));
    blanking_->apply(fb.image, cloud_, o.has_target ? &o.shown : nullptr, header);
    const double frame_ms = (ros::WallTime::now() - start).toSec() * 1e3 + colour_ms_;

    // The frame's document as `detect --bag --steady` and Python's Tracker write it, then the node's own.
    nlohmann::json j = frontend::detectionDocument(det, detector_.config(), params_.projector, params_.explain);
    frontend::addContinuousFrame(j, o);
    // `continuous.event` repeats the top-level `event` for readers written before it moved up.
    j["continuous"] = {{"event", j["event"]},
                       {"showing", o.has_target && fb.problem.empty()},
                       {"stamp", header.stamp.toSec()},
                       {"frame_ms", std::round(frame_ms * 1000.0) / 1000.0}};
    if (colour_) {
        j["continuous"]["colour"] = {{"used", colour_note_.empty()},
                                     {"ms", std::round(colour_ms_ * 1000.0) / 1000.0},
                                     {"registration", colour_->registration()}};
        if (!colour_note_.empty()) j["continuous"]["colour"]["why_not"] = colour_note_;
    }
    if (blanking_->enabled())
        j["continuous"]["blanking"] = {{"blanked_pixels", blanking_->blankedPixels()},
                                       {"ms", std::round(blanking_->lastMs() * 1000.0) / 1000.0}};
    std_msgs::String json;
    json.data = j.dump();
    result_pub_.publish(json);
    markers_pub_.publish(toMarkers(det, o.has_target ? &o.shown : nullptr, header, params_.marker_ns));
    if (o.has_target) rectangle_pub_.publish(toPolygon(o.shown, header));
    framebuffer_pub_.publish(toImageMsg(fb.image, header));
    writeFramebufferFile(fb.image);
    if (o.event != SteadyEvent::Kept && o.event != SteadyEvent::None)
        ROS_INFO("projsurf_node: continuous: %s", toString(o.event));

    const ros::WallTime now = ros::WallTime::now();
    if (!last_frame_.isZero()) {
        const double dt = (now - last_frame_).toSec();
        if (dt > 0.0) rate_hz_ = rate_hz_ == 0.0 ? 1.0 / dt : 0.9 * rate_hz_ + 0.1 / dt;
    }
    last_frame_ = now;
    ROS_INFO_THROTTLE(10.0, "projsurf_node: continuous mode: %.1f clouds/s in, %.1f ms per frame (detection %.1f ms)",
                      rate_hz_, frame_ms, det.timing_ms.count("total") ? det.timing_ms.at("total") : 0.0);
}

}  // namespace projsurf::ros_node
