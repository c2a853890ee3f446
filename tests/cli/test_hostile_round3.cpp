// Hostile input, round three (issue 39): the settings file, the chessboard mode, the procam
// reader and bags held to the contract of docs/limits.md. Each class of finding has a case
// here that failed before its fix: a refused input gives exit 2, one stderr line
// "projsurf: error: <file>: ..." and no output; a valid but odd one exit 0 and a bounded,
// escaped warning.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <yaml-cpp/yaml.h>

#ifdef PROJSURF_TEST_HAVE_BZIP2
#include <bzlib.h>
#endif

#include "bag_writer.hpp"
#include "cli_run.hpp"
#include "hostile_fixture.hpp"
#include "projsurf/calibration/chessboard_corners.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/utf8_text.hpp"
#include "projsurf/io/formats/procam_captures.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/io/yaml/yaml_settings.hpp"
#include "projsurf/io/yaml/yaml_tree.hpp"

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::test;

namespace {

int lines(const std::string &s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

/// The message of the InputError `f` throws ("" when it throws none).
template <class F>
std::string inputError(F &&f) {
    try {
        f();
    } catch (const InputError &e) {
        return e.what();
    }
    return "";
}

class Hostile3 : public HostileCli {};

}  // namespace

// --- High: YAML alias cycles, depth, duplicates and extra documents, in every reader --------

TEST(YamlTree, CyclesDepthDuplicatesAndDocumentsAreRefusedBeforeAnyWalk) {
    auto problem = [](const std::string &text) { return inputError([&] { loadCheckedYaml("f.yaml", text); }); };
    // The 37 bytes: a mapping holding an alias of itself (SIGSEGV by recursion before).
    EXPECT_NE(problem("planes: &p {max_planes: 4, sub: *p}\n").find("key 'planes.sub' is an alias of a mapping"),
              std::string::npos);
    EXPECT_NE(problem("a: &l [1, *l]\n").find("alias cycle"), std::string::npos);
    // Aliases nest without a cycle: 70 levels, under the text's own nesting check.
    std::string deep = "a0: &a0 {x: 1}\n";
    for (int i = 1; i < 70; ++i)
        deep += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " {x: *a" + std::to_string(i - 1) + "}\n";
    EXPECT_NE(problem(deep).find("nested deeper than 64"), std::string::npos) << problem(deep);
    // Exponentially many nodes from a few aliases (a "billion laughs").
    std::string laughs = "l0: &l0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
    for (int i = 1; i < 9; ++i) {
        laughs += "l" + std::to_string(i) + ": &l" + std::to_string(i) + " [";
        for (int k = 0; k < 10; ++k) laughs += std::string(k ? ", " : "") + "*l" + std::to_string(i - 1);
        laughs += "]\n";
    }
    EXPECT_NE(problem(laughs).find("more than 100000 YAML nodes"), std::string::npos) << problem(laughs);
    EXPECT_NE(problem("a: 1\nb: 2\na: 3\n").find("key 'a' is given twice"), std::string::npos);
    EXPECT_NE(problem("p: {x: 1}\n---\np: {x: 2}\n").find("2 YAML documents"), std::string::npos);
    // A key is shown escaped: a newline cannot start a line of its own.
    const std::string nl = problem("\"a\\nprojsurf: error: forged\": 1\n\"a\\nprojsurf: error: forged\": 2\n");
    EXPECT_EQ(nl.find('\n'), std::string::npos) << nl;
    EXPECT_NE(nl.find("\\x0A"), std::string::npos) << nl;
    // What is fine stays fine: an alias of a sibling, a document marker, an empty file.
    EXPECT_EQ(problem("a: &x {b: 1}\nc: *x\n"), "");
    EXPECT_EQ(problem("---\na: 1\n"), "");
    EXPECT_EQ(problem(""), "");
}

TEST_F(Hostile3, EveryYamlReaderRefusesACycleADuplicateAndASecondDocument) {
    writeBytes(at("cycle.yaml"), "planes: &p {max_planes: 4, sub: *p}\n");
    refused(detectArgs() + " --config " + at("cycle.yaml") + " --json " + at("o.json"), at("cycle.yaml"),
            "alias cycle", {at("o.json")});
    refused("detect --print-config --config " + at("cycle.yaml"), at("cycle.yaml"), "alias cycle");
    refused("plan --calib " + sim("calib.yaml") + " --cloud " + sim("cloud.pcd") + " --config " + at("cycle.yaml"),
            at("cycle.yaml"), "alias cycle");
    // A settings block given twice was merged; a dotted and a nested key, the same key.
    writeBytes(at("twice.yaml"), "planes:\n  max_planes: 4\nplanes:\n  min_plane_points: 50\n");
    refused(detectArgs() + " --config " + at("twice.yaml"), at("twice.yaml"), "key 'planes' is given twice");
    writeBytes(at("second.yaml"), "planes: {max_planes: 4}\n---\nplanes: {max_planes: 5}\n");
    refused(detectArgs() + " --config " + at("second.yaml"), at("second.yaml"), "2 YAML documents");
    // The calibration and the camera: first wins no more.
    const std::string calib = slurp(sim("calib.yaml"));
    writeBytes(at("calib2.yaml"), calib + "projector:\n  resolution: [640, 480]\n");
    refused("detect --calib " + at("calib2.yaml") + " --cloud " + sim("cloud.pcd"), at("calib2.yaml"),
            "key 'projector' is given twice");
    writeBytes(at("cam2.yaml"), slurp(sim("camera.yaml")) + "camera:\n  width: 1\n");
    refused("detect --calib " + sim("calib.yaml") + " --depth " + sim("depth.png") + " --camera " + at("cam2.yaml"),
            at("cam2.yaml"), "key 'camera' is given twice");
    writeBytes(at("calibc.yaml"), "projector: &p {resolution: [1280, 800], x: *p}\n");
    refused("detect --calib " + at("calibc.yaml") + " --cloud " + sim("cloud.pcd"), at("calibc.yaml"), "alias cycle");
}

// --- High: bz2 bombs in a bag ----------------------------------------------------------------

namespace {

/// A bag: the bag header, one stored chunk with connection 0 (`topic`, wanted) and 1 (other),
/// then `chunks` (records given whole), then the connections again where the index is.
std::string bagAround(const std::vector<std::string> &chunks) {
    using namespace bagtest;
    auto conn = [](std::uint32_t id, const std::string &topic) {
        const std::string header = bagFields({{"topic", topic},
                                              {"type", "sensor_msgs/PointCloud2"},
                                              {"md5sum", "1158d486dd51d683ce2f1be655c3c181"},
                                              {"message_definition", "-"}});
        return bagRecord({{"op", "\x07"}, {"conn", u32Bytes(id)}, {"topic", topic}}, header);
    };
    const std::string conns = conn(0, "/points") + conn(1, "/other");
    const std::string first =
        bagRecord({{"op", "\x05"}, {"compression", "none"}, {"size", u32Bytes(static_cast<std::uint32_t>(conns.size()))}},
                  conns);
    std::string body = first;
    for (const auto &c : chunks) body += c;
    auto header = [&](std::uint64_t index_pos) {
        std::string ip;
        putU64(ip, index_pos);
        const BagFields f = {{"op", "\x03"}, {"index_pos", ip}, {"conn_count", u32Bytes(2)},
                             {"chunk_count", u32Bytes(static_cast<std::uint32_t>(chunks.size() + 1))}};
        return bagRecord(f, std::string(4096 - 8 - bagFields(f).size(), ' '));
    };
    const std::string magic = "#ROSBAG V2.0\n";
    return magic + header(magic.size() + header(0).size() + body.size()) + body + conns;
}

std::string bz2Chunk(std::uint32_t raw, const std::string &compressed) {
    using namespace bagtest;
    return bagRecord({{"op", "\x05"}, {"compression", "bz2"}, {"size", u32Bytes(raw)}}, compressed);
}

}  // namespace

TEST_F(Hostile3, BagChunksAreBoundedByTheirCompressedSizeBeforeDecompressing) {
    // The chunk: 574 bytes announcing 512 MiB (within the per-record limit): refused
    // from its header, nothing decompressed.
    writeBytes(at("bomb.bag"), bagAround({bz2Chunk(512u << 20, std::string(574, 'B'))}));
    const auto t0 = std::chrono::steady_clock::now();
    refused("detect --calib " + sim("calib.yaml") + " --bag " + at("bomb.bag") + " --topic /points", at("bomb.bag"),
            "times its size (a decompression bomb?)");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
#ifdef PROJSURF_TEST_HAVE_BZIP2
    // Chunks of 60 MiB of zeros each (a message on another topic), 2 KB compressed: each within
    // the per-chunk allowance, together beyond the bag's 1 GiB at over 100 x.
    std::string time;
    bagtest::putU32(time, 1);
    bagtest::putU32(time, 0);
    std::string chunk = bagtest::bagRecord({{"op", "\x02"}, {"conn", bagtest::u32Bytes(1)}, {"time", time}},
                                                 std::string(60u << 20, '\0'));
    std::string packed(chunk.size() / 100 + 600, '\0');
    unsigned int packed_len = static_cast<unsigned int>(packed.size());
    ASSERT_EQ(BZ2_bzBuffToBuffCompress(packed.data(), &packed_len, chunk.data(),
                                       static_cast<unsigned int>(chunk.size()), 9, 0, 0),
              BZ_OK);
    packed.resize(packed_len);
    const std::string one = bz2Chunk(static_cast<std::uint32_t>(chunk.size()), packed);
    writeBytes(at("many.bag"), bagAround(std::vector<std::string>(40, one)));
    const auto t1 = std::chrono::steady_clock::now();
    refused("detect --calib " + sim("calib.yaml") + " --bag " + at("many.bag") + " --topic /points", at("many.bag"),
            "decompress to more than 1024 MiB");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count(), 30.0);
    // Two such chunks are an odd but valid bag: read to its end, not refused as a bomb.
    writeBytes(at("two.bag"), bagAround({one, one}));
    const CliRun ok = cli("detect --calib " + sim("calib.yaml") + " --bag " + at("two.bag") + " --topic /points", dir_);
    EXPECT_NE(ok.status, -1);
    EXPECT_EQ(ok.err.find("decompression bomb"), std::string::npos) << ok.err;
#endif
}

