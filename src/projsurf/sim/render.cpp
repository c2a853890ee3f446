#include "projsurf/sim/render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "projsurf/sim/noise/gaussian_table.hpp"
#include "projsurf/sim/ray_cast.hpp"

namespace projsurf::sim {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

/// Bilinear BGR sample of an 8-bit image at (x, y) (pixel centres at integers), in [0, 1].
cv::Vec3f sampleBilinear(const cv::Mat &img, double x, double y) {
    const double fx = std::clamp(x, 0.0, img.cols - 1.0), fy = std::clamp(y, 0.0, img.rows - 1.0);
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
    const int x1 = std::min(x0 + 1, img.cols - 1), y1 = std::min(y0 + 1, img.rows - 1);
    const float ax = static_cast<float>(fx - x0), ay = static_cast<float>(fy - y0);
    const cv::Vec3b &a = img.at<cv::Vec3b>(y0, x0), &b = img.at<cv::Vec3b>(y0, x1);
    const cv::Vec3b &c = img.at<cv::Vec3b>(y1, x0), &d = img.at<cv::Vec3b>(y1, x1);
    cv::Vec3f out;
    for (int k = 0; k < 3; ++k)
        out[k] = ((1 - ay) * ((1 - ax) * a[k] + ax * b[k]) + ay * ((1 - ax) * c[k] + ax * d[k])) / 255.0f;
    return out;
}

/// The projector as a light: its shadow map and framebuffer.
struct ProjectorLight {
    ShadowMap map;
    PinholeView view;
    Projector projector;
    cv::Mat framebuffer;
};

/// Checks the framebuffer and casts the projector's shadow map (about `width` texels wide).
std::optional<ProjectorLight> makeLight(const Scene &scene, const std::optional<Projection> &projection, int width) {
    if (!projection) return std::nullopt;
    const cv::Mat &fb = projection->framebuffer;
    if (fb.type() != CV_8UC3 || fb.cols != projection->projector.width || fb.rows != projection->projector.height)
        throw std::invalid_argument("render: the framebuffer must be BGR 8-bit of the projector's resolution");
    ProjectorLight light;
    light.view = projectorView(projection->projector);
    light.projector = projection->projector;
    light.map = makeShadowMap(scene, light.view, std::min(1.0, static_cast<double>(width) / light.view.width));
    light.framebuffer = fb;
    return light;
}

/// Light leaving surface point p of quad qi, as a fraction of white per BGR channel: the
/// albedo under ambient light, plus the framebuffer's colour where the projector reaches p.
/// The reflectance at p: the quad's texture (nearest texel) where it has one, else its albedo.
cv::Vec3f albedoAt(const Quad &quad, const Eigen::Vector3d &p) {
    if (quad.texture.empty()) return quad.albedo;
    const Eigen::Vector3d q = p - quad.corner;
    const double a = q.dot(quad.edge_a) / quad.edge_a.squaredNorm(), b = q.dot(quad.edge_b) / quad.edge_b.squaredNorm();
    const int col = std::clamp(static_cast<int>(a * quad.texture.cols), 0, quad.texture.cols - 1);
    const int row = std::clamp(static_cast<int>(b * quad.texture.rows), 0, quad.texture.rows - 1);
    return quad.texture.at<cv::Vec3f>(row, col);
}

/// The framebuffer pixel whose light reaches surface point p of quad qi, if any: p inside the
/// projector's frustum (through its lens model) and not in its shadow.
std::optional<Eigen::Vector2d> framebufferPixel(const ProjectorLight &light, const Eigen::Vector3d &p, int qi) {
    if (!light.map.reaches(p, qi)) return std::nullopt;
    if (!light.projector.distorted()) {
        const Eigen::Vector2d px = light.view.pixelOf(light.view.toView(p));
        if (!light.view.inside(px)) return std::nullopt;
        return px;
    }
    const auto px = light.projector.toPixel(p);
    if (!px || px->x() < -0.5 || px->x() >= light.projector.width - 0.5 || px->y() < -0.5 ||
        px->y() >= light.projector.height - 0.5)
        return std::nullopt;
    return px;
}

cv::Vec3f shade(const Quad &quad, const Eigen::Vector3d &p, int qi, const std::optional<ProjectorLight> &light,
                const Lighting &lighting) {
    const cv::Vec3f albedo = albedoAt(quad, p);
    cv::Vec3f c = albedo * static_cast<float>(lighting.ambient) + cv::Vec3f::all(quad.emission);
    if (!light) return c;
    if (const auto px = framebufferPixel(*light, p, qi)) {
        const cv::Vec3f fbc = sampleBilinear(light->framebuffer, px->x(), px->y());
        c += albedo.mul(fbc) * static_cast<float>(lighting.projector_gain);
    }
    return c;
}

}  // namespace

