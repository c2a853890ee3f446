#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/formats/ply_file.hpp"

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
    } table[] = {{"char", "int8", Kind::Int, 1},       {"uchar", "uint8", Kind::UInt, 1},
                 {"short", "int16", Kind::Int, 2},     {"ushort", "uint16", Kind::UInt, 2},
                 {"int", "int32", Kind::Int, 4},       {"uint", "uint32", Kind::UInt, 4},
                 {"float", "float32", Kind::Float, 4}, {"double", "float64", Kind::Float, 8}};
    for (const auto &e : table)
        if (s == e.a || s == e.b) {
            t = {e.kind, e.size};
            return true;
        }
    return false;
}

enum class PlyFormat { None, Ascii, Little, Big };

struct PlyHeader {
    PlyFormat format = PlyFormat::None;
    std::vector<PlyElement> elements;
};

/// What the body readers share: the file, the read position (just past the header), the vertex
/// element and where its x, y, z properties sit.
struct PlyBody {
    const std::string &path;
    const std::string &bytes;
    std::size_t pos;
    const std::vector<PlyElement> &elements;
    std::vector<PlyElement>::const_iterator vertex;
    int xyz[3];

    InputError truncated(const std::string &detail) const {
        return InputError(
            path, "truncated data: the header promises " + std::to_string(vertex->count) + " vertices; " + detail);
    }
    InputError endsEarly(const PlyElement &e) const { return truncated("element " + shown(e.name) + " ends early"); }
};

const char *const kAxisNames[3] = {"x", "y", "z"};

InputError badHeader(const std::string &path, const std::string &what) {
    return InputError(path, "malformed PLY header: " + what);
}

PlyFormat plyFormat(const std::string &path, const std::vector<std::string_view> &words, std::string_view line) {
    if (words.size() != 3) throw badHeader(path, "format line " + shown(line));
    if (words[1] == "ascii") return PlyFormat::Ascii;
    if (words[1] == "binary_little_endian") return PlyFormat::Little;
    if (words[1] == "binary_big_endian") return PlyFormat::Big;
    throw badHeader(path, "unknown format " + shown(words[1]));
}

PlyProperty plyProperty(const std::string &path, const std::vector<std::string_view> &words, std::string_view line) {
    PlyProperty p;
    if (words.size() == 5 && words[1] == "list") {
        p.is_list = true;
        if (!plyType(words[2], p.count_type) || p.count_type.kind == Kind::Float || !plyType(words[3], p.type))
            throw badHeader(path, "property line " + shown(line));
        p.name = std::string(words[4]);
    } else if (words.size() == 3) {
        if (!plyType(words[1], p.type)) throw badHeader(path, "unknown property type in " + shown(line));
        p.name = std::string(words[2]);
    } else {
        throw badHeader(path, "property line " + shown(line));
    }
    return p;
}

/// The header up to and including its end_header line; `pos` ends past it.
PlyHeader readPlyHeader(const std::string &path, const std::string &bytes, std::size_t &pos) {
    std::vector<std::string_view> words;
    if (nextLine(bytes, pos) != "ply") throw badHeader(path, "the file does not start with 'ply'");
    PlyHeader header;
    for (;;) {
        if (pos >= bytes.size()) throw badHeader(path, "no end_header line");
        const std::string_view line = nextLine(bytes, pos);
        splitWords(line, words);
        if (words.empty()) continue;
        const std::string_view key = words[0];
        if (key == "comment" || key == "obj_info") continue;
        if (key == "format") {
            if (header.format != PlyFormat::None) throw badHeader(path, "repeated format line");
            header.format = plyFormat(path, words, line);
        } else if (key == "element") {
            PlyElement e;
            if (words.size() != 3 || !parseU64(words[2], e.count)) throw badHeader(path, "element line " + shown(line));
            e.name = std::string(words[1]);
            header.elements.push_back(e);
        } else if (key == "property") {
            if (header.elements.empty()) throw badHeader(path, "property before any element: " + shown(line));
            header.elements.back().props.push_back(plyProperty(path, words, line));
        } else if (key == "end_header") {
            break;
        } else {
            throw badHeader(path, "unexpected line " + shown(line));
        }
    }
    if (header.format == PlyFormat::None) throw badHeader(path, "no format line");
    return header;
}

