#include "eval/demo/walk_in.hpp"

#include <chrono>
#include <opencv2/imgproc.hpp>

#include "projsurf/people/beam_blanking.hpp"

namespace projsurf::eval {

using namespace projsurf::sim;  // the simulator the evaluation runs on
namespace {

const cv::Vec3f kClothes{0.45f, 0.25f, 0.15f};  // BGR, a dark blue jumper
const cv::Vec3f kSkin{0.55f, 0.65f, 0.85f};

bool lit(const cv::Mat &fb, int y, int x) {
    const uchar *p = fb.ptr<uchar>(y) + x * fb.channels();
    for (int c = 0; c < fb.channels(); ++c)
        if (p[c]) return true;
    return false;
}

}  // namespace

void addPerson(Scene &scene, double x, double z, double floor_y, bool arm) {
    using V = Eigen::Vector3d;
    addBox(scene, V(x, floor_y - 1.45, z), V(0.45, 0, 0), V(0, 1.45, 0), V(0, 0, 0.25), kClothes, "person");
    addBox(scene, V(x + 0.125, floor_y - 1.70, z + 0.02), V(0.2, 0, 0), V(0, 0.25, 0), V(0, 0, 0.22), kSkin, "person");
    if (arm)
        addBox(scene, V(x + 0.45, floor_y - 1.35, z + 0.08), V(0.55, 0, 0), V(0, 0.08, 0), V(0, 0, 0.08), kClothes,
               "person");
}

std::vector<Scene> walkInScenes(const Scene &base, double x_from, double x_to, int frames, double z, double floor_y) {
    std::vector<Scene> out;
    for (int k = 0; k < frames; ++k) {
        const double x = frames > 1 ? x_from + (x_to - x_from) * k / (frames - 1) : x_from;
        Scene s = base;
        addPerson(s, x, z, floor_y, true);
        out.push_back(std::move(s));
    }
    return out;
}

BeamScore scoreBlanking(const Scene &scene, const Plane &wall, const Projector &projector, const cv::Mat &before,
                        const cv::Mat &after, double far_m) {
    CV_Assert(before.size() == after.size() && before.cols == projector.width && before.rows == projector.height);
    // Wall raster: 1 cm cells in a frame on the wall plane around the lens's foot point.
    constexpr double kCell = 0.01;
    const Eigen::Vector3d n = wall.normal;
    Eigen::Vector3d e1 = Eigen::Vector3d::UnitY().cross(n);
    if (e1.norm() < 1e-6) e1 = Eigen::Vector3d::UnitX();
    e1.normalize();
    const Eigen::Vector3d e2 = n.cross(e1);
    const Eigen::Vector3d o = wall.project(projector.origin);
    const int half_w = 600, half_h = 400;                            // 12 x 8 m
    cv::Mat shadow(2 * half_h, 2 * half_w, CV_8U, cv::Scalar(255));  // 0 = shadow (distanceTransform's zeros)
    const auto cellOf = [&](const Eigen::Vector3d &p, int &cx, int &cy) {
        const Eigen::Vector3d r = p - o;
        cx = static_cast<int>(std::floor(r.dot(e1) / kCell)) + half_w;
        cy = static_cast<int>(std::floor(r.dot(e2) / kCell)) + half_h;
        return cx >= 0 && cy >= 0 && cx < shadow.cols && cy < shadow.rows;
    };

    BeamScore score;
    const int w = projector.width, h = projector.height;
    cv::Mat kind(h, w, CV_8U, cv::Scalar(0));  // 1 = person, 2 = wall (the plane), 0 = else
    std::vector<Eigen::Vector3d> wall_point(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const Eigen::Vector3d ray = projector.ray(Eigen::Vector2d(x, y));
            const auto hit = castRay(scene, projector.origin, ray);
            const auto on_wall = intersectRay(wall, projector.origin, ray);
            if (on_wall) wall_point[static_cast<size_t>(y) * w + x] = *on_wall;
            if (!hit) continue;
            if (scene.quads[hit->quad].label == "person") {
                kind.at<uchar>(y, x) = 1;
                ++score.on_person;
                if (lit(after, y, x)) ++score.lit_on_person;
                int cx, cy;
                if (on_wall && cellOf(*on_wall, cx, cy)) shadow.at<uchar>(cy, cx) = 0;
            } else if (on_wall && std::abs(wall.signedDistance(projector.origin + hit->t * ray)) < 0.02) {
                kind.at<uchar>(y, x) = 2;
            }
        }
    }
    cv::Mat dist;  // cells to the nearest shadow cell
    cv::distanceTransform(shadow, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (kind.at<uchar>(y, x) != 2 || !lit(before, y, x)) continue;
            int cx, cy;
            if (!cellOf(wall_point[static_cast<size_t>(y) * w + x], cx, cy)) continue;
            if (score.on_person > 0 && dist.at<float>(cy, cx) * kCell <= far_m) continue;
            ++score.far_pixels;
            if (lit(after, y, x)) ++score.far_lit;
        }
    }
    return score;
}

std::vector<WalkInShot> walkInShots(const Scene &scene, const Plane &wall, const Projector &real,
                                    const Projector &believed, const Plane &plane, const cv::Mat &framebuffer,
                                    const PinholeView &viewer, const Lighting &light, double person_z, unsigned seed,
                                    int frames) {
    std::vector<WalkInShot> shots;
    BeamBlanker blanker(believed);
    const auto scenes = walkInScenes(scene, -1.1, -0.25, frames, person_z);
    for (int k = 0; k < frames; ++k) {
        WalkInShot shot;
        shot.person_x = frames > 1 ? -1.1 + 0.85 * k / (frames - 1) : -1.1;
        const RgbdFrame seen = renderFrame(scenes[k], SensorModel(), seed + 1000 + k);
        const auto t0 = std::chrono::steady_clock::now();
        const cv::Mat &mask = blanker.compute(seen.cloud, plane);
        shot.mask_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        cv::Mat blanked = framebuffer.clone();
        applyBlanking(blanked, mask);
        shot.blanked_pixels = blanker.blankedPixels();
        shot.score = scoreBlanking(scenes[k], wall, real, framebuffer, blanked);
        shot.view = renderView(scenes[k], viewer, Projection{real, blanked}, light);
        shot.view_unblanked = renderView(scenes[k], viewer, Projection{real, framebuffer}, light);
        shots.push_back(std::move(shot));
    }
    return shots;
}

}  // namespace projsurf::eval