cv::Mat renderView(const Scene &scene, const PinholeView &viewer, const std::optional<Projection> &projection,
                   const Lighting &lighting) {
    const DepthBuffer buf = castView(scene, viewer, 0.01);
    const std::optional<ProjectorLight> light = makeLight(scene, projection, std::max(viewer.width, 640));
    cv::Mat img(viewer.height, viewer.width, CV_8UC3, cv::Scalar(0, 0, 0));
    for (int v = 0; v < viewer.height; ++v)
        for (int u = 0; u < viewer.width; ++u) {
            const int qi = buf.quad.at<int>(v, u);
            if (qi < 0) continue;
            const Eigen::Vector3d p = viewer.origin + buf.z.at<double>(v, u) * viewer.rayDirection(u, v);
            const cv::Vec3f c = shade(scene.quads[qi], p, qi, light, lighting);
            cv::Vec3b &out = img.at<cv::Vec3b>(v, u);
            for (int k = 0; k < 3; ++k) out[k] = cv::saturate_cast<uchar>(255.0f * c[k]);
        }
    return img;
}

namespace {

/// The emitter's shadow map, for sensors whose emitter sits beside the camera (IR shadows).
std::optional<ShadowMap> emitterShadow(const Scene &scene, const SensorModel &sensor, const PinholeView &view) {
    if (!sensor.ir_shadow) return std::nullopt;
    // The emitter's pattern covers a little more than the camera's view.
    PinholeView e = view.padded(sensor.camera.width / 8);
    e.origin = sensor.emitter;
    return makeShadowMap(scene, e);
}

/// A frame of the camera's size with no reading and black colour.
RgbdFrame emptyFrame(const CameraIntrinsics &cam, const DepthBuffer &buf) {
    RgbdFrame f;
    f.depth = cv::Mat(cam.height, cam.width, CV_16UC1, cv::Scalar(0));
    f.rgb = cv::Mat(cam.height, cam.width, CV_8UC3, cv::Scalar(0, 0, 0));
    f.quad = buf.quad.clone();
    f.cloud.width = cam.width;
    f.cloud.height = cam.height;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    f.cloud.points.assign(static_cast<std::size_t>(cam.width) * cam.height, Point(nan, nan, nan));
    return f;
}

/// Pixels within two of a depth edge (a different surface more than edge_jump away): 1.
cv::Mat depthEdges(const DepthBuffer &buf, const SensorModel &sensor) {
    const CameraIntrinsics &cam = sensor.camera;
    cv::Mat edges = cv::Mat::zeros(cam.height, cam.width, CV_8U);
    auto jump = [&](int u0, int v0, int u1, int v1) {
        const int a = buf.quad.at<int>(v0, u0), b = buf.quad.at<int>(v1, u1);
        return a != b &&
               (a < 0 || b < 0 || std::abs(buf.z.at<double>(v0, u0) - buf.z.at<double>(v1, u1)) > sensor.edge_jump);
    };
    for (int v = 0; v < cam.height; ++v)
        for (int u = 0; u < cam.width; ++u)
            if ((u + 1 < cam.width && jump(u, v, u + 1, v)) || (v + 1 < cam.height && jump(u, v, u, v + 1)))
                edges.at<uchar>(v, u) = 1;
    cv::dilate(edges, edges, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
    return edges;
}

}  // namespace

RgbdFrame renderFrame(const Scene &scene, const SensorModel &sensor, unsigned seed,
                      const std::optional<Projection> &projection, const Lighting &lighting) {
    const CameraIntrinsics &cam = sensor.camera;
    const PinholeView view = cameraView(cam);
    const DepthBuffer buf = castView(scene, view, 0.05);

    const std::optional<ShadowMap> emitter = emitterShadow(scene, sensor, view);
    // A projector shadow map as wide as the camera image is enough for the light's edges.
    const std::optional<ProjectorLight> light = makeLight(scene, projection, cam.width);

    RgbdFrame f = emptyFrame(cam, buf);

    // Per-quad constants, and the grazing-angle thresholds as cosines (no acos per pixel).
    std::vector<Eigen::Vector3d> normals;
    for (const auto &q : scene.quads) normals.push_back(q.normal());
    const double cos_start = std::cos(sensor.grazing_start_deg / kRadToDeg);
    const double cos_max = std::cos(sensor.grazing_max_deg / kRadToDeg);

    const bool jitter = sensor.noise && sensor.edge_jitter_px > 0.0;
    const cv::Mat edges = jitter ? depthEdges(buf, sensor) : cv::Mat();

    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    NormalSource gauss(rng);
    const float colour_sigma = sensor.noise ? static_cast<float>(sensor.rgb_noise) : 0.0f;
    for (int v = 0; v < cam.height; ++v) {
        const int *qrow = buf.quad.ptr<int>(v);
        const double *zrow = buf.z.ptr<double>(v);
        cv::Vec3b *rgb_row = f.rgb.ptr<cv::Vec3b>(v);
        std::uint16_t *depth_row = f.depth.ptr<std::uint16_t>(v);
        Point *cloud_row = f.cloud.points.data() + static_cast<std::size_t>(v) * cam.width;
        const double dy = (v - cam.cy) / cam.fy;
        for (int u = 0; u < cam.width; ++u) {
            const int qi = qrow[u];
            if (qi < 0) continue;  // nothing there: no reading, black
            const Quad &quad = scene.quads[qi];
            const Eigen::Vector3d d((u - cam.cx) / cam.fx, dy, 1.0);  // camera ray, z = 1
            const double z = zrow[u];
            const Eigen::Vector3d p = z * d;

            // Depth reading. Beside a depth edge the reading may come from the neighbouring
            // surface: the edge lands within about a pixel (ragged edges).
            int qd = qi;
            double zd = z;
            if (jitter && edges.at<uchar>(v, u)) {
                const int du = static_cast<int>(std::lround(sensor.edge_jitter_px * gauss.next()));
                const int dv = static_cast<int>(std::lround(sensor.edge_jitter_px * gauss.next()));
                const int nu = std::clamp(u + du, 0, cam.width - 1), nv = std::clamp(v + dv, 0, cam.height - 1);
                const int qn = buf.quad.at<int>(nv, nu);
                const double zn = buf.z.at<double>(nv, nu);
                if (qn != qi && (qn < 0 || std::abs(zn - z) > sensor.edge_jump)) {
                    qd = qn;
                    zd = zn;
                }
            }
            bool valid = qd >= 0;
            const Eigen::Vector3d pd = zd * d;
            if (valid && emitter && !emitter->reaches(pd, qd)) valid = false;
            const double cos_angle = valid ? std::abs(normals[qd].dot(d)) / d.norm() : 1.0;
            if (valid && cos_angle < cos_start) {
                const double drop = sensor.dropoutProbability(std::acos(cos_angle) * kRadToDeg);
                valid = cos_angle > cos_max && drop < 1.0 && (drop <= 0.0 || uniform(rng) >= drop);
            }
            const double zm = valid ? sensor.measure(zd, sensor.noise ? gauss.next() : 0.0f) : 0.0;
            if (zm > 0.0) {
                cloud_row[u] = (zm * d).cast<float>();
                depth_row[u] = static_cast<std::uint16_t>(std::min(65535.0, std::round(zm * cam.depth_scale)));
            }

            // Colour: albedo under ambient light plus the projector's light where it reaches.
            const cv::Vec3f c = shade(quad, p, qi, light, lighting);
            for (int k = 0; k < 3; ++k) {
                float value = 255.0f * c[k];
                if (colour_sigma > 0.0f) value += colour_sigma * gauss.next();
                rgb_row[u][k] = cv::saturate_cast<uchar>(value);
            }
        }
    }
    return f;
}

LightTransport lightTransport(const Scene &scene, const PinholeView &viewer, const Projector &projector,
                              const Lighting &lighting) {
    const DepthBuffer buf = castView(scene, viewer, 0.05);
    const cv::Mat black(projector.height, projector.width, CV_8UC3, cv::Scalar(0, 0, 0));
    const std::optional<ProjectorLight> light = makeLight(scene, Projection{projector, black}, viewer.width);
    LightTransport t;
    t.ambient = cv::Mat(viewer.height, viewer.width, CV_32FC3, cv::Scalar::all(0));
    t.reflectance = cv::Mat(viewer.height, viewer.width, CV_32FC3, cv::Scalar::all(0));
    t.fb_x = cv::Mat(viewer.height, viewer.width, CV_32F, cv::Scalar(-1));
    t.fb_y = cv::Mat(viewer.height, viewer.width, CV_32F, cv::Scalar(-1));
    for (int v = 0; v < viewer.height; ++v)
        for (int u = 0; u < viewer.width; ++u) {
            const int qi = buf.quad.at<int>(v, u);
            if (qi < 0) continue;
            const Quad &quad = scene.quads[qi];
            const Eigen::Vector3d p = viewer.origin + buf.z.at<double>(v, u) * viewer.rayDirection(u, v);
            const cv::Vec3f albedo = albedoAt(quad, p);
            t.ambient.at<cv::Vec3f>(v, u) =
                albedo * static_cast<float>(lighting.ambient) + cv::Vec3f::all(quad.emission);
            const auto px = framebufferPixel(*light, p, qi);
            if (!px) continue;
            t.reflectance.at<cv::Vec3f>(v, u) = albedo * static_cast<float>(lighting.projector_gain);
            // Clamped like sampleBilinear: the outer half pixel takes the edge pixel's colour.
            t.fb_x.at<float>(v, u) = static_cast<float>(std::clamp(px->x(), 0.0, projector.width - 1.0));
            t.fb_y.at<float>(v, u) = static_cast<float>(std::clamp(px->y(), 0.0, projector.height - 1.0));
        }
    return t;
}

cv::Mat litBy(const LightTransport &transport, const cv::Mat &framebuffer) {
    cv::Mat seen;
    cv::remap(framebuffer, seen, transport.fb_x, transport.fb_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    seen.convertTo(seen, CV_32FC3, 1.0 / 255.0);
    return transport.ambient + transport.reflectance.mul(seen);
}

}  // namespace projsurf::sim
