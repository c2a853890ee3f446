#pragma once
// Why a cell of a wall's raster is not free: the default method sets it (free space, 3.2.2, and
// colour), the overlay paints it and --explain counts it over the projector's beam.
#include <opencv2/core.hpp>

namespace projsurf {

/// Why a cell of the raster is not free (what an overlay shows).
enum class CellState : uchar {
    Free = 0,
    NoReading = 1,    ///< no wall point seen there (missing depth, or off the wall)
    SeenThrough = 2,  ///< points beyond the wall seen through it (a hole, a door, glass)
    InFront = 3,      ///< something between the projector and the wall shadows it
    Edge = 4,         ///< the cell along the edge of the observed wall (its true edge may be a cell in)
    // Free by depth, but unfit by its colour (detection/colour/surface_suitability.hpp): 4 + its Unfit value.
    Glare = 5,      ///< blown out: specular or emissive (glass, a lamp, a screen)
    Dark = 6,       ///< too dark (low albedo)
    Textured = 7,   ///< textured or edgy (a framed picture, a calendar, a busy pattern)
    Saturated = 8,  ///< too saturated a colour
    Proud = 9,      ///< the wall's readings there stand off its shape on average, or step at its border (a frame, a TV)
};

/// How many CellState values there are (one past the largest).
constexpr int kCellStates = static_cast<int>(CellState::Proud) + 1;

}  // namespace projsurf
