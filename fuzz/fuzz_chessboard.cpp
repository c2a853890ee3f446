// libFuzzer harness: a chessboard capture folder (calibrate --captures in chessboard mode,
// eval --procam), read and calibrated as those do: the folder listing with its budget, each
// pose's captures, the decoding, the board search, the corners carried into the projector, the
// stereo fit, and the calibration written and read back. A valid folder is made once: a 64 x 32
// framebuffer's 24 Gray-code captures (OpenCV's order) seen by a 160 x 120 camera, three poses
// of a 6 x 5-square board under the white pattern. The input replaces one of its files: the
// first byte says which (pose k's graycode_NN.png, k-major), the second whether the file is
// replaced (0), or becomes a link to pose 0's same capture (1: links count as poses), the rest
// is the file. PROJSURF_FUZZ_WRITE_SEEDS=DIR writes seeds there: the valid files, a PNG header
// announcing 5792 x 5792 (the 1.5 GiB budget), a noise capture under the white pattern.
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "fuzz_common.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/calibration/stereo_fit.hpp"
#include "projsurf/frontend/inputs/chessboard_calibration.hpp"
#include "projsurf/io/formats/procam_captures.hpp"
#include "projsurf/io/reports/chessboard_report.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace fs = std::filesystem;

namespace {

constexpr int kFbW = 64, kFbH = 32, kCamW = 160, kCamH = 120, kPoses = 3;

struct ValidFolder {
    std::vector<std::string> names;  ///< relative paths, in the order the first byte selects
    std::vector<std::string> bytes;  ///< their valid contents
};

std::string encodePng(const cv::Mat &m) {
    std::vector<uchar> buf;
    cv::imencode(".png", m, buf);
    return std::string(buf.begin(), buf.end());
}

/// 1 on the board's white squares and off the board, 0.1 on its black squares (pose k shifts it).
/// (At 160 px the corners' 3 x 3 patches keep too few lit pixels to be carried: the valid
/// folder reaches the decoding, the board search and the carrying; the fit is reached by inputs.)
cv::Mat boardReflectance(int k) {
    cv::Mat r(kCamH, kCamW, CV_32F, cv::Scalar(1.0f));
    const int square = 14, x0 = 30 + 6 * k, y0 = 20 + 4 * k;
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 6; ++i)
            if ((i + j) % 2 == 0) r(cv::Rect(x0 + i * square, y0 + j * square, square, square)).setTo(0.1f);
    return r;
}

const ValidFolder &validFolder() {
    static const ValidFolder v = [] {
        ValidFolder f;
        const auto order = projsurf::openCvGrayPatterns(kFbW, kFbH);
        for (int k = 0; k < kPoses; ++k) {
            const cv::Mat reflect = boardReflectance(k);
            for (std::size_t i = 0; i < order.size(); ++i) {
                cv::Mat seen;
                cv::resize(projsurf::grayPatternImage(order[i], kFbW, kFbH), seen, {kCamW, kCamH}, 0, 0,
                           cv::INTER_NEAREST);
                seen.convertTo(seen, CV_32F);
                seen = seen.mul(reflect) * 0.9 + 10.0;
                seen.convertTo(seen, CV_8U);
                f.names.push_back("capture_" + std::to_string(k) + "/graycode_" + (i < 10 ? "0" : "") +
                                  std::to_string(i) + ".png");
                f.bytes.push_back(encodePng(seen));
            }
        }
        return f;
    }();
    return v;
}

std::vector<std::string> seeds() {
    const ValidFolder &f = validFolder();
    std::vector<std::string> out;
    for (std::size_t i = 0; i < f.names.size(); ++i)
        out.push_back(std::string(1, static_cast<char>(i)) + std::string(1, '\0') + f.bytes[i]);
    // A 5792 x 5792 grey PNG header (never decoded: refused from the budget).
    std::string big("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\x16\xa0\0\0\x16\xa0\x08\0\0\0\0\0\0\0\0", 33);
    out.push_back(std::string(1, '\0') + std::string(1, '\0') + big + std::string(64, '\0'));
    // Noise under the white pattern of pose 0: no board, found after one search.
    cv::Mat noise(kCamH, kCamW, CV_8U);
    cv::randu(noise, 0, 256);
    const std::size_t white = projsurf::openCvGrayPatterns(kFbW, kFbH).size() - 2;
    out.push_back(std::string(1, static_cast<char>(white)) + std::string(1, '\0') + encodePng(noise));
    // A link in place of pose 1's white capture.
    out.push_back(std::string(1, static_cast<char>(f.names.size() / kPoses + white)) + std::string(1, '\1'));
    return out;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
    if (const char *dir = std::getenv("PROJSURF_FUZZ_WRITE_SEEDS")) {
        fs::create_directories(dir);
        const auto all = seeds();
        for (std::size_t i = 0; i < all.size(); ++i) {
            projsurf::fuzz::writeInput("seed", reinterpret_cast<const std::uint8_t *>(all[i].data()), all[i].size());
            fs::copy_file(projsurf::fuzz::workDir() + "/seed", fs::path(dir) / ("seed_" + std::to_string(i)),
                          fs::copy_options::overwrite_existing);
        }
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    if (size < 2) return 0;
    const ValidFolder &f = validFolder();
    const std::size_t which = data[0] % f.names.size();
    const bool link = data[1] % 2 == 1 && which >= f.names.size() / kPoses;
    const fs::path dir = fs::path(fuzz::workDir()) / "chessboard";
    std::error_code ec;
    fs::remove_all(dir, ec);
    for (int k = 0; k < kPoses; ++k) fs::create_directories(dir / ("capture_" + std::to_string(k)));
    for (std::size_t i = 0; i < f.names.size(); ++i) {
        const std::string name = "chessboard/" + f.names[i];
        if (i == which && link)
            fs::create_symlink(dir / f.names[i % (f.names.size() / kPoses)], dir / f.names[i], ec);
        else if (i == which)
            fuzz::writeInput(name, data + 2, size - 2);
        else
            fuzz::writeInput(name, reinterpret_cast<const std::uint8_t *>(f.bytes[i].data()), f.bytes[i].size());
    }
    fuzz::expectOnlyInputErrors([&] {
        const ProcamFolder folder = readProcamFolder(dir.string(), std::make_pair(kFbW, kFbH));
        const frontend::ChessboardCalibration cal = frontend::calibrateChessboard(folder, 0.02);
        ChessboardReport report;
        report.captures_dir = dir.string();
        report.poses = static_cast<int>(folder.poses.size());
        report.square_m = 0.02;
        const std::string out = (fs::path(fuzz::workDir()) / "chessboard_calib.yaml").string();
        writeChessboardCalibration(out, cal.fit, cal.width, cal.height, report);
        (void)readCalibration(out);  // what was written is read back by every reader
    });
    return 0;
}
