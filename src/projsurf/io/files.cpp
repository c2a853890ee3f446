#include "projsurf/io/files.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <unistd.h>

#include "projsurf/io/errors.hpp"

namespace fs = std::filesystem;

namespace projsurf {

void writeFileAtomic(const std::string &path, const std::string &bytes) {
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw InputError(path, "cannot open for writing");
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            throw InputError(path, "write failed");
        }
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw InputError(path, "cannot write: " + ec.message());
    }
}

void writeImageAtomic(const std::string &path, const cv::Mat &image) {
    std::string ext = fs::path(path).extension().string();
    if (ext.empty()) ext = ".png";
    std::vector<uchar> buf;
    bool ok = false;
    try {
        ok = cv::imencode(ext, image, buf);
    } catch (const cv::Exception &) {
        ok = false;
    }
    if (!ok) throw InputError(path, "cannot encode an image with extension '" + ext + "'");
    writeFileAtomic(path, std::string(buf.begin(), buf.end()));
}

void requireReadable(const std::string &path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(path, "no such file");
    if (fs::is_directory(path, ec)) throw InputError(path, "is a directory, expected a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "cannot open for reading");
}

void requireWritableLocation(const std::string &path) {
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(path, "output directory does not exist");
}

cv::Mat readImage(const std::string &path, int flags) {
    requireReadable(path);
    cv::Mat image;
    try {
        image = cv::imread(path, flags);
    } catch (const cv::Exception &) {
        image.release();
    }
    if (image.empty()) throw InputError(path, "not a readable image");
    return image;
}

}  // namespace projsurf
