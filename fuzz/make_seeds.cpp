// Seeds for the fuzzers, made at run time from the simulator's output (`projsurf simulate
// --captures 3` and `projsurf detect --json`): every reader gets small valid files of each
// variant it reads, so that the fuzzers start from inside the formats.
// usage: projsurf_fuzz_seeds SIM_DIR DETECTION_JSON CORPUS_DIR
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "../tests/support/bag_writer.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/cloud_io.hpp"

namespace fs = std::filesystem;
using namespace projsurf;

namespace {

void put(const fs::path &dir, const std::string &name, const std::string &bytes) {
    fs::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary) << bytes;
}

std::string slurp(const fs::path &p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string png(const cv::Mat &m) {
    std::vector<uchar> buf;
    cv::imencode(".png", m, buf);
    return std::string(buf.begin(), buf.end());
}

}  // namespace

int main(int argc, char **argv) {
    if (argc != 4) {
        std::cerr << "usage: projsurf_fuzz_seeds SIM_DIR DETECTION_JSON CORPUS_DIR\n";
        return 2;
    }
    const fs::path sim = argv[1], out = argv[3];
    // A 32 x 24 organized cloud: every 20th pixel of the simulated frame.
    const Cloud full = readCloud((sim / "cloud.pcd").string());
    Cloud small;
    small.width = 32;
    small.height = 24;
    for (int r = 0; r < 24; ++r)
        for (int c = 0; c < 32; ++c)
            small.points.push_back(full.points[static_cast<std::size_t>(r * 20) * full.width + c * 20]);
    Cloud flat = small;
    flat.width = static_cast<int>(flat.points.size());
    flat.height = 1;

    writeCloudPcd((out / "pcd" / "binary.pcd").string(), (fs::create_directories(out / "pcd"), small));
    pcl::PointCloud<pcl::PointXYZ> pc(32, 24);
    for (std::size_t i = 0; i < small.points.size(); ++i)
        pc.points[i] = pcl::PointXYZ(small.points[i].x(), small.points[i].y(), small.points[i].z());
    pc.is_dense = false;
    pcl::io::savePCDFileASCII((out / "pcd" / "ascii.pcd").string(), pc);
    pcl::io::savePCDFileBinaryCompressed((out / "pcd" / "compressed.pcd").string(), pc);

    fs::create_directories(out / "ply");
    writeCloudPly((out / "ply" / "binary.ply").string(), flat);
    std::ostringstream ply;
    std::size_t finite = 0;
    for (const Point &p : flat.points) finite += isFinite(p);
    ply << "ply\nformat ascii 1.0\nelement vertex " << finite
        << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "element face 0\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Point &p : flat.points)
        if (isFinite(p)) ply << p.x() << " " << p.y() << " " << p.z() << "\n";
    put(out / "ply", "ascii.ply", ply.str());

    cv::Mat depth = cv::imread((sim / "depth.png").string(), cv::IMREAD_UNCHANGED), d64;
    cv::resize(depth, d64, {64, 48}, 0, 0, cv::INTER_NEAREST);
    put(out / "depth_png", "depth.png", png(d64));

    put(out / "camera_yaml", "camera.yaml", slurp(sim / "camera.yaml"));
    put(out / "calib_yaml", "calib.yaml", slurp(sim / "calib.yaml"));
    put(out / "detection_json", "det.json", slurp(argv[2]));
    // The layout of procam-calibration's calibration_result.xml (OpenCV FileStorage).
    const auto matrix = [](const char *name, int rows, int cols, const char *data) {
        return std::string("<") + name + " type_id=\"opencv-matrix\"><rows>" + std::to_string(rows) + "</rows><cols>" +
               std::to_string(cols) + "</cols><dt>d</dt><data>" + data + "</data></" + name + ">\n";
    };
    put(out / "procam_xml", "calibration_result.xml",
        "<?xml version=\"1.0\"?>\n<opencv_storage>\n<img_shape>1280 1024</img_shape>\n<rms>0.5</rms>\n" +
            matrix("cam_int", 3, 3, "1000. 0. 640. 0. 1000. 512. 0. 0. 1.") +
            matrix("cam_dist", 1, 5, "0. 0. 0. 0. 0.") +
            matrix("proj_int", 3, 3, "1500. 0. 512. 0. 1500. 384. 0. 0. 1.") +
            matrix("proj_dist", 1, 5, "0. 0. 0. 0. 0.") + matrix("rotation", 3, 3, "1. 0. 0. 0. 1. 0. 0. 0. 1.") +
            matrix("translation", 3, 1, "0.1 0. 0.") + "</opencv_storage>\n");
    put(out / "bag", "two_clouds.bag", bagtest::bagWithClouds({small, flat}, "/points"));

    for (int k = 0; k < 3; ++k) {
        for (const char *kind : {"rgb", "depth"}) {
            const std::string name = "capture_" + std::to_string(k) + "_" + kind + ".png";
            cv::Mat img = cv::imread((sim / "captures" / name).string(), cv::IMREAD_UNCHANGED), i64;
            cv::resize(img, i64, {64, 48}, 0, 0, kind[0] == 'd' ? cv::INTER_NEAREST : cv::INTER_AREA);
            put(out / "captures", name, std::string(1, kind[0] == 'd' ? '\1' : '\0') + png(i64));
        }
    }
    std::cout << "seeds in " << out.string() << "\n";
    return 0;
}
