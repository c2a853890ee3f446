#include "projsurf/io/files/files.hpp"

#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/image_header.hpp"
#include "projsurf/io/files/quiet_stderr.hpp"

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

namespace {

std::string encodeImage(const std::string &path, const cv::Mat &image) {
    std::string ext = fs::path(path).extension().string();
    if (ext.empty()) ext = ".png";
    std::vector<uchar> buf;
    bool ok = false;
    try {
        QuietStderr quiet;
        ok = cv::imencode(ext, image, buf);
    } catch (const cv::Exception &) {
        ok = false;
    }
    if (!ok) throw InputError(path, "cannot encode an image with extension '" + ext + "'");
    return std::string(buf.begin(), buf.end());
}

}  // namespace

OutputGroup::~OutputGroup() {
    std::error_code ec;
    for (const auto &f : files_) fs::remove(f.first, ec);
}

std::string OutputGroup::reserve(const std::string &path) {
    const fs::path p(path);
    if (path.empty() || p.filename().empty()) throw InputError(path, "not a file name");
    std::error_code ec;
    if (fs::is_directory(p, ec)) throw InputError(path, "is a directory, expected a file name");
    const std::string tmp = (p.parent_path() / ("." + p.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                                                std::to_string(files_.size()) + p.extension().string()))
                                .string();
    files_.emplace_back(tmp, path);
    return tmp;
}

void OutputGroup::addFile(const std::string &path, const std::string &bytes) {
    const std::string tmp = reserve(path);
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, "cannot open for writing");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw InputError(path, "write failed");
}

void OutputGroup::addImage(const std::string &path, const cv::Mat &image) { addFile(path, encodeImage(path, image)); }

void OutputGroup::commit() {
    for (std::size_t i = 0; i < files_.size(); ++i) {
        std::error_code ec;
        fs::rename(files_[i].first, files_[i].second, ec);
        if (ec) throw InputError(files_[i].second, "cannot write: " + ec.message());
        files_[i].first.clear();  // renamed: nothing to remove
    }
    files_.clear();
}

void requireReadable(const std::string &path) {
    // The kind of file first, never by opening it: a FIFO or a device would block the open or
    // the read forever.
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec && ec != std::errc::no_such_file_or_directory) {
        if (ec == std::errc::too_many_symbolic_link_levels) throw InputError(path, "symbolic link loop");
        throw InputError(path, "cannot read the file: " + ec.message());
    }
    if (!fs::exists(st)) {
        std::error_code lec;
        if (fs::is_symlink(fs::symlink_status(path, lec))) throw InputError(path, "dangling symbolic link");
        throw InputError(path, "no such file");
    }
    if (fs::is_directory(st)) throw InputError(path, "is a directory, expected a file");
    if (fs::is_fifo(st)) throw InputError(path, "is a FIFO (named pipe), expected a regular file");
    if (fs::is_character_file(st) || fs::is_block_file(st))
        throw InputError(path, "is a device, expected a regular file");
    if (fs::is_socket(st)) throw InputError(path, "is a socket, expected a regular file");
    if (!fs::is_regular_file(st)) throw InputError(path, "not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "cannot open for reading");
}

void requireWritableLocation(const std::string &path) {
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(path, "output directory does not exist");
}

std::string readSmallTextFile(const std::string &path, std::uint64_t max_bytes, const char *kind) {
    requireReadable(path);
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec) throw InputError(path, "cannot read the file");
    if (size > max_bytes)
        throw InputError(path, std::string(kind) + " file of " + std::to_string(size) + " bytes exceeds the limit of " +
                                   std::to_string(max_bytes) + " bytes");
    std::string text(static_cast<std::size_t>(size), '\0');
    std::ifstream in(path, std::ios::binary);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) throw InputError(path, "cannot read the file");
    // An image where a text file belongs (an --overlay PNG given as --detection): say so.
    const std::string image_format = readImageHeader(text).format;
    if (!image_format.empty() && image_format != "PNM")
        throw InputError(path, "is a " + image_format + " image, not a " + kind + " file");
    if (text.find('\0') != std::string::npos)
        throw InputError(path, std::string("binary data, not a ") + kind + " file");
    // Nesting: brackets, (YAML blocks) indentation steps, (XML) elements; quotes and comments
    // are not told apart, which only ever overcounts.
    const bool xml = std::string(kind) == "XML";
    int depth = 0, max_depth = 0;
    std::size_t line_start = 0;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        if (i == text.size() || text[i] == '\n') {
            std::size_t indent = 0;
            while (line_start + indent < i && (text[line_start + indent] == ' ' || text[line_start + indent] == '-'))
                ++indent;
            max_depth = std::max(max_depth, static_cast<int>(std::min<std::size_t>(indent / 2, 1 << 20)));
            line_start = i + 1;
            continue;
        }
        const char c = text[i];
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if (c == '[' || c == '{' || (xml && c == '<' && std::isalpha(static_cast<unsigned char>(next))))
            max_depth = std::max(max_depth, ++depth);
        else if (((c == ']' || c == '}') || (xml && ((c == '<' && next == '/') || (c == '/' && next == '>')))) &&
                 depth > 0)
            --depth;
    }
    if (max_depth > limits::kMaxNesting)
        throw InputError(path,
                         std::string(kind) + " nested deeper than " + std::to_string(limits::kMaxNesting) + " levels");
    return text;
}

