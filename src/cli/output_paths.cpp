#include "cli/output_paths.hpp"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "projsurf/io/files/errors.hpp"

namespace fs = std::filesystem;

namespace projsurf::cli {
namespace {

// Options that name a file or folder read, and ones that name a file or folder written.
// (`simulate --captures N` is a count: never a path, and never equal to a written path's.)
const std::vector<std::string> kInputs = {"--cloud",  "--depth",   "--camera",    "--bag",       "--rgb",
                                          "--calib",  "--config",  "--detection", "--image",     "--video",
                                          "--framebuffer", "--published", "--picture", "--depth-dir",
                                          "--captures", "--procam", "--real-dir", "--labels"};
const std::vector<std::string> kOutputs = {"--json", "--overlay", "--out", "--write-picture", "--write-card"};

/// (option, value) of every option in `names` on the command line.
std::vector<std::pair<std::string, std::string>> valuesOf(const std::vector<std::string> &args,
                                                          const std::vector<std::string> &names) {
    std::vector<std::pair<std::string, std::string>> out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string &a = args[i];
        const std::size_t eq = a.find('=');
        const std::string name = a.substr(0, eq);
        if (std::find(names.begin(), names.end(), name) == names.end()) continue;
        const std::string value = eq != std::string::npos ? a.substr(eq + 1) : i + 1 < args.size() ? args[i + 1] : "";
        const bool count = name == "--captures" && !value.empty() &&
                           std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (!count) out.emplace_back(name, value);
    }
    return out;
}

bool samePath(const std::string &a, const std::string &b) {
    if (a.empty() || b.empty()) return false;
    std::error_code ec1, ec2;
    if (fs::exists(a, ec1) && fs::exists(b, ec2)) {
        std::error_code ec;
        if (fs::equivalent(a, b, ec) && !ec) return true;  // a link, "..", a hard link
    }
    const fs::path ca = fs::weakly_canonical(a, ec1), cb = fs::weakly_canonical(b, ec2);
    return !ec1 && !ec2 && ca == cb;
}

}  // namespace

void refuseOutputOverInput(const std::vector<std::string> &args) {
    const auto inputs = valuesOf(args, kInputs);
    for (const auto &[out_name, out_path] : valuesOf(args, kOutputs))
        for (const auto &[in_name, in_path] : inputs)
            if (samePath(out_path, in_path))
                throw InputError(out_path, out_name + " is the file given as " + in_name +
                                               ": an output may not replace an input (write it elsewhere)");
}

}  // namespace projsurf::cli
