#pragma once
// Where on a plane the camera saw free wall (the default method's 3.2.2): a cell is free when
// wall points were seen in it (gaps between samples closed), nothing was seen through it, and
// no point in front of the wall shadows it from the projector.
#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>

#include "projsurf/detection/cell_state.hpp"
#include "projsurf/detection/default/plane_observation.hpp"
#include "projsurf/detection/detector_config.hpp"
#include "projsurf/detection/raster_frame.hpp"

namespace projsurf {

struct SurfaceCells {
    cv::Mat free;   ///< CV_8U, 255 = free surface (the footprint not applied)
    cv::Mat state;  ///< CV_8U, a CellState per cell
};

/// Free surface from an observation: support closed over gaps up to `gap_cells` cells;
/// blocked where more points were seen through than on the wall, or shadowed, ignoring blocked
/// cells with fewer than `min_blocked_neighbours` blocked cells in their 3x3 (sensor noise);
/// blocked also where the readings' mean offset from the wall's shape over a window stands out
/// (`proud`, `cell` the raster's cell in m) and where they step along a line (`steps`, a
/// frame's border: step_edges); one cell trimmed off every edge so the picture never hangs
/// over the wall's true edge.
SurfaceCells observedFreeSurface(const PlaneObservation &observation, int gap_cells, int min_blocked_neighbours,
                                 const ProudEvidence &proud = {}, double cell = 0.01, const StepEvidence &steps = {});

/// The cells (255) whose window of readings stands off the wall's shape on average by more
/// than the spread of such means over the wall allows (ProudEvidence); empty when the
/// observation has no offsets.
cv::Mat proudCells(const PlaneObservation &observation, const ProudEvidence &proud, double cell);

}  // namespace projsurf