void requireWritableFile(const std::string &path) {
    requireWritableLocation(path);
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(path, "is a directory, expected a file name");
}

void requireImageWriter(const std::string &path) {
    bool ok = false;
    try {
        ok = !fs::path(path).extension().empty() && cv::haveImageWriter(path);
    } catch (const cv::Exception &) {
    }
    if (!ok) throw InputError(path, "cannot write an image with this extension (use .png)");
}

namespace {

/// The size of an image file in bytes; InputError when it cannot be read or exceeds the limit.
std::uintmax_t imageFileBytes(const std::string &path) {
    requireReadable(path);
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec) throw InputError(path, "cannot read the file");
    if (size > limits::kMaxImageFileBytes)
        throw InputError(path, "image file of " + std::to_string(size) + " bytes exceeds the limit of " +
                                   std::to_string(limits::kMaxImageFileBytes) + " bytes");
    return size;
}

/// readImage's work; `width` > 0: the header must give exactly width x height (else the
/// mismatch is named, with `whose` size it should have been).
cv::Mat decodeImageFile(const std::string &path, int flags, std::uint64_t max_pixels, int width, int height,
                        const std::string &whose) {
    const std::uintmax_t size = imageFileBytes(path);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    {
        std::ifstream in(path, std::ios::binary);
        in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (static_cast<std::uintmax_t>(in.gcount()) != size) throw InputError(path, "cannot read the file");
    }
    // The size from the header, before the decoder allocates anything.
    const ImageHeader header = readImageHeader(bytes);
    if (header.format.empty()) throw InputError(path, "not a readable image (expected PNG, JPEG, BMP or PNM)");
    if (header.width == 0 || header.height == 0)
        throw InputError(path, "not a readable image (" + header.format + " header gives a zero size)");
    if (width > 0 &&
        (header.width != static_cast<std::uint64_t>(width) || header.height != static_cast<std::uint64_t>(height)))
        throw InputError(path, "is " + std::to_string(header.width) + "x" + std::to_string(header.height) + ", " +
                                   whose + " says " + std::to_string(width) + "x" + std::to_string(height));
    if (header.width * header.height > max_pixels)
        throw InputError(path, header.format + " image of " + std::to_string(header.width) + " x " +
                                   std::to_string(header.height) + " pixels exceeds the limit of " +
                                   std::to_string(max_pixels) + " pixels");
    cv::Mat image;
    try {
        QuietStderr quiet;  // libpng / libjpeg warnings
        image = cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, bytes.data()), flags);
    } catch (const cv::Exception &) {
        image.release();
    }
    if (image.empty()) throw InputError(path, "not a readable image (corrupt " + header.format + " data)");
    if (static_cast<std::uint64_t>(image.total()) > max_pixels)  // the header lied
        throw InputError(path, "image exceeds the limit of " + std::to_string(max_pixels) + " pixels");
    if (width > 0 && (image.cols != width || image.rows != height))  // the header lied
        throw InputError(path, "is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) + ", " + whose +
                                   " says " + std::to_string(width) + "x" + std::to_string(height));
    return image;
}

}  // namespace

std::pair<std::uint64_t, std::uint64_t> imageFileSize(const std::string &path) {
    const std::uintmax_t size = imageFileBytes(path);
    // The header is in the first bytes (a JPEG's frame header after its metadata segments:
    // the whole file when the first MiB does not hold it).
    ImageHeader header;
    for (const std::uintmax_t n : {std::min<std::uintmax_t>(size, 1 << 20), static_cast<std::uintmax_t>(size)}) {
        std::string bytes(static_cast<std::size_t>(n), '\0');
        std::ifstream in(path, std::ios::binary);
        in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (static_cast<std::uintmax_t>(in.gcount()) != n) throw InputError(path, "cannot read the file");
        header = readImageHeader(bytes);
        if (!header.format.empty() || n == size) break;
    }
    if (header.format.empty()) throw InputError(path, "not a readable image (expected PNG, JPEG, BMP or PNM)");
    if (header.width == 0 || header.height == 0)
        throw InputError(path, "not a readable image (" + header.format + " header gives a zero size)");
    return {header.width, header.height};
}

cv::Mat readImage(const std::string &path, int flags, std::uint64_t max_pixels) {
    return decodeImageFile(path, flags, max_pixels, 0, 0, "");
}

cv::Mat readImageOfSize(const std::string &path, int flags, int width, int height, const std::string &whose) {
    return decodeImageFile(path, flags, static_cast<std::uint64_t>(width) * height, width, height, whose);
}

}  // namespace projsurf
