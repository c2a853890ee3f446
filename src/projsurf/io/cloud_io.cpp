#include "projsurf/io/cloud_io.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <string_view>
#include <vector>

#include "projsurf/core/camera.hpp"
#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/limits.hpp"
#include "projsurf/io/yaml_files.hpp"

namespace projsurf {
namespace {

// ---------------------------------------------------------------------------------------
// Scalars
// ---------------------------------------------------------------------------------------

enum class Kind { Int, UInt, Float };

struct Scalar {
    Kind kind = Kind::Float;
    int size = 4;  // bytes: 1, 2, 4 or 8 (Float: 4 or 8)
};

/// Value of a stored scalar; `big_endian` tells the byte order in the file.
double decodeScalar(const unsigned char *p, Scalar t, bool big_endian) {
    std::uint64_t u = 0;
    for (int i = 0; i < t.size; ++i) {
        const unsigned char b = big_endian ? p[t.size - 1 - i] : p[i];
        u |= static_cast<std::uint64_t>(b) << (8 * i);
    }
    switch (t.kind) {
    case Kind::Float:
        if (t.size == 4) {
            const auto bits = static_cast<std::uint32_t>(u);
            float f;
            std::memcpy(&f, &bits, sizeof f);
            return f;
        } else {
            double d;
            std::memcpy(&d, &u, sizeof d);
            return d;
        }
    case Kind::UInt:
        return static_cast<double>(u);
    case Kind::Int:
        if (t.size < 8 && (u >> (8 * t.size - 1)) & 1u) u |= ~std::uint64_t{0} << (8 * t.size);
        return static_cast<double>(static_cast<std::int64_t>(u));
    }
    return 0.0;
}

/// double -> float without undefined behaviour for values beyond the float range.
float toFloat(double d) {
    if (std::isnan(d)) return std::numeric_limits<float>::quiet_NaN();
    if (d > std::numeric_limits<float>::max()) return std::numeric_limits<float>::infinity();
    if (d < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::infinity();
    return static_cast<float>(d);
}

void appendFloatLE(std::string &out, float f) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((bits >> (8 * i)) & 0xffu));
}

std::uint32_t readU32LE(const unsigned char *p) {
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

// ---------------------------------------------------------------------------------------
// Text helpers
// ---------------------------------------------------------------------------------------

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

void splitWords(std::string_view line, std::vector<std::string_view> &words) {
    words.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
}

/// A header line as it may appear in a message: short and printable.
std::string shown(std::string_view s) {
    std::string out = "'";
    for (std::size_t i = 0; i < s.size() && i < 60; ++i)
        out.push_back(std::isprint(static_cast<unsigned char>(s[i])) ? s[i] : '?');
    if (s.size() > 60) out += "...";
    return out + "'";
}

bool parseU64(std::string_view s, std::uint64_t &value) {
    if (s.empty()) return false;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), value);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parseDouble(std::string_view s, double &value) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    if (s.empty()) return false;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), value);
    if (r.ec == std::errc::result_out_of_range) {  // overflow/underflow: keep the sign
        value = (s[0] == '-') ? -HUGE_VAL : HUGE_VAL;
        return r.ptr == s.data() + s.size();
    }
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

/// Next line of `bytes` from `pos` (without '\n' and a trailing '\r'); advances `pos`.
std::string_view nextLine(const std::string &bytes, std::size_t &pos) {
    const std::size_t nl = bytes.find('\n', pos);
    const std::size_t end = nl == std::string::npos ? bytes.size() : nl;
    std::string_view line(bytes.data() + pos, end - pos);
    pos = nl == std::string::npos ? bytes.size() : nl + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

/// Whitespace-separated tokens over a byte range, across lines.
struct Tokens {
    const std::string &bytes;
    std::size_t pos;
    bool next(std::string_view &tok) {
        while (pos < bytes.size() && isSpace(bytes[pos])) ++pos;
        if (pos >= bytes.size()) return false;
        const std::size_t start = pos;
        while (pos < bytes.size() && !isSpace(bytes[pos])) ++pos;
        tok = std::string_view(bytes.data() + start, pos - start);
        return true;
    }
};

std::string readWholeFile(const std::string &path) {
    requireReadable(path);
    std::ifstream in(path, std::ios::binary);
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (!in || size < 0) throw InputError(path, "cannot read the file");
    if (static_cast<std::uint64_t>(size) > limits::kMaxCloudFileBytes)
        throw InputError(path, "point-cloud file of " + std::to_string(size) + " bytes exceeds the limit of " +
                                   std::to_string(limits::kMaxCloudFileBytes) + " bytes");
    in.seekg(0, std::ios::beg);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), size);
    if (in.gcount() != size) throw InputError(path, "cannot read the file");
    return bytes;
}

