#pragma once
// The smallest picture worth showing: a detection whose rectangle is narrower or smaller than
// this is reported as not found, with the reason, so a robot does not project a stamp-sized
// picture onto the side of a bin. Applied by the front ends (detect, the node, Python) to what
// the detector returns; the evaluation scores the detector itself.
#include <string>

#include "projsurf/detection/detection.hpp"
#include "projsurf/detection/detector_config.hpp"

namespace projsurf::frontend {

struct MinimumSize {
    /// m. Text stays readable from about 1/120 of the viewing distance in letter height
    /// (signage rule of thumb: 25 mm per 3 m): at 1.5 m, where a robot stands to show
    /// something to a person beside it, 12 mm letters, a few words a line in 0.15 m (checked
    /// on the labelled real frames: docs/tuning.md).
    double width = 0.15;
    /// m^2: 0.15 m wide at 16:9 (the widest common aspect) is 0.0127 m^2; a little less.
    double area = 0.012;
};

/// The defaults for `method`: the above for the default method; none (0, 0) for the paper's
/// steps, which reproduce the paper (section 3.2 has no minimum).
MinimumSize defaultMinimumSize(Method method);

/// Why `r` is below `minimum`, as "<subject>, 0.148 x 0.083 m, is narrower than --min-width
/// 0.150 m" (sizes with digits enough to differ from the limit); empty when it is not.
std::string belowMinimum(const Rectangle &r, const MinimumSize &minimum, const std::string &subject,
                         const std::string &width_option, const std::string &area_option);

/// A found detection below `minimum` becomes found = false with a reason that names the size
/// and the option (`width_option`, `area_option`: how this front end spells them). Returns
/// true when it did. Every candidate whose rectangle is below it becomes TooSmall, with the
/// sentence, whether or not the detection was found.
bool enforceMinimumSize(Detection &det, const MinimumSize &minimum, const std::string &width_option,
                        const std::string &area_option);

}  // namespace projsurf::frontend