TEST_F(Hostile3, BagIndexRecordsThatContradictTheChunksAreRefused) {
    using namespace bagtest;
    const std::string good = bagAround({});
    // A chunk info record claiming 5 messages of connection 0 in the first chunk, which has none.
    std::string pos;
    putU64(pos, 13 + 4096);  // the first chunk follows the magic and the header record (4096 bytes)
    std::string start;
    putU64(start, 0);
    const std::string info = bagRecord({{"op", "\x06"}, {"ver", u32Bytes(1)}, {"chunk_pos", pos},
                                        {"start_time", start}, {"end_time", start}, {"count", u32Bytes(1)}},
                                       u32Bytes(0) + u32Bytes(5));
    writeBytes(at("index.bag"), good + info);
    refused("detect --calib " + sim("calib.yaml") + " --bag " + at("index.bag") + " --topic /points",
            at("index.bag"), "contradicts its chunks");
}

// --- High: the chessboard mode's budget, links and noise ------------------------------------

namespace {

/// DIR/capture_0..poses-1 each with the 42 captures of a 1024 x 768 projector, every one a
/// link to one `w` x `h` black PNG (the 33 KB file of 5792 x 5792).
void writeLinkedPoses(const fs::path &dir, int poses, int w, int h) {
    fs::create_directories(dir);
    const fs::path png = dir / "black.png";
    ASSERT_TRUE(cv::imwrite(png.string(), cv::Mat(h, w, CV_8UC1, cv::Scalar(0))));
    for (int k = 0; k < poses; ++k) {
        const fs::path pose = dir / ("capture_" + std::to_string(k));
        fs::create_directories(pose);
        for (int i = 0; i < 42; ++i) {
            char name[32];
            std::snprintf(name, sizeof name, "graycode_%02d.png", i);
            fs::create_symlink(png, pose / name);
        }
    }
}

}  // namespace

