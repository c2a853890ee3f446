#pragma once
// A person walking into the beam of a placed picture, and how well a blanking mask
// kept the light off them: what lit framebuffer pixels hit, cast through the true scene.
#include <opencv2/core.hpp>
#include <vector>

#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scene.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::eval {

/// A person of 1.7 m, camera frame: torso (0.45 x 1.45 x 0.25 m) and head (0.2 x 0.25 x 0.22
/// m) standing on the floor plane y = floor_y, the torso's left-front-bottom corner at
/// (x, floor_y, z); with `arm`, an arm (8 x 8 cm, 0.55 m long) reaching right at shoulder
/// height. Every quad is labelled "person".
void addPerson(sim::Scene &scene, double x, double z, double floor_y = 1.0, bool arm = true);

/// Frames of a walk-in: the person's x from `x_from` to `x_to` (m, camera frame) in `frames`
/// equal steps, at depth z, each frame the base scene plus the person.
std::vector<sim::Scene> walkInScenes(const sim::Scene &base, double x_from, double x_to, int frames, double z,
                                     double floor_y = 1.0);

struct BeamScore {
    long lit_on_person = 0;  ///< lit framebuffer pixels whose ray first meets the person
    long on_person = 0;      ///< framebuffer pixels whose ray first meets the person
    long far_pixels = 0;     ///< lit before blanking, ray on `wall`, more than `far_m` from the person's shadow
    long far_lit = 0;        ///< of those, still lit after blanking
    double farLitShare() const { return far_pixels > 0 ? static_cast<double>(far_lit) / far_pixels : 1.0; }
};

/// Casts every framebuffer pixel's ray through `scene`. `before`/`after`: the framebuffer
/// without and with blanking (8-bit, any channels; lit = any channel non-zero). Distances on
/// the wall plane are measured on a 1 cm raster from the person's shadow (where rays that
/// meet the person would have met the wall).
BeamScore scoreBlanking(const sim::Scene &scene, const Plane &wall, const Projector &projector, const cv::Mat &before,
                        const cv::Mat &after, double far_m = 0.10);

/// One frame of the demo's walk-in: what an audience sees, with the framebuffer blanked for
/// the frame's cloud (and, for comparison, without).
struct WalkInShot {
    double person_x = 0.0;   ///< m, camera frame
    cv::Mat view;            ///< BGR, the blanked picture projected
    cv::Mat view_unblanked;  ///< BGR, the same frame without blanking
    int blanked_pixels = 0;
    double mask_ms = 0.0;  ///< time of the mask
    BeamScore score;       ///< through the true projector
};

/// A person walks in at depth `person_z` (m) in `frames` steps from x = -1.1 m to -0.25 m
/// (camera frame) in front of `scene`; each frame is seen by `sensor`, blanked with the
/// believed projector on `plane` (the detection's), and shown through the true projector.
std::vector<WalkInShot> walkInShots(const sim::Scene &scene, const Plane &wall, const Projector &real,
                                    const Projector &believed, const Plane &plane, const cv::Mat &framebuffer,
                                    const sim::PinholeView &viewer, const sim::Lighting &light, double person_z,
                                    unsigned seed, int frames = 3);

}  // namespace projsurf::eval
