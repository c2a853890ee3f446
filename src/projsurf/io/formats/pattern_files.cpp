#include "projsurf/io/formats/pattern_files.hpp"

#include <yaml-cpp/yaml.h>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/calibration/projector_fit.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/utf8_text.hpp"
#include "projsurf/io/yaml/yaml_tree.hpp"

namespace fs = std::filesystem;

namespace projsurf {

namespace {
constexpr const char *kCoding = "gray_code_inverse";
}

PatternList writePatternSet(const std::string &dir, int width, int height) {
    // The folders made here are removed again when the set cannot be written (all or nothing).
    std::error_code ec;
    const fs::path patterns_dir = fs::path(dir) / "patterns";
    const bool had_dir = fs::exists(dir, ec), had_patterns = fs::exists(patterns_dir, ec);
    fs::create_directories(patterns_dir, ec);
    if (ec) throw InputError(dir, "cannot create the folder: " + ec.message());
    try {
        PatternList list;
        list.width = width;
        list.height = height;
        list.coding = kCoding;
        OutputGroup out;
        YAML::Node root;
        root["patterns"]["resolution"].push_back(width);
        root["patterns"]["resolution"].push_back(height);
        root["patterns"]["resolution"].SetStyle(YAML::EmitterStyle::Flow);
        root["patterns"]["coding"] = kCoding;
        for (const auto &p : grayPatterns(width, height)) {
            out.addImage((patterns_dir / (p.name + ".png")).string(), grayPatternImage(p, width, height));
            root["patterns"]["order"].push_back(p.name);
            list.names.push_back(p.name);
        }
        YAML::Emitter e;
        e << root;
        out.addFile((fs::path(dir) / "patterns.yaml").string(), std::string(e.c_str()) + "\n");
        out.commit();
        return list;
    } catch (...) {
        if (!had_patterns) fs::remove(patterns_dir, ec);  // only when empty
        if (!had_dir) fs::remove(dir, ec);
        throw;
    }
}

PatternList readPatternList(const std::string &path) {
    const std::string text = readSmallTextFile(path, limits::kMaxYamlBytes, "YAML");
    PatternList list;
    try {
        const YAML::Node root = loadCheckedYaml(path, text);
        const YAML::Node p = root["patterns"];
        if (!p || !p.IsMap()) throw InputError(path, "missing key 'patterns'");
        const YAML::Node res = p["resolution"];
        if (!res || !res.IsSequence() || res.size() != 2)
            throw InputError(path, "'patterns.resolution' must be [W, H]");
        list.width = res[0].as<int>();
        list.height = res[1].as<int>();
        if (list.width < 2 || list.height < 2 || list.width > limits::kMaxFramebufferSide ||
            list.height > limits::kMaxFramebufferSide)
            throw InputError(path, "'patterns.resolution' out of range");
        if (static_cast<std::uint64_t>(list.width) * list.height > limits::kMaxFramebufferPixels)
            throw InputError(path, "'patterns.resolution' exceeds the framebuffer limit of " +
                                       std::to_string(limits::kMaxFramebufferPixels) + " pixels");
        list.coding = p["coding"] ? p["coding"].as<std::string>() : "";
        if (list.coding != kCoding)
            throw InputError(path, "unknown pattern coding '" + shownText(list.coding) + "' (this version writes and reads '" +
                                       kCoding + "'; run projsurf patterns again)");
        const YAML::Node order = p["order"];
        if (!order || !order.IsSequence()) throw InputError(path, "missing list 'patterns.order'");
        for (const auto &n : order) list.names.push_back(n.as<std::string>());
    } catch (const YAML::Exception &e) {
        throw InputError(path, std::string("malformed YAML: ") + e.what());
    }
    std::vector<std::string> expected;
    for (const auto &p : grayPatterns(list.width, list.height)) expected.push_back(p.name);
    if (list.names != expected)
        throw InputError(path, "'patterns.order' is not the list projsurf patterns writes for " +
                                   std::to_string(list.width) + "x" + std::to_string(list.height));
    return list;
}

std::uint64_t structuredLightBytes(std::uint64_t poses, std::uint64_t pixels, std::uint64_t patterns) {
    const std::uint64_t per_pixel = patterns                                   // the pose's 8-bit captures
                                    + 4                                        // the image being decoded (BGRA)
                                    + 2                                        // its depth
                                    + 2 * sizeof(double) + 1                   // its decoding
                                    + poses * sizeof(ProjectorCorrespondence);  // every pose's lifted points
    return per_pixel * pixels;
}

std::vector<std::string> listPoseFolders(const std::string &dir, const PatternList &list, int width, int height) {
    std::vector<std::string> poses;
    for (std::uint64_t k = 0;; ++k) {
        const fs::path pd = fs::path(dir) / ("pose_" + std::to_string(k));
        std::error_code ec;
        if (!fs::is_directory(pd, ec)) break;
        if (k == limits::kMaxCaptures)
            throw InputError(dir, "more than " + std::to_string(limits::kMaxCaptures) + " pose folders (pose_0.." +
                                      std::to_string(limits::kMaxCaptures - 1) + " are read)");
        poses.push_back(pd.string());
    }
    if (poses.empty())
        throw InputError((fs::path(dir) / "pose_0").string(),
                         "missing: structured light (patterns.yaml) needs pose_0/, pose_1/, ... beside it, each with "
                         "depth.png and one colour image per pattern");
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
    const std::uint64_t bytes = structuredLightBytes(poses.size(), pixels, list.names.size());
    if (bytes > limits::kMaxStructuredLightBytes)
        throw InputError(dir, std::to_string(poses.size()) + " pose(s) of " + std::to_string(list.names.size()) +
                                  " captures of " + std::to_string(width) + "x" + std::to_string(height) +
                                  " pixels need " + std::to_string(bytes >> 20) +
                                  " MiB to decode, beyond the limit of " +
                                  std::to_string(limits::kMaxStructuredLightBytes >> 20) +
                                  " MiB (fewer poses, or a smaller camera image)");
    return poses;
}

PoseCaptures readPoseCaptures(const std::string &pose_dir, const PatternList &list, int width, int height) {
    const fs::path pd(pose_dir);
    PoseCaptures pc;
    pc.dir = pose_dir;
    const std::string dpath = (pd / "depth.png").string();
    pc.depth = readImageOfSize(dpath, cv::IMREAD_UNCHANGED, width, height, "camera.yaml");
    if (pc.depth.type() != CV_16UC1) throw InputError(dpath, "expected a 16-bit single-channel depth PNG");
    std::error_code ec;
    for (const auto &name : list.names) {
        const std::string path = (pd / (name + ".png")).string();
        if (!fs::exists(path, ec))
            throw InputError(path,
                             "missing: capture one colour image per pattern of patterns.yaml, named as the pattern");
        pc.colour.push_back(readImageOfSize(path, cv::IMREAD_GRAYSCALE, width, height, "camera.yaml"));
    }
    return pc;
}

}  // namespace projsurf