TEST_F(Hostile3, ChessboardModeCountsTheDecodingBudgetBeforeReadingACapture) {
    // One pose of 4000 x 4000 black captures: 2.4 GiB to decode (117 s and 3.6 GB at 5792 x 5792).
    writeLinkedPoses(dir_ / "big", 1, 4000, 4000);
    const auto t0 = std::chrono::steady_clock::now();
    refused("calibrate --captures " + at("big") + " --square-m 0.075 --resolution 1024,768 --out " + at("c.yaml"),
            at("big"), "MiB to decode, beyond the limit of 1536 MiB", {at("c.yaml")});
    // 60 poses (links, all to one file) of 1280 x 1024: each fits, together beyond the captures' bound.
    writeLinkedPoses(dir_ / "many", 60, 1280, 1024);
    refused("calibrate --captures " + at("many") + " --square-m 0.075 --resolution 1024,768 --out " + at("c.yaml"),
            at("many"), "MiB of captures to decode", {at("c.yaml")});
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 20.0);
    // A capture of another size than the first is refused from its header.
    writeLinkedPoses(dir_ / "mixed", 2, 64, 48);
    const fs::path odd = dir_ / "mixed" / "capture_1" / "graycode_05.png";
    fs::remove(odd);
    ASSERT_TRUE(cv::imwrite(odd.string(), cv::Mat(4000, 4000, CV_8UC1, cv::Scalar(0))));
    refused("calibrate --captures " + at("mixed") + " --square-m 0.075 --resolution 1024,768 --out " + at("c.yaml"),
            odd.string(), "is 4000x4000, the first capture says 64x48", {at("c.yaml")});
}

