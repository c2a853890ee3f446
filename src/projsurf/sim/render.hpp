#pragma once
// Renders what the RGB-D camera sees of a scene, optionally with a picture projected on it:
// the depth image, the organized cloud and the colour image (with the projector's light and
// its shadows). Deterministic for a given seed.
#include <opencv2/core.hpp>
#include <optional>

#include "projsurf/sim/ray_cast.hpp"
#include "projsurf/sim/scenes/scene.hpp"
#include "projsurf/sim/sensor_model.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::sim {

/// A picture sent to the projector: `framebuffer` is BGR (CV_8UC3) of the projector's resolution.
struct Projection {
    Projector projector;
    cv::Mat framebuffer;
};

/// Light on the scene, as fractions of full white (a dim room, so the projected picture and
/// the calibration disc stand out, as in the paper's set-up, section 3.1.1).
struct Lighting {
    double ambient = 0.15;        ///< room light reaching every surface
    double projector_gain = 1.0;  ///< a white framebuffer pixel adds this much light
};

struct RgbdFrame {
    cv::Mat depth;  ///< CV_16UC1 in camera.depth_scale units (mm), 0 = no reading
    cv::Mat rgb;    ///< CV_8UC3 BGR, registered to the depth image
    Cloud cloud;    ///< organized, camera frame, metres; NaN where there is no reading
    cv::Mat quad;   ///< CV_32S, index of the quad seen at each pixel (-1 = nothing), before dropouts
};

/// Renders one frame. `projection` (optional) is lit onto the scene: a camera pixel shows the
/// framebuffer colour (bilinear) times the surface albedo when its surface point is inside
/// the projector's frustum and not in a projector shadow; every surface also gets ambient light.
RgbdFrame renderFrame(const Scene &scene, const SensorModel &sensor, unsigned seed,
                      const std::optional<Projection> &projection = std::nullopt, const Lighting &lighting = {});

/// A noise-free colour image of the scene from any viewpoint (an audience member facing the
/// wall, see facingView), lit like renderFrame's colour image.
cv::Mat renderView(const Scene &scene, const PinholeView &viewer, const std::optional<Projection> &projection,
                   const Lighting &lighting = {});

/// How a projector's light reaches the camera, cast once for a fixed scene and viewpoint so that
/// many framebuffers (a structured-light sequence) cost an image remap each instead of a
/// render: per camera pixel, the light without the projector, the reflectance to the
/// projector's light, and the framebuffer position lighting it.
struct LightTransport {
    cv::Mat ambient;      ///< CV_32FC3, ambient light and emission leaving the surface, fraction of white
    cv::Mat reflectance;  ///< CV_32FC3, albedo times projector gain; 0 where the projector does not reach
    cv::Mat fb_x, fb_y;   ///< CV_32F, framebuffer pixel lighting each camera pixel; -1 where none
};
LightTransport lightTransport(const Scene &scene, const PinholeView &viewer, const Projector &projector,
                              const Lighting &lighting = {});
/// The noise-free colour the viewer sees with `framebuffer` (BGR 8-bit, the projector's size)
/// projected: CV_32FC3, fraction of white per channel, as renderFrame's colour before noise.
cv::Mat litBy(const LightTransport &transport, const cv::Mat &framebuffer);

}  // namespace projsurf::sim
