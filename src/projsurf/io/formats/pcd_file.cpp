#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/formats/pcd_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string_view>
#include <vector>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/formats/cloud_format_parsing.hpp"

namespace projsurf {
namespace {

using namespace cloud_format;

/// LZF, the compression of PCD binary_compressed: decompresses a stream into exactly `out_len` bytes; false on any
/// inconsistency. Stream: a control byte c. c < 32: a literal run of c + 1 bytes follows. Otherwise a back reference:
/// length L = c >> 5 (L == 7: plus the next byte), offset high bits c & 31, then the offset's low byte; copy L + 2
/// bytes starting (offset + 1) bytes back.
bool lzfDecompress(const unsigned char *in, std::size_t in_len, unsigned char *out, std::size_t out_len) {
    std::size_t ip = 0, op = 0;
    while (ip < in_len) {
        const unsigned ctrl = in[ip++];
        if (ctrl < 32) {
            const std::size_t len = ctrl + 1;
            if (len > in_len - ip || len > out_len - op) return false;
            std::memcpy(out + op, in + ip, len);
            ip += len;
            op += len;
        } else {
            std::size_t len = ctrl >> 5;
            if (len == 7) {
                if (ip >= in_len) return false;
                len += in[ip++];
            }
            if (ip >= in_len) return false;
            const std::size_t back = ((ctrl & 0x1fu) << 8) + in[ip++] + 1;
            len += 2;
            if (back > op || len > out_len - op) return false;
            for (std::size_t k = 0; k < len; ++k, ++op) out[op] = out[op - back];  // may overlap
        }
    }
    return op == out_len;
}

// A back reference is at most 3 bytes for 264 output bytes: no stream expands further.
constexpr std::uint64_t kLzfMaxRatio = 89;

enum class PcdData { Ascii, Binary, Compressed };

struct PcdField {
    std::string name;
    Scalar type;
    std::uint64_t count = 1;
};

struct PcdHeader {
    std::vector<PcdField> fields;
    std::uint64_t width = 0, height = 1, points = 0;
    PcdData data = PcdData::Ascii;
    std::size_t data_offset = 0;
};

/// The FIELDS, SIZE, TYPE and COUNT lines as fields, each checked.
std::vector<PcdField> pcdFields(const std::string &path, const std::vector<std::string_view> &names,
                                const std::vector<std::string_view> &sizes, const std::vector<std::string_view> &types,
                                const std::vector<std::string_view> &counts) {
    auto bad = [&](const std::string &what) { return InputError(path, "malformed PCD header: " + what); };
    std::vector<PcdField> fields;
    if (names.empty()) throw bad("no FIELDS line");
    if (sizes.empty()) throw bad("no SIZE line");
    if (types.empty()) throw bad("no TYPE line");
    if (sizes.size() != names.size() || types.size() != names.size() ||
        (!counts.empty() && counts.size() != names.size()))
        throw bad("FIELDS has " + std::to_string(names.size()) + " entries but SIZE has " +
                  std::to_string(sizes.size()) + ", TYPE " + std::to_string(types.size()) +
                  (counts.empty() ? std::string() : ", COUNT " + std::to_string(counts.size())));
    for (std::size_t i = 0; i < names.size(); ++i) {
        PcdField f;
        f.name = std::string(names[i]);
        std::uint64_t size = 0;
        if (!parseU64(sizes[i], size) || (size != 1 && size != 2 && size != 4 && size != 8))
            throw bad("SIZE of field " + shown(names[i]) + " must be 1, 2, 4 or 8, got " + shown(sizes[i]));
        f.type.size = static_cast<int>(size);
        if (types[i] == "F")
            f.type.kind = Kind::Float;
        else if (types[i] == "I")
            f.type.kind = Kind::Int;
        else if (types[i] == "U")
            f.type.kind = Kind::UInt;
        else
            throw bad("TYPE of field " + shown(names[i]) + " must be F, I or U, got " + shown(types[i]));
        if (f.type.kind == Kind::Float && size != 4 && size != 8)
            throw bad("field " + shown(names[i]) + " has TYPE F with SIZE " + std::to_string(size) +
                      " (expected 4 or 8)");
        if (!counts.empty() && (!parseU64(counts[i], f.count) || f.count < 1 || f.count > (1u << 20)))
            throw bad("COUNT of field " + shown(names[i]) + " must be a whole number in 1..2^20, got " +
                      shown(counts[i]));
        fields.push_back(f);
    }
    return fields;
}

/// WIDTH x HEIGHT, checked against POINTS and the size limits.
std::uint64_t checkedPointCount(const std::string &path, const PcdHeader &h, bool have_width, bool have_points,
                                std::uint64_t points) {
    auto bad = [&](const std::string &what) { return InputError(path, "malformed PCD header: " + what); };
    if (!have_width) throw bad("no WIDTH line");
    const std::uint64_t int_max = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
    if (h.width > int_max || h.height > int_max)
        throw bad("WIDTH " + std::to_string(h.width) + " x HEIGHT " + std::to_string(h.height) + " is too large");
    const std::uint64_t wh = h.width * h.height;  // both < 2^31: no overflow
    if (have_points && points != wh)
        throw bad("POINTS " + std::to_string(points) + " does not match WIDTH x HEIGHT = " + std::to_string(h.width) +
                  " x " + std::to_string(h.height));
    if (wh > limits::kMaxCloudPoints)
        throw InputError(path, "cloud of " + std::to_string(wh) + " points exceeds the limit of " +
                                   std::to_string(limits::kMaxCloudPoints) + " points");
    return wh;
}

PcdHeader parsePcdHeader(const std::string &path, const std::string &bytes) {
    auto bad = [&](const std::string &what) { return InputError(path, "malformed PCD header: " + what); };
    std::vector<std::string_view> names, sizes, types, counts, words;
    bool have_width = false, have_height = false, have_points = false, have_version = false, have_viewpoint = false;
    std::uint64_t points = 0;
    PcdHeader h;
    std::size_t pos = 0;
    bool have_data = false;
    while (!have_data) {
        if (pos >= bytes.size()) throw bad("no DATA line");
        const std::string_view line = nextLine(bytes, pos);
        splitWords(line, words);
        if (words.empty() || words[0][0] == '#') continue;
        const std::string_view key = words[0];
        const std::size_t nargs = words.size() - 1;
        auto once = [&](bool &seen) {
            if (seen) throw bad("repeated " + std::string(key) + " line");
            seen = true;
        };
        auto list = [&](std::vector<std::string_view> &dst) {
            if (!dst.empty()) throw bad("repeated " + std::string(key) + " line");
            if (nargs == 0) throw bad(std::string(key) + " line without values");
            dst.assign(words.begin() + 1, words.end());
        };
        auto single = [&](bool &seen) {
            once(seen);
            std::uint64_t v = 0;
            if (nargs != 1 || !parseU64(words[1], v))
                throw bad(std::string(key) + " needs one non-negative whole number, got " + shown(line));
            return v;
        };
        if (key == "VERSION") {
            once(have_version);
            if (nargs != 1) throw bad("VERSION needs one value, got " + shown(line));
        } else if (key == "FIELDS" || key == "COLUMNS") {
            list(names);
        } else if (key == "SIZE") {
            list(sizes);
        } else if (key == "TYPE") {
            list(types);
        } else if (key == "COUNT") {
            list(counts);
        } else if (key == "WIDTH") {
            h.width = single(have_width);
        } else if (key == "HEIGHT") {
            h.height = single(have_height);
        } else if (key == "POINTS") {
            points = single(have_points);
        } else if (key == "VIEWPOINT") {
            once(have_viewpoint);
            double v;
            if (nargs != 7) throw bad("VIEWPOINT needs 7 numbers, got " + shown(line));
            for (std::size_t i = 1; i < words.size(); ++i)
                if (!parseDouble(words[i], v) || !std::isfinite(v)) throw bad("VIEWPOINT value " + shown(words[i]));
        } else if (key == "DATA") {
            if (nargs != 1) throw bad("DATA needs one value, got " + shown(line));
            if (words[1] == "ascii")
                h.data = PcdData::Ascii;
            else if (words[1] == "binary")
                h.data = PcdData::Binary;
            else if (words[1] == "binary_compressed")
                h.data = PcdData::Compressed;
            else
                throw bad("unknown DATA type " + shown(words[1]) + " (expected ascii, binary or binary_compressed)");
            have_data = true;
        } else {
            throw bad("unexpected line " + shown(line));
        }
    }
    h.data_offset = pos;

    h.fields = pcdFields(path, names, sizes, types, counts);
    h.points = checkedPointCount(path, h, have_width, have_points, points);
    return h;
}

/// Where x, y, z live in a point: field index, byte offset within a point (binary), value
/// index (ascii).
struct PcdLayout {
    std::uint64_t point_size = 0, values_per_point = 0;
    std::vector<std::uint64_t> field_offset, field_value;
    int xyz[3] = {0, 0, 0};
};

const char *const kAxisNames[3] = {"x", "y", "z"};

PcdLayout pcdLayout(const std::string &path, const PcdHeader &h) {
    PcdLayout lay;
    for (const PcdField &f : h.fields) {
        lay.field_offset.push_back(lay.point_size);
        lay.field_value.push_back(lay.values_per_point);
        lay.point_size += f.type.size * f.count;
        lay.values_per_point += f.count;
    }
    for (int a = 0; a < 3; ++a) {
        const auto it =
            std::find_if(h.fields.begin(), h.fields.end(), [&](const PcdField &f) { return f.name == kAxisNames[a]; });
        if (it == h.fields.end()) {
            std::string list;
            for (const PcdField &f : h.fields) list += (list.empty() ? "" : " ") + f.name;
            throw InputError(path,
                             std::string("no ") + kAxisNames[a] + " field in the PCD (FIELDS: " + shown(list) + ")");
        }
        lay.xyz[a] = static_cast<int>(it - h.fields.begin());
    }
    return lay;
}

InputError truncatedPcd(const std::string &path, const PcdHeader &h, const std::string &detail) {
    return InputError(path, "truncated data: the header promises " + std::to_string(h.points) + " points; " + detail);
}

void readAsciiPoints(const std::string &path, const std::string &bytes, const PcdHeader &h, const PcdLayout &lay,
                     std::vector<Point> &points) {
    const std::size_t remaining = bytes.size() - h.data_offset;
    const char *const *axis_names = kAxisNames;
    auto truncated = [&](const std::string &detail) { return truncatedPcd(path, h, detail); };
    // Each point needs at least one character and one separator per value.
    points.reserve(
        static_cast<std::size_t>(std::min<std::uint64_t>(h.points, remaining / (2 * lay.values_per_point) + 1)));
    std::vector<std::string_view> words;
    std::size_t pos = h.data_offset, line_no = 0;
    while (points.size() < h.points && pos < bytes.size()) {
        const std::string_view line = nextLine(bytes, pos);
        ++line_no;
        splitWords(line, words);
        if (words.empty()) continue;
        if (words.size() != lay.values_per_point)
            throw InputError(path, "ascii data line " + std::to_string(line_no) + ": expected " +
                                       std::to_string(lay.values_per_point) + " values, found " +
                                       std::to_string(words.size()));
        Point p;
        for (int a = 0; a < 3; ++a) {
            double v;
            const std::string_view w = words[lay.field_value[lay.xyz[a]]];
            if (!parseDouble(w, v))
                throw InputError(path, "ascii data line " + std::to_string(line_no) + ": " + axis_names[a] +
                                           " is not a number: " + shown(w));
            p[a] = toFloat(v);
        }
        points.push_back(p);
    }
    if (points.size() < h.points) throw truncated("found " + std::to_string(points.size()));
}

void readBinaryPoints(const std::string &path, const std::string &bytes, const PcdHeader &h, const PcdLayout &lay,
                      std::vector<Point> &points) {
    const std::size_t remaining = bytes.size() - h.data_offset;
    const auto *data = reinterpret_cast<const unsigned char *>(bytes.data()) + h.data_offset;
    auto truncated = [&](const std::string &detail) { return truncatedPcd(path, h, detail); };
    if (h.points > remaining / lay.point_size)
        throw truncated("needs " + std::to_string(h.points * lay.point_size) + " bytes of binary data, the file has " +
                        std::to_string(remaining));
    points.resize(static_cast<std::size_t>(h.points));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const unsigned char *p = data + i * lay.point_size;
        for (int a = 0; a < 3; ++a)
            points[i][a] = toFloat(decodeScalar(p + lay.field_offset[lay.xyz[a]], h.fields[lay.xyz[a]].type, false));
    }
}

void readCompressedPoints(const std::string &path, const std::string &bytes, const PcdHeader &h, const PcdLayout &lay,
                          std::vector<Point> &points) {
    const std::size_t remaining = bytes.size() - h.data_offset;
    const auto *data = reinterpret_cast<const unsigned char *>(bytes.data()) + h.data_offset;
    auto truncated = [&](const std::string &detail) { return truncatedPcd(path, h, detail); };
    if (remaining < 8) throw truncated("the binary_compressed size words are missing");
    const std::uint64_t compressed = readU32LE(data), raw = readU32LE(data + 4);
    if (compressed > remaining - 8)
        throw truncated(std::to_string(compressed) + " compressed bytes announced, " + std::to_string(remaining - 8) +
                        " present");
    if (h.points > std::numeric_limits<std::uint32_t>::max() / lay.point_size || raw != h.points * lay.point_size)
        throw InputError(path, "corrupt binary_compressed data: uncompressed size " + std::to_string(raw) +
                                   " does not match " + std::to_string(h.points) + " points of " +
                                   std::to_string(lay.point_size) + " bytes");
    if (raw > limits::kMaxDecompressedBytes)
        throw InputError(path, "binary_compressed data of " + std::to_string(raw) +
                                   " uncompressed bytes exceeds the limit of " +
                                   std::to_string(limits::kMaxDecompressedBytes) + " bytes");
    if (raw > compressed * kLzfMaxRatio)
        throw InputError(path, "corrupt binary_compressed data: " + std::to_string(compressed) +
                                   " compressed bytes cannot hold " + std::to_string(raw) + " bytes");
    std::vector<unsigned char> soa(static_cast<std::size_t>(raw));
    if (!lzfDecompress(data + 8, static_cast<std::size_t>(compressed), soa.data(), soa.size()))
        throw InputError(path, "corrupt binary_compressed data (LZF stream does not decode)");
    // Field-major layout: all points' values of field 0, then of field 1, ...
    std::uint64_t start[3];
    for (int a = 0; a < 3; ++a) start[a] = lay.field_offset[lay.xyz[a]] * h.points;
    points.resize(static_cast<std::size_t>(h.points));
    for (int a = 0; a < 3; ++a) {
        const PcdField &f = h.fields[lay.xyz[a]];
        const std::uint64_t stride = f.type.size * f.count;
        for (std::size_t i = 0; i < points.size(); ++i)
            points[i][a] = toFloat(decodeScalar(soa.data() + start[a] + i * stride, f.type, false));
    }
}

}  // namespace