std::string lowerExtension(const std::string &path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char &c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// ---------------------------------------------------------------------------------------
// LZF (the compression of PCD binary_compressed)
// ---------------------------------------------------------------------------------------

/// Decompresses an LZF stream into exactly `out_len` bytes; false on any inconsistency.
/// Stream: a control byte c. c < 32: a literal run of c + 1 bytes follows. Otherwise a
/// back reference: length L = c >> 5 (L == 7: plus the next byte), offset high bits c & 31,
/// then the offset's low byte; copy L + 2 bytes starting (offset + 1) bytes back.
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

// ---------------------------------------------------------------------------------------
// PCD
// ---------------------------------------------------------------------------------------

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
            if (words[1] == "ascii") h.data = PcdData::Ascii;
            else if (words[1] == "binary") h.data = PcdData::Binary;
            else if (words[1] == "binary_compressed") h.data = PcdData::Compressed;
            else throw bad("unknown DATA type " + shown(words[1]) + " (expected ascii, binary or binary_compressed)");
            have_data = true;
        } else {
            throw bad("unexpected line " + shown(line));
        }
    }
    h.data_offset = pos;

    if (names.empty()) throw bad("no FIELDS line");
    if (sizes.empty()) throw bad("no SIZE line");
    if (types.empty()) throw bad("no TYPE line");
    if (sizes.size() != names.size() || types.size() != names.size() || (!counts.empty() && counts.size() != names.size()))
        throw bad("FIELDS has " + std::to_string(names.size()) + " entries but SIZE has " + std::to_string(sizes.size()) +
                  ", TYPE " + std::to_string(types.size()) +
                  (counts.empty() ? std::string() : ", COUNT " + std::to_string(counts.size())));
    for (std::size_t i = 0; i < names.size(); ++i) {
        PcdField f;
        f.name = std::string(names[i]);
        std::uint64_t size = 0;
        if (!parseU64(sizes[i], size) || (size != 1 && size != 2 && size != 4 && size != 8))
            throw bad("SIZE of field " + shown(names[i]) + " must be 1, 2, 4 or 8, got " + shown(sizes[i]));
        f.type.size = static_cast<int>(size);
        if (types[i] == "F") f.type.kind = Kind::Float;
        else if (types[i] == "I") f.type.kind = Kind::Int;
        else if (types[i] == "U") f.type.kind = Kind::UInt;
        else throw bad("TYPE of field " + shown(names[i]) + " must be F, I or U, got " + shown(types[i]));
        if (f.type.kind == Kind::Float && size != 4 && size != 8)
            throw bad("field " + shown(names[i]) + " has TYPE F with SIZE " + std::to_string(size) + " (expected 4 or 8)");
        if (!counts.empty() && (!parseU64(counts[i], f.count) || f.count < 1 || f.count > (1u << 20)))
            throw bad("COUNT of field " + shown(names[i]) + " must be a whole number in 1..2^20, got " + shown(counts[i]));
        h.fields.push_back(f);
    }
    if (!have_width) throw bad("no WIDTH line");
    const std::uint64_t int_max = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
    if (h.width > int_max || h.height > int_max)
        throw bad("WIDTH " + std::to_string(h.width) + " x HEIGHT " + std::to_string(h.height) + " is too large");
    const std::uint64_t wh = h.width * h.height;  // both < 2^31: no overflow
    if (have_points && points != wh)
        throw bad("POINTS " + std::to_string(points) + " does not match WIDTH x HEIGHT = " + std::to_string(h.width) + " x " +
                  std::to_string(h.height));
    h.points = wh;
    if (h.points > limits::kMaxCloudPoints)
        throw InputError(path, "cloud of " + std::to_string(h.points) + " points exceeds the limit of " +
                                   std::to_string(limits::kMaxCloudPoints) + " points");
    return h;
}

