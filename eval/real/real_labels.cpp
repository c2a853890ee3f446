#include "eval/real/real_labels.hpp"
#include "projsurf/io/yaml/yaml_numbers.hpp"

#include <yaml-cpp/yaml.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/io/yaml/yaml_tree.hpp"

namespace fs = std::filesystem;

namespace projsurf::eval {
namespace {

/// Reads keys of one file and names them in errors as "file: 'key.sub' ...".
struct Reader {
    std::string path;

    [[noreturn]] void fail(const std::string &problem) const { throw InputError(path, problem); }

    YAML::Node need(const YAML::Node &node, const std::string &key, const std::string &where) const {
        if (!node.IsMap() || !node[key]) fail("missing key '" + where + key + "'");
        return node[key];
    }
    double number(const YAML::Node &node, const std::string &what) const {
        double v = 0;
        try {
            v = node.as<double>();
        } catch (const YAML::Exception &) {
            fail("'" + what + "' is not a number");
        }
        if (!std::isfinite(v)) fail("'" + what + "' is not finite");
        return v;
    }
    std::string text(const YAML::Node &node, const std::string &what) const {
        if (!node.IsScalar()) fail("'" + what + "' must be a string");
        return node.as<std::string>();
    }
    Eigen::Vector3d vector3(const YAML::Node &node, const std::string &what) const {
        if (!node.IsSequence() || node.size() != 3) fail("'" + what + "' must be a list of 3 numbers");
        return {number(node[0], what), number(node[1], what), number(node[2], what)};
    }
    LabelPolygon polygon(const YAML::Node &node, const std::string &what) const {
        LabelPolygon p;
        p.name = node["name"] ? text(node["name"], what + ".name") : "";
        const YAML::Node pts = need(node, "polygon", what + ".");
        if (!pts.IsSequence() || pts.size() < 3)
            fail("'" + what + ".polygon' must be a list of at least 3 [x, y] pixels");
        for (const auto &xy : pts) {
            if (!xy.IsSequence() || xy.size() != 2) fail("'" + what + ".polygon' must be a list of [x, y] pixels");
            p.pixels.emplace_back(number(xy[0], what + ".polygon"), number(xy[1], what + ".polygon"));
            // Depth images are at most 16384 px a side: a vertex far beyond is a typo, and 1e300
            // overflows the rasterised polygon.
            if (std::abs(p.pixels.back().x()) > 1e5 || std::abs(p.pixels.back().y()) > 1e5)
                fail("'" + what + ".polygon' has a vertex more than 100000 px from the image");
        }
        return p;
    }
};

/// Label numbers carry 7 significant digits (labels/remake.sh rebuilds them byte for byte).
YAML::Node num(double v) { return yamlNumber(v, 7); }
YAML::Node flow(std::initializer_list<double> v) { return yamlNumbers(v, 7); }

YAML::Node polygonNode(const LabelPolygon &p) {
    YAML::Node n;
    if (!p.name.empty()) n["name"] = p.name;
    YAML::Node pts;
    for (const auto &xy : p.pixels) pts.push_back(flow({xy.x(), xy.y()}));
    pts.SetStyle(YAML::EmitterStyle::Flow);
    n["polygon"] = pts;
    return n;
}

LabelBest readBest(const Reader &r, const YAML::Node &b, const std::string &key, const RealLabel &l) {
    LabelBest best;
    try {
        best.found = r.need(b, "found", key + ".").as<bool>();
    } catch (const YAML::Exception &) {
        r.fail("'" + key + ".found' must be true or false");
    }
    if (!best.found) return best;
    best.surface = r.text(r.need(b, "surface", key + "."), key + ".surface");
    if (std::none_of(l.surfaces.begin(), l.surfaces.end(),
                     [&](const LabelSurface &s) { return s.name == best.surface; }))
        r.fail("'" + key + ".surface' names no surface: '" + best.surface + "'");
    best.width = r.number(r.need(b, "width", key + "."), key + ".width");
    best.height = r.number(r.need(b, "height", key + "."), key + ".height");
    if (!(best.width > 0 && best.height > 0)) r.fail("'" + key + ".width' and '" + key + ".height' must be positive");
    const YAML::Node c = r.need(b, "corners", key + ".");
    if (!c.IsSequence() || c.size() != 4) r.fail("'" + key + ".corners' must be a list of 4 [x, y, z] points");
    for (int k = 0; k < 4; ++k) best.corners[k] = r.vector3(c[k], key + ".corners");
    return best;
}

void writeBest(YAML::Node node, const LabelBest &b) {
    node["found"] = b.found;
    if (!b.found) return;
    node["surface"] = b.surface;
    node["width"] = num(b.width);
    node["height"] = num(b.height);
    node["area"] = num(b.area());  // for the reader's eye; not read back
    for (const auto &c : b.corners) node["corners"].push_back(flow({c.x(), c.y(), c.z()}));
}

/// A gravity block `key` {source, vector}: the source one of `sources`, the vector non-zero
/// (returned unit).
void readGravity(const Reader &r, const YAML::Node &node, const std::string &key,
                 const std::vector<std::string> &sources, std::string &source, Eigen::Vector3d &vector) {
    source = r.text(r.need(node, "source", key + "."), key + ".source");
    if (std::find(sources.begin(), sources.end(), source) == sources.end())
        r.fail("'" + key + ".source' must be '" + sources[0] + "' or '" + sources[1] + "'");
    vector = r.vector3(r.need(node, "vector", key + "."), key + ".vector");
    if (vector.norm() < 1e-6) r.fail("'" + key + ".vector' is the zero vector");
    vector.normalize();
}

/// The optional key's text, which must be one of `allowed`; "" when the key is absent.
std::string oneOf(const Reader &r, const YAML::Node &root, const std::string &key,
                  const std::vector<std::string> &allowed) {
    if (!root[key]) return "";
    const std::string value = r.text(root[key], key);
    if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return value;
    std::string names;
    for (const std::string &a : allowed) names += (names.empty() ? "" : ", ") + a;
    r.fail("'" + key + "' must be one of " + names + " (got '" + value + "')");
}

}  // namespace

const std::vector<std::string> &unsuitableReasons() {
    static const std::vector<std::string> reasons{"textured", "dark", "saturated", "glare"};
    return reasons;
}

const std::vector<std::string> &splitSides() {
    static const std::vector<std::string> sides{"tune", "check"};
    return sides;
}

const std::vector<std::string> &sensorFamilies() {
    static const std::vector<std::string> families{"structured_light", "time_of_flight", "stereo"};
    return families;
}

namespace {

/// A label kept in a half's folder (labels/real/tune/, check/) says that half: a frame moved
/// between halves is moved in both places.
void checkHalfFolder(const Reader &r, const std::string &split) {
    const std::string folder = fs::path(r.path).parent_path().filename().string();
    for (const std::string &side : splitSides())
        if (folder == side && split != side)
            r.fail((split.empty() ? "no 'split'" : "'split' is '" + split + "'") + " but the file is in the folder " +
                   side + "/");
}

}  // namespace

RealLabel readRealLabel(const std::string &path) {
    // As every YAML file: bounded size and nesting, one document, no alias cycle, no key twice.
    const YAML::Node root = loadCheckedYaml(path, readSmallTextFile(path, limits::kMaxSettingsYamlBytes, "YAML"));
    const Reader r{path};
    if (!root.IsMap()) r.fail("expected a YAML mapping at the top level");
    RealLabel l;
    l.frame = r.text(r.need(root, "frame", ""), "frame");
    if (l.frame.empty()) r.fail("'frame' is empty");
    if (l.frame.find('/') != std::string::npos || l.frame == "." || l.frame == "..")
        r.fail("'frame' must be the name of one folder of the real frames, not a path");
    if (root["note"]) l.note = r.text(root["note"], "note");
    l.split = oneOf(r, root, "split", splitSides());
    checkHalfFolder(r, l.split);
    if (root["scene"]) l.scene = r.text(root["scene"], "scene");
    l.sensor = oneOf(r, root, "sensor", sensorFamilies());

    const YAML::Node g = r.need(root, "gravity", "");
    readGravity(r, g, "gravity", {"auto", "stated"}, l.gravity_source, l.gravity);
    if (g["reference"])
        readGravity(r, g["reference"], "gravity.reference", {"floor_fit", "walls"}, l.reference_gravity_source,
                    l.reference_gravity);

    l.projector = readCalibration(path);  // the `projector:` block, as in a calibration file

    const YAML::Node surfaces = r.need(root, "surfaces", "");
    if (!surfaces.IsSequence()) r.fail("'surfaces' must be a list (empty when no wall is usable)");
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        const std::string where = "surfaces[" + std::to_string(i) + "]";
        LabelSurface s;
        s.name = r.text(r.need(surfaces[i], "name", where + "."), where + ".name");
        const YAML::Node regions = r.need(surfaces[i], "regions", where + ".");
        if (!regions.IsSequence() || regions.size() == 0) r.fail("'" + where + ".regions' must be a non-empty list");
        for (std::size_t k = 0; k < regions.size(); ++k)
            s.regions.push_back(r.polygon(regions[k], where + ".regions[" + std::to_string(k) + "]"));
        if (surfaces[i]["plane"]) {
            const YAML::Node p = surfaces[i]["plane"];
            if (!p.IsSequence() || p.size() != 4) r.fail("'" + where + ".plane' must be [nx, ny, nz, d]");
            const Eigen::Vector3d n(r.number(p[0], where + ".plane"), r.number(p[1], where + ".plane"),
                                    r.number(p[2], where + ".plane"));
            if (n.norm() < 1e-6) r.fail("'" + where + ".plane' has a zero normal");
            s.plane = makePlane(n, r.number(p[3], where + ".plane"));
            s.has_plane = true;
        }
        for (const auto &other : l.surfaces)
            if (other.name == s.name) r.fail("two surfaces are named '" + s.name + "'");
        l.surfaces.push_back(std::move(s));
    }
    if (root["obstacles"]) {
        const YAML::Node obstacles = root["obstacles"];
        if (!obstacles.IsSequence()) r.fail("'obstacles' must be a list");
        for (std::size_t i = 0; i < obstacles.size(); ++i)
            l.obstacles.push_back(r.polygon(obstacles[i], "obstacles[" + std::to_string(i) + "]"));
    }
    if (root["best"]) l.best = readBest(r, root["best"], "best", l);
    if (root["colour"]) {
        const YAML::Node c = root["colour"];
        if (!c.IsMap()) r.fail("'colour' must be a mapping with 'unsuitable' (a list, empty when nothing is)");
        l.colour.judged = true;
        if (c["note"]) l.colour.note = r.text(c["note"], "colour.note");
        const YAML::Node u = r.need(c, "unsuitable", "colour.");
        if (!u.IsSequence()) r.fail("'colour.unsuitable' must be a list (empty when nothing is unsuitable)");
        for (std::size_t i = 0; i < u.size(); ++i) {
            const std::string where = "colour.unsuitable[" + std::to_string(i) + "]";
            LabelUnsuitable item;
            item.polygon = r.polygon(u[i], where);
            item.why = r.text(r.need(u[i], "why", where + "."), where + ".why");
            const auto &ok = unsuitableReasons();
            if (std::find(ok.begin(), ok.end(), item.why) == ok.end())
                r.fail("'" + where + ".why' must be one of textured, dark, saturated, glare (got '" + item.why + "')");
            l.colour.unsuitable.push_back(std::move(item));
        }
        if (c["best"]) l.colour.best = readBest(r, c["best"], "colour.best", l);
    }
    return l;
}