Cloud readPcd(const std::string &path, const std::string &bytes) {
    const PcdHeader h = parsePcdHeader(path, bytes);
    const PcdLayout lay = pcdLayout(path, h);
    if (h.points == 0) throw InputError(path, "the cloud has zero points");
    Cloud cloud;
    if (h.data == PcdData::Ascii)
        readAsciiPoints(path, bytes, h, lay, cloud.points);
    else if (h.data == PcdData::Binary)
        readBinaryPoints(path, bytes, h, lay, cloud.points);
    else
        readCompressedPoints(path, bytes, h, lay, cloud.points);
    if (h.height > 1) {
        cloud.width = static_cast<int>(h.width);
        cloud.height = static_cast<int>(h.height);
    } else {
        cloud.width = static_cast<int>(cloud.points.size());
        cloud.height = 1;
    }
    return cloud;
}

void writeCloudPcd(const std::string &path, const Cloud &cloud) {
    const bool organized = cloud.organized();
    const std::size_t width = organized ? static_cast<std::size_t>(cloud.width) : cloud.points.size();
    const std::size_t height = organized ? static_cast<std::size_t>(cloud.height) : 1;
    std::string out =
        "# .PCD v0.7 - Point Cloud Data file format (written by projsurf)\n"
        "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
    out += "WIDTH " + std::to_string(width) + "\nHEIGHT " + std::to_string(height) + "\n";
    out += "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(cloud.points.size()) + "\nDATA binary\n";
    out.reserve(out.size() + 12 * cloud.points.size());
    for (const Point &p : cloud.points)
        for (int a = 0; a < 3; ++a) appendFloatLE(out, p[a]);
    writeFileAtomic(path, out);
}

}  // namespace projsurf
