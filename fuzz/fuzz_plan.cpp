// libFuzzer harness: plan's inputs. The input is a point cloud (PCD), read as plan reads it and
// given to the same calls (today's detection, then the stance search) with the example
// projector and a level camera; the plan's JSON is written out as the CLI writes it. Clouds
// beyond 20,000 points are skipped: the readers' limits have their own harnesses, and the
// search's time per input is what makes a useful number of inputs per minute.
#include "fuzz_common.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/answer/detect_answer.hpp"
#include "projsurf/frontend/answer/plan_json.hpp"
#include "projsurf/frontend/settings/minimum_size.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/planning/stand_planner.hpp"

namespace {

const projsurf::Projector &exampleProjector() {
    static const projsurf::Projector p = [] {
        const char yaml[] =
            "projector:\n  resolution: [1280, 800]\n  fov_deg: [39.3, 24.0]\n  axis:\n"
            "    origin: [0, 0.12, 0]\n    direction: [0, -0.05, 0.9987]\n";
        const std::string path =
            projsurf::fuzz::writeInput("calib.yaml", reinterpret_cast<const std::uint8_t *>(yaml), sizeof yaml - 1);
        return projsurf::readCalibration(path);
    }();
    return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    const Projector &projector = exampleProjector();
    const std::string path = fuzz::writeInput("cloud.pcd", data, size);
    fuzz::expectOnlyInputErrors([&] {
        const Cloud cloud = readCloud(path);
        if (cloud.size() > 20000) return;
        DetectorConfig cfg;
        const Eigen::Vector3d down = SurfaceDetector::levelGravity();
        SurfaceDetector detector(projector, cfg);
        const Detection today =
            frontend::detectAnswer(detector, cloud, down, frontend::defaultMinimumSize(cfg.method), path);
        const PlanResult r = planStand(cloud, projector, cfg, down, PlanOptions{}, today);
        (void)frontend::planToJson(r).dump(2);
    });
    return 0;
}
