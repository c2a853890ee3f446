#pragma once
// The median of a set of values and their robust spread (1.4826 times the median absolute
// deviation: the standard deviation of Gaussian values, unmoved by a minority of outliers).
#include <utility>
#include <vector>

namespace projsurf {

/// {median, 1.4826 MAD} of `v` (reordered); {0, 0} when empty.
std::pair<float, float> medianSpread(std::vector<float> &v);

}  // namespace projsurf
