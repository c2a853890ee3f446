#pragma once
// The part of a seen wall's departure from its plane that a quadratic cannot follow: the
// low-frequency distortion of a depth camera, whose features are about a hundred pixels across
// (Kinect v1: Smisek et al. 2011, Herrera et al. 2012; fixed per unit), so several of them lie
// on one wall. A robust smoothing of the residuals over the wall: weighted residuals binned on
// a grid of nodes, both sums blurred with a Gaussian, their ratio the height at the nodes,
// bilinear between them; Tukey weights keep what stands proud of the wall out of it.
#include <Eigen/Core>
#include <algorithm>
#include <vector>

namespace projsurf {

/// Heights (m) at the nodes of a regular grid over plane coordinates (u, v); node (i, j) is at
/// origin + spacing * (i, j); bilinear between nodes, the border node's value beyond the grid.
struct WallRelief {
    Eigen::Vector2d origin = Eigen::Vector2d::Zero();
    double spacing = 0.0;  ///< m; 0 = no relief (height 0 everywhere)
    int nu = 0, nv = 0;
    std::vector<float> h;  ///< nv x nu, row j = v index

    /// Where a coordinate falls along one axis of `n` nodes (`f` in node units): the node
    /// interval `i` and the fraction `a` into it, clamped to the grid (NaN reads node 0).
    struct Axis {
        int i;
        double a;
    };
    static Axis axis(double f, int n) {
        f = std::min(double(n - 1), std::max(0.0, f));  // max before min, the constant first: NaN -> 0
        const int i = std::min(static_cast<int>(f), n - 2);
        return {i, f - i};
    }
    Axis uAxis(double u) const { return axis((u - origin.x()) / spacing, nu); }
    Axis vAxis(double v) const { return axis((v - origin.y()) / spacing, nv); }
    /// The bilinear value in node interval (u.i, v.i).
    double at(const Axis &u, const Axis &v) const {
        const float *r0 = h.data() + static_cast<std::size_t>(v.i) * nu + u.i, *r1 = r0 + nu;
        return (1.0 - v.a) * ((1.0 - u.a) * r0[0] + u.a * r0[1]) + v.a * ((1.0 - u.a) * r1[0] + u.a * r1[1]);
    }

    bool empty() const { return h.empty(); }
    double at(const Eigen::Vector2d &uv) const { return h.empty() ? 0.0 : at(uAxis(uv.x()), vAxis(uv.y())); }
};

struct WallReliefOptions {
    bool enabled = true;
    /// px of the depth image at the wall's depth between nodes, and the Gaussian's sigma: the
    /// sensor's distortion lives in the image (our Kinect v1 model: features of 110 px), so the
    /// relief follows features of a few tens of pixels and no finer (a frame's edge stays out).
    double node_px = 12.0;
    double sigma_px = 20.0;
    double tukey_bands = 1.5;  ///< Tukey biweight width in inlier bands
    int rounds = 3;            ///< reweighting rounds
    /// Nodes with less than this share of the median node weight shrink towards 0 (the
    /// quadratic): where the wall was hardly seen, the relief does not guess.
    double min_weight_share = 0.25;
    int max_nodes = 96;  ///< per side; a larger wall takes wider spacing
};

/// One sample of the wall: its plane coordinates, its height above the quadratic, its inlier
/// band (m) and its depth (m).
struct ReliefSample {
    Eigen::Vector2d uv;
    double r, band, z;
};

/// The relief of `samples` (at least a few hundred for a meaningful result), `focal_px` the
/// depth camera's focal length (px) that turns node_px and sigma_px into metres at the samples'
/// median depth. Empty when disabled or too few samples.
WallRelief fitWallRelief(const std::vector<ReliefSample> &samples, double focal_px, const WallReliefOptions &options);

}  // namespace projsurf