Cloud readPcd(const std::string &path, const std::string &bytes) {
    const PcdHeader h = parsePcdHeader(path, bytes);
    // Where x, y, z live: field index, byte offset within a point (binary), value index (ascii).
    std::uint64_t point_size = 0, values_per_point = 0;
    std::vector<std::uint64_t> field_offset, field_value;
    for (const PcdField &f : h.fields) {
        field_offset.push_back(point_size);
        field_value.push_back(values_per_point);
        point_size += f.type.size * f.count;
        values_per_point += f.count;
    }
    int xyz[3];
    const char *axis_names[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
        const auto it = std::find_if(h.fields.begin(), h.fields.end(), [&](const PcdField &f) { return f.name == axis_names[a]; });
        if (it == h.fields.end()) {
            std::string list;
            for (const PcdField &f : h.fields) list += (list.empty() ? "" : " ") + f.name;
            throw InputError(path, std::string("no ") + axis_names[a] + " field in the PCD (FIELDS: " + shown(list) + ")");
        }
        xyz[a] = static_cast<int>(it - h.fields.begin());
    }
    if (h.points == 0) throw InputError(path, "the cloud has zero points");

    Cloud cloud;
    const std::size_t remaining = bytes.size() - h.data_offset;
    const auto *data = reinterpret_cast<const unsigned char *>(bytes.data()) + h.data_offset;
    auto truncated = [&](const std::string &detail) {
        return InputError(path, "truncated data: the header promises " + std::to_string(h.points) + " points; " + detail);
    };

    if (h.data == PcdData::Ascii) {
        // Each point needs at least one character and one separator per value.
        cloud.points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(h.points, remaining / (2 * values_per_point) + 1)));
        std::vector<std::string_view> words;
        std::size_t pos = h.data_offset, line_no = 0;
        while (cloud.points.size() < h.points && pos < bytes.size()) {
            const std::string_view line = nextLine(bytes, pos);
            ++line_no;
            splitWords(line, words);
            if (words.empty()) continue;
            if (words.size() != values_per_point)
                throw InputError(path, "ascii data line " + std::to_string(line_no) + ": expected " +
                                           std::to_string(values_per_point) + " values, found " + std::to_string(words.size()));
            Point p;
            for (int a = 0; a < 3; ++a) {
                double v;
                const std::string_view w = words[field_value[xyz[a]]];
                if (!parseDouble(w, v))
                    throw InputError(path, "ascii data line " + std::to_string(line_no) + ": " + axis_names[a] +
                                               " is not a number: " + shown(w));
                p[a] = toFloat(v);
            }
            cloud.points.push_back(p);
        }
        if (cloud.points.size() < h.points) throw truncated("found " + std::to_string(cloud.points.size()));
    } else if (h.data == PcdData::Binary) {
        if (h.points > remaining / point_size)
            throw truncated("needs " + std::to_string(h.points * point_size) + " bytes of binary data, the file has " +
                            std::to_string(remaining));
        cloud.points.resize(static_cast<std::size_t>(h.points));
        for (std::size_t i = 0; i < cloud.points.size(); ++i) {
            const unsigned char *p = data + i * point_size;
            for (int a = 0; a < 3; ++a)
                cloud.points[i][a] = toFloat(decodeScalar(p + field_offset[xyz[a]], h.fields[xyz[a]].type, false));
        }
    } else {
        if (remaining < 8) throw truncated("the binary_compressed size words are missing");
        const std::uint64_t compressed = readU32LE(data), raw = readU32LE(data + 4);
        if (compressed > remaining - 8)
            throw truncated(std::to_string(compressed) + " compressed bytes announced, " + std::to_string(remaining - 8) +
                            " present");
        if (h.points > std::numeric_limits<std::uint32_t>::max() / point_size || raw != h.points * point_size)
            throw InputError(path, "corrupt binary_compressed data: uncompressed size " + std::to_string(raw) +
                                       " does not match " + std::to_string(h.points) + " points of " +
                                       std::to_string(point_size) + " bytes");
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
        for (int a = 0; a < 3; ++a) start[a] = field_offset[xyz[a]] * h.points;
        cloud.points.resize(static_cast<std::size_t>(h.points));
        for (int a = 0; a < 3; ++a) {
            const PcdField &f = h.fields[xyz[a]];
            const std::uint64_t stride = f.type.size * f.count;
            for (std::size_t i = 0; i < cloud.points.size(); ++i)
                cloud.points[i][a] = toFloat(decodeScalar(soa.data() + start[a] + i * stride, f.type, false));
        }
    }
    if (h.height > 1) {
        cloud.width = static_cast<int>(h.width);
        cloud.height = static_cast<int>(h.height);
    } else {
        cloud.width = static_cast<int>(cloud.points.size());
        cloud.height = 1;
    }
    return cloud;
}

