// projsurf patterns: write the structured-light patterns (Gray-code columns and rows with their
// inverses, white, black) and patterns.yaml, the order to project them in.
#include <iostream>

#include "cli/commands.hpp"
#include "projsurf/frontend/settings/resolution.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/formats/pattern_files.hpp"

namespace projsurf::cli {
namespace {

struct PatternsOptions {
    std::string out;
    std::string resolution = "1280,800";  // px, Aaxa P300 (paper 3.1.2)
};

void run(const PatternsOptions &o) {
    const cv::Size wh = frontend::parseResolution("--resolution", o.resolution);
    const PatternList list = writePatternSet(o.out, wh.width, wh.height);
    std::cout << "projsurf patterns: " << list.names.size() << " patterns " << list.width << "x" << list.height
              << " -> " << o.out << "/patterns/, order in " << o.out << "/patterns.yaml\n"
              << "  at each robot position k, project them full screen in that order and save the colour capture of "
                 "each as "
              << o.out << "/pose_k/<name>.png, plus one depth.png; add camera.yaml; then projsurf calibrate --captures "
              << o.out << " (see docs/projector.md)\n";
}

}  // namespace

void addPatternsCommand(CLI::App &app) {
    auto opts = std::make_shared<PatternsOptions>();
    auto *sub = app.add_subcommand("patterns", "write the structured-light patterns for projector calibration");
    sub->add_option("--out", opts->out, "folder to write patterns/ and patterns.yaml into")->required();
    sub->add_option("--resolution", opts->resolution, "projector framebuffer width,height, px")->capture_default_str();
    sub->callback([opts] { run(*opts); });
}

}  // namespace projsurf::cli
