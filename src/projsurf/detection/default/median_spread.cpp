#include "projsurf/detection/default/median_spread.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {

std::pair<float, float> medianSpread(std::vector<float> &v) {
    if (v.empty()) return {0.0f, 0.0f};
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    const float m = *mid;
    for (float &x : v) x = std::abs(x - m);
    std::nth_element(v.begin(), mid, v.end());
    return {m, 1.4826f * *mid};
}

}  // namespace projsurf