void writeRealLabel(const std::string &path, const RealLabel &l) {
    YAML::Node root;
    root["frame"] = l.frame;
    if (!l.split.empty()) root["split"] = l.split;
    if (!l.scene.empty()) root["scene"] = l.scene;
    if (!l.sensor.empty()) root["sensor"] = l.sensor;
    if (!l.note.empty()) root["note"] = l.note;
    root["gravity"]["source"] = l.gravity_source.empty() ? std::string("stated") : l.gravity_source;
    root["gravity"]["vector"] = flow({l.gravity.x(), l.gravity.y(), l.gravity.z()});
    if (!l.reference_gravity_source.empty()) {
        root["gravity"]["reference"]["source"] = l.reference_gravity_source;
        const Eigen::Vector3d &g = l.reference_gravity;
        root["gravity"]["reference"]["vector"] = flow({g.x(), g.y(), g.z()});
    }
    const Projector &p = l.projector;
    root["projector"]["resolution"] = flow({static_cast<double>(p.width), static_cast<double>(p.height)});
    root["projector"]["fov_deg"] = flow({p.fov_h * 180.0 / M_PI, p.fov_v * 180.0 / M_PI});
    root["projector"]["axis"]["origin"] = flow({p.origin.x(), p.origin.y(), p.origin.z()});
    const Eigen::Vector3d d = p.direction.normalized();
    root["projector"]["axis"]["direction"] = flow({d.x(), d.y(), d.z()});
    YAML::Node surfaces(YAML::NodeType::Sequence);
    for (const auto &s : l.surfaces) {
        YAML::Node n;
        n["name"] = s.name;
        for (const auto &p : s.regions) n["regions"].push_back(polygonNode(p));
        if (s.has_plane) n["plane"] = flow({s.plane.normal.x(), s.plane.normal.y(), s.plane.normal.z(), s.plane.d});
        surfaces.push_back(n);
    }
    root["surfaces"] = surfaces;
    YAML::Node obstacles(YAML::NodeType::Sequence);
    for (const auto &p : l.obstacles) obstacles.push_back(polygonNode(p));
    root["obstacles"] = obstacles;
    writeBest(root["best"], l.best);
    if (l.colour.judged) {
        if (!l.colour.note.empty()) root["colour"]["note"] = l.colour.note;
        YAML::Node unsuitable(YAML::NodeType::Sequence);
        for (const auto &u : l.colour.unsuitable) {
            YAML::Node n = polygonNode(u.polygon);
            YAML::Node item;
            item["name"] = u.polygon.name;
            item["why"] = u.why;
            item["polygon"] = n["polygon"];
            unsuitable.push_back(item);
        }
        root["colour"]["unsuitable"] = unsuitable;
        writeBest(root["colour"]["best"], l.colour.best);
    }
    YAML::Emitter out;
    out.SetDoublePrecision(6);
    out << root;
    writeFileAtomic(path, std::string(out.c_str()) + "\n");
}

std::vector<std::string> listLabelFiles(const std::string &dir) {
    std::vector<std::string> out;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return out;
    // The folder itself and its sub-folders one level down (the repository keeps its halves in
    // tune/ and check/); ordered by frame, wherever its file is.
    const auto add = [&](const fs::path &folder) {
        for (const auto &e : fs::directory_iterator(folder, ec))
            if (e.is_regular_file(ec) && e.path().extension() == ".yaml") out.push_back(e.path().string());
    };
    add(dir);
    for (const auto &e : fs::directory_iterator(dir, ec))
        if (e.is_directory(ec)) add(e.path());
    std::sort(out.begin(), out.end(), [](const std::string &a, const std::string &b) {
        return std::make_pair(fs::path(a).filename(), a) < std::make_pair(fs::path(b).filename(), b);
    });
    return out;
}

}  // namespace projsurf::eval
