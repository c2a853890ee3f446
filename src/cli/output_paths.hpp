#pragma once
// No output of a command may be one of its inputs: `detect --depth d.png --json d.png` would
// replace the frame by its own detection (and `--calib c.png --overlay c.png` the calibration).
#include <string>
#include <vector>

namespace projsurf::cli {

/// Throws InputError naming the file and both options when an output option's path (--json,
/// --overlay, --out, --write-picture, --write-card) is, after canonical resolution (links,
/// "..", a hard link to the same file), the path of an input option of the same command.
/// `args` are the command line's words (a value after its option or glued with '=').
void refuseOutputOverInput(const std::vector<std::string> &args);

}  // namespace projsurf::cli
