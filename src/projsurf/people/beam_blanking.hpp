#pragma once
// Blanking what stands in the beam (contract "Blanking"): the framebuffer pixels whose ray
// meets something between the lens and the detected surface, from the current cloud.
//
// A cloud point P (camera frame, m) obstructs when it lies on the camera side of the plane,
// nearer the lens than the plane along the ray lens -> P by more than `min_gap`; every
// framebuffer pixel whose ray passes within `ray_margin` of such a point is blanked.
//
// Sensor noise is not an obstruction. Depth cameras bend a flat wall smoothly by centimetres
// (Kinect v1: +-3-5 cm at 3 m, fixed per unit, detection/default/wall_shape.hpp) in patches far larger
// than an arm, so the gap must also exceed `noise_sigmas` times the wall's depth noise
// measured on this cloud (sigma = k z^2, k from the median |distance| / z^2 of the points
// near the plane, as a robust sigma); with a clean sensor the contract's 5 cm rules.
// The obstructing points are binned into a coarse grid over the framebuffer (cells about one
// depth-camera pixel across), and only connected groups survive (a 3x3 closing then a 3x3
// opening of the grid: an isolated reading, or two, never fill a 3x3 block; an arm a few cm
// wide fills many). Each surviving cell is then dilated by the margin at its nearest point's
// depth (a chamfer distance with offsets, so every cell gets its own radius in one linear
// pass), rounded up to whole cells.
#include <array>
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

struct BlankingOptions {
    double min_gap = 0.05;     ///< m, nearer the lens than the plane by more than this (contract)
    double ray_margin = 0.03;  ///< m, within this of the ray (contract)
    /// rad, side of a grid cell seen from the lens, at least: a little more than one pixel of
    /// a VGA depth camera (Kinect v1 fx 525 px: 1.9 mrad), so a surface leaves no empty cells.
    double cell_angle = 0.0025;
    /// Organized clouds: cells are at least this many of the cloud's own pixels across
    /// (measured on the cloud: a 320x240 cloud gets cells twice as wide).
    double cell_per_pixel = 1.3;
    /// m along the projector axis: nearer points are the robot itself (RGB-D cameras read
    /// from about 0.3-0.5 m).
    double min_depth = 0.3;
    bool filter_noise = true;  ///< keep connected groups only (false: every obstructing point counts)
    /// The gap must exceed this many sigmas of the wall noise measured on the cloud (0: the
    /// contract's min_gap alone). Kinect v1 units in the simulator bend a wall by up to 4.7
    /// sigma in patches the opening does not remove (sim/kinect1_model, 2-3.5 m, measured).
    double noise_sigmas = 4.5;
    /// m, points this near the plane measure the noise (a person further out does not).
    double noise_window = 0.3;
};

/// Computes the mask frame after frame; its buffers are reused (one object per thread).
class BeamBlanker {
public:
    explicit BeamBlanker(const Projector &projector, const BlankingOptions &options = {});

    /// The mask for this cloud and the detected plane (normal towards the camera, as
    /// types/plane.hpp): CV_8U, framebuffer size, 255 = blanked. A plane the lens is not in
    /// front of blanks nothing. The returned reference stays valid until the next call.
    const cv::Mat &compute(const Cloud &cloud, const Plane &plane);

    /// Blanked pixels of the last mask.
    int blankedPixels() const { return blanked_; }
    /// Obstructing points of the last cloud, before the grid's noise filter (diagnostics).
    int candidatePoints() const { return candidates_; }
    /// The wall's depth noise measured on the last cloud: sigma_z / z^2, 1/m (0 = too few points).
    double noiseK() const { return noise_k_; }
    int cellPx() const { return cell_; }
    const BlankingOptions &options() const { return options_; }

private:
    /// Grid geometry for cells of `cell_px` framebuffer pixels.
    void configure(int cell_px);
    // The steps of compute, in order.
    void fitCellToCloud(const Cloud &cloud);                        ///< cells as wide as the cloud's pixels allow
    float lensSide(const Plane &plane) const;                       ///< m, signed distance of the lens from the plane
    void measureWallNoise(const Cloud &cloud, const Plane &plane);  ///< noise_k_
    float smallestCosine(const Plane &plane) const;  ///< between the plane's normal and the padded grid's rays
    void binObstructions(const Cloud &cloud, const Plane &plane, float lens_side);  ///< hit_, nearest_
    void keepConnectedCells();                                                      ///< kept_: hit_ without lone cells
    bool growByMargins();  ///< grown_; false when no cell was kept
    void writeMask();      ///< mask_ and blanked_ from grown_
    const cv::Mat &blankNothing();

    Projector projector_;
    BlankingOptions options_;
    int cell_ = 4;           ///< framebuffer px per grid cell
    int pad_ = 0;            ///< cells of grid beyond each framebuffer edge
    double off_axis_ = 1.0;  ///< 1 / cos of the widest angle from the axis the grid covers
    int grid_w_ = 0, grid_h_ = 0;
    cv::Mat hit_, kept_, nearest_, near3_, scratch_, distance_, grown_, mask_;
    std::vector<int> histogram_;
    std::vector<uchar> row_;
    int blanked_ = 0;
    int candidates_ = 0;
    double noise_k_ = 0.0;
};

/// Sets the framebuffer's pixels to black where `mask` (CV_8U, same size) is non-zero.
void applyBlanking(cv::Mat &framebuffer, const cv::Mat &mask);

}  // namespace projsurf