/// Finds the vertex element and its x, y, z properties, and checks its point count.
void locateVertices(PlyBody &body) {
    const std::string &path = body.path;
    body.vertex = std::find_if(body.elements.begin(), body.elements.end(),
                               [](const PlyElement &e) { return e.name == "vertex"; });
    if (body.vertex == body.elements.end()) throw badHeader(path, "no vertex element");
    const PlyElement &vertex = *body.vertex;
    for (const PlyProperty &p : vertex.props)
        if (p.is_list)
            throw InputError(path, "the vertex element has a list property " + shown(p.name) +
                                       "; list properties in vertices are not supported");
    for (int a = 0; a < 3; ++a) {
        const auto it = std::find_if(vertex.props.begin(), vertex.props.end(),
                                     [&](const PlyProperty &p) { return p.name == kAxisNames[a]; });
        if (it == vertex.props.end())
            throw InputError(path, std::string("no ") + kAxisNames[a] + " property in the PLY vertex element");
        body.xyz[a] = static_cast<int>(it - vertex.props.begin());
    }
    if (vertex.count == 0) throw InputError(path, "the cloud has zero points");
    if (vertex.count > limits::kMaxCloudPoints)
        throw InputError(path, "cloud of " + std::to_string(vertex.count) + " points exceeds the limit of " +
                                   std::to_string(limits::kMaxCloudPoints) + " points");
}

/// ASCII: skips the elements stored before the vertices, token by token.
void skipAsciiElements(const PlyBody &body, Tokens &tokens) {
    std::string_view tok;
    for (auto e = body.elements.begin(); e != body.vertex; ++e) {
        if (e->props.empty()) continue;  // zero tokens per instance, whatever the count
        for (std::uint64_t i = 0; i < e->count; ++i)
            for (const PlyProperty &p : e->props) {
                if (!tokens.next(tok)) throw body.endsEarly(*e);
                if (!p.is_list) continue;
                std::uint64_t n = 0;
                if (!parseU64(tok, n))
                    throw InputError(body.path, "bad list length " + shown(tok) + " in element " + shown(e->name));
                for (std::uint64_t k = 0; k < n; ++k)
                    if (!tokens.next(tok)) throw body.endsEarly(*e);
            }
    }
}

void readAsciiVertices(const PlyBody &body, Cloud &cloud) {
    Tokens tokens{body.bytes, body.pos};
    skipAsciiElements(body, tokens);
    const PlyElement &vertex = *body.vertex;
    const std::size_t nprops = vertex.props.size();
    const std::size_t remaining = body.bytes.size() - tokens.pos;
    cloud.points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(vertex.count, remaining / (2 * nprops) + 1)));
    std::vector<std::string_view> values(nprops);
    for (std::uint64_t i = 0; i < vertex.count; ++i) {
        for (std::size_t k = 0; k < nprops; ++k)
            if (!tokens.next(values[k])) throw body.truncated("found " + std::to_string(i));
        Point p;
        for (int a = 0; a < 3; ++a) {
            double v;
            if (!parseDouble(values[body.xyz[a]], v))
                throw InputError(body.path, "vertex " + std::to_string(i) + ": " + kAxisNames[a] +
                                                " is not a number: " + shown(values[body.xyz[a]]));
            p[a] = toFloat(v);
        }
        cloud.points.push_back(p);
    }
}

