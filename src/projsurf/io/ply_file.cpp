#include "projsurf/io/ply_file.hpp"
#include "projsurf/io/cloud_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string_view>
#include <vector>

#include "projsurf/io/cloud_format_parsing.hpp"
#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/limits.hpp"

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

}  // namespace

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
            if (words[1] == "ascii")
                format = Format::Ascii;
            else if (words[1] == "binary_little_endian")
                format = Format::Little;
            else if (words[1] == "binary_big_endian")
                format = Format::Big;
            else
                throw bad("unknown format " + shown(words[1]));
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
    const auto vit =
        std::find_if(elements.begin(), elements.end(), [](const PlyElement &e) { return e.name == "vertex"; });
    if (vit == elements.end()) throw bad("no vertex element");
    const PlyElement &vertex = *vit;
    int xyz[3];
    const char *axis_names[3] = {"x", "y", "z"};
    for (const PlyProperty &p : vertex.props)
        if (p.is_list)
            throw InputError(path, "the vertex element has a list property " + shown(p.name) +
                                       "; list properties in vertices are not supported");
    for (int a = 0; a < 3; ++a) {
        const auto it = std::find_if(vertex.props.begin(), vertex.props.end(),
                                     [&](const PlyProperty &p) { return p.name == axis_names[a]; });
        if (it == vertex.props.end())
            throw InputError(path, std::string("no ") + axis_names[a] + " property in the PLY vertex element");
        xyz[a] = static_cast<int>(it - vertex.props.begin());
    }
    if (vertex.count == 0) throw InputError(path, "the cloud has zero points");
    if (vertex.count > limits::kMaxCloudPoints)
        throw InputError(path, "cloud of " + std::to_string(vertex.count) + " points exceeds the limit of " +
                                   std::to_string(limits::kMaxCloudPoints) + " points");
    auto truncated = [&](const std::string &detail) {
        return InputError(
            path, "truncated data: the header promises " + std::to_string(vertex.count) + " vertices; " + detail);
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
                    if (!parseU64(tok, n))
                        throw InputError(path, "bad list length " + shown(tok) + " in element " + shown(e->name));
                    for (std::uint64_t k = 0; k < n; ++k)
                        if (!tokens.next(tok)) throw truncated("element " + shown(e->name) + " ends early");
                }
        }
        const std::size_t nprops = vertex.props.size();
        const std::size_t remaining = bytes.size() - tokens.pos;
        cloud.points.reserve(
            static_cast<std::size_t>(std::min<std::uint64_t>(vertex.count, remaining / (2 * nprops) + 1)));
        std::vector<std::string_view> values(nprops);
        for (std::uint64_t i = 0; i < vertex.count; ++i) {
            for (std::size_t k = 0; k < nprops; ++k)
                if (!tokens.next(values[k])) throw truncated("found " + std::to_string(i));
            Point p;
            for (int a = 0; a < 3; ++a) {
                double v;
                if (!parseDouble(values[xyz[a]], v))
                    throw InputError(path, "vertex " + std::to_string(i) + ": " + axis_names[a] +
                                               " is not a number: " + shown(values[xyz[a]]));
                p[a] = toFloat(v);
            }
            cloud.points.push_back(p);
        }
    } else {
        const bool big = format == Format::Big;
        const auto *data = reinterpret_cast<const unsigned char *>(bytes.data());
        const std::size_t end = bytes.size();
        for (auto e = elements.begin(); e != vit; ++e) {
            const bool fixed =
                std::none_of(e->props.begin(), e->props.end(), [](const PlyProperty &p) { return p.is_list; });
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
                        if (static_cast<std::size_t>(p.type.size) > end - pos)
                            throw truncated("element " + shown(e->name) + " ends early");
                        pos += p.type.size;
                        continue;
                    }
                    if (static_cast<std::size_t>(p.count_type.size) > end - pos)
                        throw truncated("element " + shown(e->name) + " ends early");
                    const double n = decodeScalar(data + pos, p.count_type, big);
                    pos += p.count_type.size;
                    if (n < 0) throw InputError(path, "negative list length in element " + shown(e->name));
                    if (n > static_cast<double>((end - pos) / p.type.size))
                        throw truncated("element " + shown(e->name) + " ends early");
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
            throw truncated("needs " + std::to_string(vertex.count * vertex_size) +
                            " bytes of vertex data, the file has " + std::to_string(end - pos));
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