// ---------------------------------------------------------------------------------------
// PLY
// ---------------------------------------------------------------------------------------

struct PlyProperty {
    std::string name;
    Scalar type;
    bool is_list = false;
    Scalar count_type;  // lists only
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> props;
};

bool plyType(std::string_view s, Scalar &t) {
    static const struct {
        const char *a, *b;
        Kind kind;
        int size;
    } table[] = {{"char", "int8", Kind::Int, 1},     {"uchar", "uint8", Kind::UInt, 1},   {"short", "int16", Kind::Int, 2},
                 {"ushort", "uint16", Kind::UInt, 2}, {"int", "int32", Kind::Int, 4},      {"uint", "uint32", Kind::UInt, 4},
                 {"float", "float32", Kind::Float, 4}, {"double", "float64", Kind::Float, 8}};
    for (const auto &e : table)
        if (s == e.a || s == e.b) {
            t = {e.kind, e.size};
            return true;
        }
    return false;
}

Cloud readPly(const std::string &path, const std::string &bytes) {
    auto bad = [&](const std::string &what) { return InputError(path, "malformed PLY header: " + what); };
    std::size_t pos = 0;
    std::vector<std::string_view> words;
    if (nextLine(bytes, pos) != "ply") throw bad("the file does not start with 'ply'");
    enum class Format { None, Ascii, Little, Big } format = Format::None;
    std::vector<PlyElement> elements;
    bool ended = false;
    while (!ended) {
        if (pos >= bytes.size()) throw bad("no end_header line");
        const std::string_view line = nextLine(bytes, pos);
        splitWords(line, words);
        if (words.empty()) continue;
        const std::string_view key = words[0];
        if (key == "comment" || key == "obj_info") continue;
        if (key == "format") {
            if (format != Format::None) throw bad("repeated format line");
            if (words.size() != 3) throw bad("format line " + shown(line));
            if (words[1] == "ascii") format = Format::Ascii;
            else if (words[1] == "binary_little_endian") format = Format::Little;
            else if (words[1] == "binary_big_endian") format = Format::Big;
            else throw bad("unknown format " + shown(words[1]));
        } else if (key == "element") {
            PlyElement e;
            if (words.size() != 3 || !parseU64(words[2], e.count)) throw bad("element line " + shown(line));
            e.name = std::string(words[1]);
            elements.push_back(e);
        } else if (key == "property") {
            if (elements.empty()) throw bad("property before any element: " + shown(line));
            PlyProperty p;
            if (words.size() == 5 && words[1] == "list") {
                p.is_list = true;
                if (!plyType(words[2], p.count_type) || p.count_type.kind == Kind::Float || !plyType(words[3], p.type))
                    throw bad("property line " + shown(line));
                p.name = std::string(words[4]);
            } else if (words.size() == 3) {
                if (!plyType(words[1], p.type)) throw bad("unknown property type in " + shown(line));
                p.name = std::string(words[2]);
            } else {
                throw bad("property line " + shown(line));
            }
            elements.back().props.push_back(p);
        } else if (key == "end_header") {
            ended = true;
        } else {
            throw bad("unexpected line " + shown(line));
        }
    }
    if (format == Format::None) throw bad("no format line");
    const auto vit = std::find_if(elements.begin(), elements.end(), [](const PlyElement &e) { return e.name == "vertex"; });
    if (vit == elements.end()) throw bad("no vertex element");
    const PlyElement &vertex = *vit;
    int xyz[3];
    const char *axis_names[3] = {"x", "y", "z"};
    for (const PlyProperty &p : vertex.props)
        if (p.is_list)
            throw InputError(path, "the vertex element has a list property " + shown(p.name) +
                                       "; list properties in vertices are not supported");
    for (int a = 0; a < 3; ++a) {
        const auto it = std::find_if(vertex.props.begin(), vertex.props.end(), [&](const PlyProperty &p) { return p.name == axis_names[a]; });
        if (it == vertex.props.end()) throw InputError(path, std::string("no ") + axis_names[a] + " property in the PLY vertex element");
        xyz[a] = static_cast<int>(it - vertex.props.begin());
    }
    if (vertex.count == 0) throw InputError(path, "the cloud has zero points");
    if (vertex.count > limits::kMaxCloudPoints)
        throw InputError(path, "cloud of " + std::to_string(vertex.count) + " points exceeds the limit of " +
                                   std::to_string(limits::kMaxCloudPoints) + " points");
    auto truncated = [&](const std::string &detail) {
        return InputError(path, "truncated data: the header promises " + std::to_string(vertex.count) + " vertices; " + detail);
    };

    Cloud cloud;
    if (format == Format::Ascii) {
        Tokens tokens{bytes, pos};
        std::string_view tok;
        // Skip the elements stored before the vertices.
        for (auto e = elements.begin(); e != vit; ++e) {
            if (e->props.empty()) continue;  // zero tokens per instance, whatever the count
            for (std::uint64_t i = 0; i < e->count; ++i)
                for (const PlyProperty &p : e->props) {
                    if (!tokens.next(tok)) throw truncated("element " + shown(e->name) + " ends early");
                    if (!p.is_list) continue;
                    std::uint64_t n = 0;
                    if (!parseU64(tok, n)) throw InputError(path, "bad list length " + shown(tok) + " in element " + shown(e->name));
                    for (std::uint64_t k = 0; k < n; ++k)
                        if (!tokens.next(tok)) throw truncated("element " + shown(e->name) + " ends early");
                }
        }
        const std::size_t nprops = vertex.props.size();
        const std::size_t remaining = bytes.size() - tokens.pos;
        cloud.points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(vertex.count, remaining / (2 * nprops) + 1)));
        std::vector<std::string_view> values(nprops);
        for (std::uint64_t i = 0; i < vertex.count; ++i) {
            for (std::size_t k = 0; k < nprops; ++k)
                if (!tokens.next(values[k])) throw truncated("found " + std::to_string(i));
            Point p;
            for (int a = 0; a < 3; ++a) {
                double v;
                if (!parseDouble(values[xyz[a]], v))
                    throw InputError(path, "vertex " + std::to_string(i) + ": " + axis_names[a] + " is not a number: " + shown(values[xyz[a]]));
                p[a] = toFloat(v);
            }
            cloud.points.push_back(p);
        }
    } else {
        const bool big = format == Format::Big;
        const auto *data = reinterpret_cast<const unsigned char *>(bytes.data());
        const std::size_t end = bytes.size();
        for (auto e = elements.begin(); e != vit; ++e) {
            const bool fixed = std::none_of(e->props.begin(), e->props.end(), [](const PlyProperty &p) { return p.is_list; });
            if (fixed) {
                std::uint64_t size = 0;
                for (const PlyProperty &p : e->props) size += p.type.size;
                if (size == 0) continue;
                if (e->count > (end - pos) / size) throw truncated("element " + shown(e->name) + " ends early");
                pos += static_cast<std::size_t>(e->count * size);
                continue;
            }
            // Each instance holds at least one list length byte: the loop ends with the data.
            for (std::uint64_t i = 0; i < e->count; ++i)
                for (const PlyProperty &p : e->props) {
                    if (!p.is_list) {
                        if (static_cast<std::size_t>(p.type.size) > end - pos) throw truncated("element " + shown(e->name) + " ends early");
                        pos += p.type.size;
                        continue;
                    }
                    if (static_cast<std::size_t>(p.count_type.size) > end - pos) throw truncated("element " + shown(e->name) + " ends early");
                    const double n = decodeScalar(data + pos, p.count_type, big);
                    pos += p.count_type.size;
                    if (n < 0) throw InputError(path, "negative list length in element " + shown(e->name));
                    if (n > static_cast<double>((end - pos) / p.type.size)) throw truncated("element " + shown(e->name) + " ends early");
                    pos += static_cast<std::size_t>(n) * p.type.size;
                }
        }
        std::uint64_t vertex_size = 0;
        std::vector<std::uint64_t> offset;
        for (const PlyProperty &p : vertex.props) {
            offset.push_back(vertex_size);
            vertex_size += p.type.size;
        }
        if (vertex.count > (end - pos) / vertex_size)
            throw truncated("needs " + std::to_string(vertex.count * vertex_size) + " bytes of vertex data, the file has " +
                            std::to_string(end - pos));
        cloud.points.resize(static_cast<std::size_t>(vertex.count));
        for (std::size_t i = 0; i < cloud.points.size(); ++i) {
            const unsigned char *v = data + pos + i * vertex_size;
            for (int a = 0; a < 3; ++a)
                cloud.points[i][a] = toFloat(decodeScalar(v + offset[xyz[a]], vertex.props[xyz[a]].type, big));
        }
    }
    cloud.width = static_cast<int>(std::min<std::size_t>(cloud.points.size(), std::numeric_limits<int>::max()));
    cloud.height = 1;
    return cloud;
}