/// Binary: one instance of an element that holds lists, property by property. Each instance
/// holds at least one list length byte, so the caller's loop ends with the data.
void skipBinaryInstance(const PlyBody &body, const PlyElement &e, std::size_t &pos, bool big) {
    const auto *data = reinterpret_cast<const unsigned char *>(body.bytes.data());
    const std::size_t end = body.bytes.size();
    for (const PlyProperty &p : e.props) {
        if (!p.is_list) {
            if (static_cast<std::size_t>(p.type.size) > end - pos) throw body.endsEarly(e);
            pos += p.type.size;
            continue;
        }
        if (static_cast<std::size_t>(p.count_type.size) > end - pos) throw body.endsEarly(e);
        const double n = decodeScalar(data + pos, p.count_type, big);
        pos += p.count_type.size;
        if (n < 0) throw InputError(body.path, "negative list length in element " + shown(e.name));
        if (n > static_cast<double>((end - pos) / p.type.size)) throw body.endsEarly(e);
        pos += static_cast<std::size_t>(n) * p.type.size;
    }
}

/// Binary: skips the elements stored before the vertices; returns the position of the vertices.
std::size_t skipBinaryElements(const PlyBody &body, bool big) {
    std::size_t pos = body.pos;
    const std::size_t end = body.bytes.size();
    for (auto e = body.elements.begin(); e != body.vertex; ++e) {
        const bool fixed =
            std::none_of(e->props.begin(), e->props.end(), [](const PlyProperty &p) { return p.is_list; });
        if (fixed) {
            std::uint64_t size = 0;
            for (const PlyProperty &p : e->props) size += p.type.size;
            if (size == 0) continue;
            if (e->count > (end - pos) / size) throw body.endsEarly(*e);
            pos += static_cast<std::size_t>(e->count * size);
            continue;
        }
        for (std::uint64_t i = 0; i < e->count; ++i) skipBinaryInstance(body, *e, pos, big);
    }
    return pos;
}

void readBinaryVertices(const PlyBody &body, bool big, Cloud &cloud) {
    const std::size_t pos = skipBinaryElements(body, big);
    const auto *data = reinterpret_cast<const unsigned char *>(body.bytes.data());
    const std::size_t end = body.bytes.size();
    const PlyElement &vertex = *body.vertex;
    std::uint64_t vertex_size = 0;
    std::vector<std::uint64_t> offset;
    for (const PlyProperty &p : vertex.props) {
        offset.push_back(vertex_size);
        vertex_size += p.type.size;
    }
    if (vertex.count > (end - pos) / vertex_size)
        throw body.truncated("needs " + std::to_string(vertex.count * vertex_size) +
                             " bytes of vertex data, the file has " + std::to_string(end - pos));
    cloud.points.resize(static_cast<std::size_t>(vertex.count));
    for (std::size_t i = 0; i < cloud.points.size(); ++i) {
        const unsigned char *v = data + pos + i * vertex_size;
        for (int a = 0; a < 3; ++a)
            cloud.points[i][a] = toFloat(decodeScalar(v + offset[body.xyz[a]], vertex.props[body.xyz[a]].type, big));
    }
}

}  // namespace

Cloud readPly(const std::string &path, const std::string &bytes) {
    std::size_t pos = 0;
    const PlyHeader header = readPlyHeader(path, bytes, pos);
    PlyBody body{path, bytes, pos, header.elements, header.elements.end(), {0, 0, 0}};
    locateVertices(body);
    Cloud cloud;
    if (header.format == PlyFormat::Ascii)
        readAsciiVertices(body, cloud);
    else
        readBinaryVertices(body, header.format == PlyFormat::Big, cloud);
    cloud.width = static_cast<int>(std::min<std::size_t>(cloud.points.size(), std::numeric_limits<int>::max()));
    cloud.height = 1;
    return cloud;
}

void writeCloudPly(const std::string &path, const Cloud &cloud) {
    const std::size_t n = countFinite(cloud);
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by projsurf\nelement vertex " +
                      std::to_string(n) + "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    out.reserve(out.size() + 12 * n);
    for (const Point &p : cloud.points)
        if (isFinite(p))
            for (int a = 0; a < 3; ++a) appendFloatLE(out, p[a]);
    writeFileAtomic(path, out);
}

}  // namespace projsurf
