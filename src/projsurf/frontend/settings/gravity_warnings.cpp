#include "projsurf/frontend/settings/gravity_warnings.hpp"

#include "projsurf/frontend/settings/gravity_sanity.hpp"

namespace projsurf::frontend {

std::vector<std::string> gravityUsedWarnings(const GravityWords &words, const GravityUsed &used, const Cloud &cloud,
                                             bool check_floor) {
    std::vector<std::string> out;
    if (used.choice.from_floor && !used.resolved.floor_found)
        out.push_back(words.how_auto + " found no floor; assuming a level camera");
    else if (check_floor && used.level_assumed)
        if (const auto w = levelCameraWarning(words.how_auto, cloud)) out.push_back(*w);
    if (check_floor && !used.level_assumed && !used.choice.from_floor)
        for (const std::string &w : gravityWarnings(words.option, used.choice.gravity, cloud)) out.push_back(w);
    return out;
}

}  // namespace projsurf::frontend