const char *depthName(int depth) {
    switch (depth) {
    case CV_8U: return "8-bit unsigned";
    case CV_8S: return "8-bit signed";
    case CV_16U: return "16-bit unsigned";
    case CV_16S: return "16-bit signed";
    case CV_32S: return "32-bit integer";
    case CV_32F: return "32-bit float";
    case CV_64F: return "64-bit float";
    default: return "unusual";
    }
}

}  // namespace

Cloud readCloud(const std::string &path) {
    const std::string ext = lowerExtension(path);
    if (ext != ".pcd" && ext != ".ply")
        throw InputError(path, "unknown point-cloud file extension " + shown(ext) + " (expected .pcd or .ply)");
    const std::string bytes = readWholeFile(path);
    if (bytes.empty()) throw InputError(path, "empty file");
    Cloud cloud = ext == ".pcd" ? readPcd(path, bytes) : readPly(path, bytes);
    if (cloud.points.empty()) throw InputError(path, "the cloud has zero points");
    // A cloud whose points are all NaN is a valid frame (NaN points are allowed): the
    // detector answers found: false with its reason.
    return cloud;
}

Cloud readDepthCloud(const std::string &depth_png, const std::string &camera_yaml) {
    const CameraIntrinsics camera = readCamera(camera_yaml);
    const cv::Mat depth = readImage(depth_png, cv::IMREAD_UNCHANGED, limits::kMaxDepthPixels);
    if (depth.type() != CV_16UC1)
        throw InputError(depth_png, std::string("expected a 16-bit single-channel depth image, got ") + depthName(depth.depth()) +
                                        " with " + std::to_string(depth.channels()) + " channel(s)");
    if (depth.cols != camera.width || depth.rows != camera.height)
        throw InputError(depth_png, "depth image is " + std::to_string(depth.cols) + "x" + std::to_string(depth.rows) +
                                        " but " + camera_yaml + " says " + std::to_string(camera.width) + "x" +
                                        std::to_string(camera.height));
    if (cv::countNonZero(depth) == 0) throw InputError(depth_png, "no valid depth reading (every pixel is 0)");
    return depthToCloud(depth, camera);
}