TEST(ChessboardSearch, NoiseIsAnsweredAfterOneSearchAndABoardIsStillFound) {
    cv::Mat noise(1024, 1280, CV_8UC1);
    cv::RNG(39).fill(noise, cv::RNG::UNIFORM, 0, 256);
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_FALSE(findChessboard(noise).found);
    const double noise_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(noise_s, 1.0) << "every board size was searched (13 s on this image before)";
    // A 7 x 5-square board (6 x 4 inner corners) is found with its size.
    cv::Mat board(480, 640, CV_8UC1, cv::Scalar(255));
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 7; ++i)
            if ((i + j) % 2 == 0) board(cv::Rect(100 + 50 * i, 100 + 50 * j, 50, 50)).setTo(0);
    const ChessboardCorners c = findChessboard(board);
    ASSERT_TRUE(c.found);
    EXPECT_EQ(c.inner, cv::Size(6, 4));
}

// --- Medium: nothing written that a reader refuses, nor a non-finite number ------------------

TEST(CalibrationWriters, AFitNoReaderAcceptsIsRefusedWithTheReadersReason) {
    const fs::path dir = freshDir("calib_writers");
    Projector p;
    p.width = 1280;
    p.height = 800;
    p.fov_h = 0.7;
    p.fov_v = 0.45;
    p.origin = Eigen::Vector3d(0, 0, 9.99);  // chessboard calibrate with --square-m 9.99
    p.direction = Eigen::Vector3d(0, 0, 1);
    const std::string out = (dir / "c.yaml").string();
    const std::string e = inputError([&] { writeCalibration(out, p); });
    EXPECT_NE(e.find("not written"), std::string::npos) << e;
    EXPECT_NE(e.find("more than 3 m"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(out));
    // A distortion k3 of 18.9 on the full model, and a NaN in the report.
    YAML::Node root;
    p.origin = Eigen::Vector3d::Zero();
    root["projector"] = calibrationNode(p);
    for (double k : {0.0, 0.0, 0.0, 0.0, 18.9}) root["projector"]["distortion"].push_back(k);
    EXPECT_NE(inputError([&] { calibrationYamlText(out, root); }).find("beyond +-10"), std::string::npos);
    root["projector"].remove("distortion");
    root["projector"]["residuals"]["reprojection_rms_px"] = std::nan("");
    EXPECT_NE(inputError([&] { calibrationYamlText(out, root); }).find("residuals.reprojection_rms_px"),
              std::string::npos);
    root["projector"]["residuals"]["reprojection_rms_px"] = 0.5;
    root["projector"]["captures"]["dir"] = "nan";  // a folder's name is text
    EXPECT_EQ(inputError([&] { calibrationYamlText(out, root); }), "");
    fs::remove_all(dir);
}

TEST_F(Hostile3, ProcamXmlWithZeroOrNonFiniteNumbersIsRefused) {
    // The real excerpt's pose, three times, beside a published XML that eval must not divide by.
    fs::create_directories(dir_ / "procam");
    for (int k = 0; k < 3; ++k)
        fs::create_directory_symlink(PROJSURF_PROCAM_EXCERPT_DIR,
                                     dir_ / "procam" / ("capture_" + std::to_string(k)));
    auto xml = [](const std::string &fx, const std::string &t) {
        return "<?xml version=\"1.0\"?>\n<opencv_storage>\n"
               "<cam_int type_id=\"opencv-matrix\"><rows>3</rows><cols>3</cols><dt>d</dt><data>1000 0 640 0 1000 512 0 0 1</data></cam_int>\n"
               "<cam_dist type_id=\"opencv-matrix\"><rows>1</rows><cols>5</cols><dt>d</dt><data>0 0 0 0 0</data></cam_dist>\n"
               "<proj_int type_id=\"opencv-matrix\"><rows>3</rows><cols>3</cols><dt>d</dt><data>" + fx +
               " 0 512 0 1500 384 0 0 1</data></proj_int>\n"
               "<proj_dist type_id=\"opencv-matrix\"><rows>1</rows><cols>5</cols><dt>d</dt><data>0 0 0 0 0</data></proj_dist>\n"
               "<rotation type_id=\"opencv-matrix\"><rows>3</rows><cols>3</cols><dt>d</dt><data>1 0 0 0 1 0 0 0 1</data></rotation>\n"
               "<translation type_id=\"opencv-matrix\"><rows>3</rows><cols>1</cols><dt>d</dt><data>" + t +
               "</data></translation>\n</opencv_storage>\n";
    };
    fs::create_directories(dir_ / "procam");
    const std::string path = at("procam/calibration_result.xml");
    writeBytes(path, xml("0", "100 0 0"));
    refused("eval --no-progress --procam " + at("procam") + " --json " + at("e.json"), path, "'proj_int' focal",
            {at("e.json")});
    writeBytes(path, xml("1500", "0 0 0"));
    refused("eval --no-progress --procam " + at("procam") + " --json " + at("e.json"), path, "'translation'",
            {at("e.json")});
    writeBytes(path, xml(".Nan", "100 0 0"));
    refused("eval --no-progress --procam " + at("procam") + " --json " + at("e.json"), path, "'proj_int'",
            {at("e.json")});
    // --published without --procam was ignored (a full eval ran).
    const CliRun r = cli("eval --out " + at("e") + " --published " + path, dir_);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--procam"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(at("e")));
}

TEST_F(Hostile3, SettingsValuesAreBoundedAndTheErrorNamesTheFileAndTheKey) {
    // Inside the documented "> 0" before, they ended in an OpenCV assertion naming the frame.
    for (const char *line : {"wall.shape.relief.node_px: 1e-300", "wall.shape.relief.sigma_px: 1e300",
                             "tolerance.noise_k: 1e300", "free_space.proud.window: 1e300",
                             "objects.surround.offsets: [1e-300]"}) {
        writeBytes(at("s.yaml"), std::string(line) + "\n");
        const std::string key = std::string(line).substr(0, std::string(line).find(':'));
        refused(detectArgs() + " --config " + at("s.yaml"), at("s.yaml"), "key '" + key + "': must be");
    }
    writeBytes(at("s.yaml"), "wall.shape.relief.node_px: 1\nwall.shape.relief.sigma_px: 1000\n");
    refused(detectArgs() + " --config " + at("s.yaml"), at("s.yaml"), "must not exceed 10 x");
    // The extremes that are accepted run to an answer.
    writeBytes(at("s.yaml"), "wall.shape.relief.node_px: 1\nwall.shape.relief.sigma_px: 10\n"
                             "wall.shape.relief.max_nodes: 1024\ntolerance.min_band: 10\ntolerance.max_band: 10\n");
    const CliRun r = cli(detectArgs() + " --config " + at("s.yaml"), dir_);
    EXPECT_EQ(r.status, 0) << r.err;
}

// --- Low: warnings stay one escaped line each, and few --------------------------------------

TEST_F(Hostile3, UnknownKeyWarningsAreEscapedAndBounded) {
    const std::string calib = slurp(sim("calib.yaml"));
    // A misspelt key with a Latin-1 byte: the warning was not UTF-8 (Python raised UnicodeDecodeError).
    writeBytes(at("latin.yaml"), calib + "  distorsi\xf3n: [0, 0, 0, 0, 0]\n");
    CliRun r = cli("detect --calib " + at("latin.yaml") + " --cloud " + sim("cloud.pcd"), dir_);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(isUtf8(r.err)) << r.err;
    EXPECT_NE(r.err.find("distorsi\\xF3n"), std::string::npos) << r.err;
    // A key holding a newline forged a "projsurf: error:" line with exit 0.
    writeBytes(at("nl.yaml"), calib + "  \"x\\nprojsurf: error: forged\": 1\n");
    r = cli("detect --calib " + at("nl.yaml") + " --cloud " + sim("cloud.pcd"), dir_);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_EQ(r.err.find("\nprojsurf: error"), std::string::npos) << r.err;
    // 1000 unknown keys: 1000 lines (227 KB) before; now one line naming three, "and 997 more".
    std::string many = calib;
    for (int i = 0; i < 1000; ++i) many += "  bogus_" + std::to_string(i) + ": 1\n";
    writeBytes(at("many.yaml"), many);
    r = cli("detect --calib " + at("many.yaml") + " --cloud " + sim("cloud.pcd"), dir_);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("unknown keys 'projector.bogus_0', 'projector.bogus_1', 'projector.bogus_2' and 997 more"),
              std::string::npos)
        << r.err;
    EXPECT_LT(r.err.size(), 1000u);
}

