#pragma once
// What every front end says about the gravity a cloud was detected with, in the same
// sentences: `auto` that found no floor, a level camera assumed that the floor contradicts
// (gravity_sanity.hpp's levelCameraWarning), a vector given that looks like a mistake
// (gravityWarnings). Each front end names its setting as its users write it.
#include <string>
#include <vector>

#include "projsurf/frontend/settings/gravity_choice.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf::frontend {

/// The setting as a front end's users write it.
struct GravityWords {
    std::string option;    ///< "--gravity", "gravity", "~gravity"
    std::string how_auto;  ///< its `auto`: "--gravity auto", "gravity='auto'", "~gravity auto"
};

/// How the gravity of one cloud was chosen, and what came of it.
struct GravityUsed {
    GravityChoice choice;       ///< as the user gave it (or the level camera's)
    bool level_assumed = false;  ///< no gravity was given: a level camera, checked against the floor
    ResolvedGravity resolved;   ///< what the detector was given (detect_answer.hpp's GravityDetection)
};

/// Warning texts (without "projsurf: warning: "): `auto` that found no floor, at once; with
/// `check_floor` (a floor search of its own: a stream checks its first cloud, the camera's
/// mount does not change), a level camera assumed that the floor says is tilted, or a vector
/// given that points along the optical axis or puts the floor above the camera.
std::vector<std::string> gravityUsedWarnings(const GravityWords &words, const GravityUsed &used, const Cloud &cloud,
                                             bool check_floor = true);

}  // namespace projsurf::frontend
