#include "projsurf/io/pattern_files.hpp"

#include <yaml-cpp/yaml.h>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/limits.hpp"

namespace fs = std::filesystem;

namespace projsurf {

namespace {
constexpr const char *kCoding = "gray_code_inverse";
}

PatternList writePatternSet(const std::string &dir, int width, int height) {
    std::error_code ec;
    fs::create_directories(fs::path(dir) / "patterns", ec);
    if (ec) throw InputError(dir, "cannot create the folder: " + ec.message());
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
        out.addImage((fs::path(dir) / "patterns" / (p.name + ".png")).string(), grayPatternImage(p, width, height));
        root["patterns"]["order"].push_back(p.name);
        list.names.push_back(p.name);
    }
    YAML::Emitter e;
    e << root;
    out.addFile((fs::path(dir) / "patterns.yaml").string(), std::string(e.c_str()) + "\n");
    out.commit();
    return list;
}

PatternList readPatternList(const std::string &path) {
    const std::string text = readSmallTextFile(path, limits::kMaxYamlBytes, "YAML");
    PatternList list;
    try {
        const YAML::Node root = YAML::Load(text);
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
        list.coding = p["coding"] ? p["coding"].as<std::string>() : "";
        if (list.coding != kCoding)
            throw InputError(path, "unknown pattern coding '" + list.coding + "' (this version writes and reads '" +
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

std::vector<PoseCaptures> readPoseCaptures(const std::string &dir, const PatternList &list, int width, int height) {
    std::vector<PoseCaptures> poses;
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    for (int k = 0;; ++k) {
        const fs::path pd = fs::path(dir) / ("pose_" + std::to_string(k));
        std::error_code ec;
        if (!fs::is_directory(pd, ec)) break;
        if (static_cast<std::uint64_t>(k + 1) * list.names.size() * pixels > 8 * limits::kMaxCapturePixels)
            throw InputError(pd.string(), "too many poses: the captures exceed the size limit");
        PoseCaptures pc;
        pc.dir = pd.string();
        const std::string dpath = (pd / "depth.png").string();
        pc.depth = readImage(dpath, cv::IMREAD_UNCHANGED, pixels);
        if (pc.depth.type() != CV_16UC1) throw InputError(dpath, "expected a 16-bit single-channel depth PNG");
        if (pc.depth.cols != width || pc.depth.rows != height)
            throw InputError(dpath, "size differs from camera.yaml (" + size + ")");
        for (const auto &name : list.names) {
            const std::string path = (pd / (name + ".png")).string();
            if (!fs::exists(path, ec))
                throw InputError(
                    path, "missing: capture one colour image per pattern of patterns.yaml, named as the pattern");
            cv::Mat img = readImage(path, cv::IMREAD_GRAYSCALE, pixels);
            if (img.cols != width || img.rows != height)
                throw InputError(path, "size differs from camera.yaml (" + size + ")");
            pc.colour.push_back(img);
        }
        poses.push_back(std::move(pc));
    }
    if (poses.empty()) throw InputError(dir, "no pose_0/ folder with the captures");
    return poses;
}

}  // namespace projsurf