// --- Low: no output over an input; no stale captures; bounded simulation ------------------

TEST_F(Hostile3, AnOutputThatIsAnInputIsRefusedAndTheInputSurvives) {
    fs::copy_file(sim("depth.png"), at("d.png"));
    fs::copy_file(sim("calib.yaml"), at("c.yaml"));
    const std::string depth = slurp(at("d.png")), calib = slurp(at("c.yaml"));
    refused("detect --calib " + sim("calib.yaml") + " --camera " + sim("camera.yaml") + " --depth " + at("d.png") +
                " --json " + at("d.png"),
            at("d.png"), "--json is the file given as --depth");
    refused("detect --calib=" + at("c.yaml") + " --cloud " + sim("cloud.pcd") + " --overlay " + at("c.yaml"),
            at("c.yaml"), "--overlay is the file given as --calib");
    // Through a link and a hard link too.
    fs::create_symlink(at("d.png"), at("link.png"));
    fs::create_hard_link(at("c.yaml"), at("hard.yaml"));
    refused("detect --calib " + sim("calib.yaml") + " --camera " + sim("camera.yaml") + " --depth " + at("d.png") +
                " --overlay " + at("link.png"),
            at("link.png"), "--overlay is the file given as --depth");
    refused("detect --calib " + at("c.yaml") + " --cloud " + sim("cloud.pcd") + " --json " + at("hard.yaml"),
            at("hard.yaml"), "--json is the file given as --calib");
    EXPECT_EQ(slurp(at("d.png")), depth);
    EXPECT_EQ(slurp(at("c.yaml")), calib);
}

TEST_F(Hostile3, SimulateRefusesAUsedCaptureFolderAndAHugeStructuredLightFramebuffer) {
    fs::create_directories(dir_ / "out" / "structured" / "pose_7");
    refused("simulate --structured-light --out " + at("out"), at("out/structured"), "exists and is not empty");
    EXPECT_TRUE(fs::exists(dir_ / "out" / "structured" / "pose_7"));
    fs::create_directories(dir_ / "out" / "captures");
    writeBytes(dir_ / "out" / "captures" / "capture_9_rgb.png", "x");
    refused("simulate --captures 3 --out " + at("out"), at("out/captures"), "exists and is not empty");
    // A 16384 x 2048 framebuffer (valid) took 40-54 s: refused at once.
    writeBytes(at("wide.yaml"), "projector:\n  resolution: [16384, 2048]\n  fov_deg: [60, 8.26]\n  axis:\n"
                                "    origin: [0, 0, 0]\n    direction: [0, 0, 1]\n");
    const auto t0 = std::chrono::steady_clock::now();
    refused("simulate --structured-light --calib " + at("wide.yaml") + " --out " + at("w"), at("wide.yaml"),
            "at most 8388608 pixels");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
}