void writeCloudPcd(const std::string &path, const Cloud &cloud) {
    const bool organized = cloud.organized();
    const std::size_t width = organized ? static_cast<std::size_t>(cloud.width) : cloud.points.size();
    const std::size_t height = organized ? static_cast<std::size_t>(cloud.height) : 1;
    std::string out = "# .PCD v0.7 - Point Cloud Data file format (written by projsurf)\n"
                      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
    out += "WIDTH " + std::to_string(width) + "\nHEIGHT " + std::to_string(height) + "\n";
    out += "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(cloud.points.size()) + "\nDATA binary\n";
    out.reserve(out.size() + 12 * cloud.points.size());
    for (const Point &p : cloud.points)
        for (int a = 0; a < 3; ++a) appendFloatLE(out, p[a]);
    writeFileAtomic(path, out);
}

void writeCloudPly(const std::string &path, const Cloud &cloud) {
    const std::size_t n = countFinite(cloud);
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by projsurf\nelement vertex " + std::to_string(n) +
                      "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    out.reserve(out.size() + 12 * n);
    for (const Point &p : cloud.points)
        if (isFinite(p))
            for (int a = 0; a < 3; ++a) appendFloatLE(out, p[a]);
    writeFileAtomic(path, out);
}

}  // namespace projsurf
