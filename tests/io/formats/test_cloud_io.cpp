// Point-cloud file I/O: PCD/PLY round trips against PCL's writers, hand-written files PCL
// mishandles (double x/y/z, COUNT > 1), every kind of bad input, the real depth frame, and
// random mutations that must load or throw InputError, never crash.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <pcl/io/lzf.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

using namespace projsurf;

namespace {

std::string freshDir() {
    std::string templ = "/tmp/projsurf_cloud_io_XXXXXX";
    if (!::mkdtemp(templ.data())) throw std::runtime_error("mkdtemp failed");
    return templ;
}

void writeBytes(const std::string &path, const std::string &bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string readBytes(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

template <typename T>
void appendLE(std::string &out, T value) {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));  // the test machine is little-endian (x86/arm)
    out.append(b, sizeof(T));
}

template <typename T>
void appendBE(std::string &out, T value) {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    for (int i = static_cast<int>(sizeof(T)) - 1; i >= 0; --i) out.push_back(b[i]);
}

/// Random points in a camera-like volume; `nan_every` > 0 makes every n-th point NaN.
template <typename PointT>
pcl::PointCloud<PointT> randomCloud(int width, int height, int nan_every, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> xy(-3.0f, 3.0f), z(0.3f, 8.0f);
    pcl::PointCloud<PointT> c;
    c.width = static_cast<std::uint32_t>(width);
    c.height = static_cast<std::uint32_t>(height);
    c.is_dense = nan_every == 0;
    c.points.resize(static_cast<std::size_t>(width) * height);
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        PointT &p = c.points[i];
        if (nan_every > 0 && i % nan_every == 1) {
            p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
        } else {
            p.x = xy(rng);
            p.y = xy(rng);
            p.z = z(rng);
        }
    }
    return c;
}

/// Same points (NaN where NaN, equal within `rel` elsewhere) and the same organization.
template <typename PointT>
void expectSameCloud(const Cloud &got, const pcl::PointCloud<PointT> &ref, double rel, bool organized) {
    ASSERT_EQ(got.size(), ref.points.size());
    if (organized) {
        EXPECT_TRUE(got.organized());
        EXPECT_EQ(got.width, static_cast<int>(ref.width));
        EXPECT_EQ(got.height, static_cast<int>(ref.height));
    } else {
        EXPECT_FALSE(got.organized());
        EXPECT_EQ(got.width, static_cast<int>(got.size()));
        EXPECT_EQ(got.height, 1);
    }
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        const float r[3] = {ref.points[i].x, ref.points[i].y, ref.points[i].z};
        for (int a = 0; a < 3; ++a) {
            const float g = got.points[i][a];
            const bool ok =
                std::isnan(r[a]) ? std::isnan(g) : std::abs(g - r[a]) <= rel * std::max(1.0f, std::abs(r[a]));
            if (!ok && ++mismatches <= 5)
                ADD_FAILURE() << "point " << i << " axis " << a << ": got " << g << ", expected " << r[a];
        }
    }
    EXPECT_EQ(mismatches, 0u);
}

/// Runs `fn`, expects InputError whose message names `path` (and contains `needle`).
void expectInputError(const std::function<void()> &fn, const std::string &path, const std::string &needle = "") {
    try {
        fn();
        ADD_FAILURE() << "no InputError for " << path;
    } catch (const InputError &e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(path), std::string::npos) << msg;
        if (!needle.empty()) {
            EXPECT_NE(msg.find(needle), std::string::npos) << msg;
        }
    }
}

void expectCloudError(const std::string &path, const std::string &needle = "") {
    expectInputError([&] { readCloud(path); }, path, needle);
}

std::string pcdHeader(const std::string &fields, const std::string &size, const std::string &type,
                      const std::string &count, std::uint64_t width, std::uint64_t height, std::uint64_t points,
                      const std::string &data) {
    std::ostringstream h;
    h << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " << fields << "\nSIZE " << size << "\nTYPE "
      << type << "\nCOUNT " << count << "\nWIDTH " << width << "\nHEIGHT " << height
      << "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << points << "\nDATA " << data << "\n";
    return h.str();
}

/// A small valid binary PCD of n points (x y z float) as bytes.
std::string smallBinaryPcd(int n) {
    std::string s = pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", n, 1, n, "binary");
    for (int i = 0; i < n; ++i) {
        appendLE(s, 0.1f * i);
        appendLE(s, -0.2f * i);
        appendLE(s, 1.0f + 0.01f * i);
    }
    return s;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// PCD round trips against PCL's writers
// ---------------------------------------------------------------------------------------

TEST(CloudIoPcd, RoundTripEveryFormatOrganizedOrNotWithNaNs) {
    const std::string dir = freshDir();
    struct Case {
        int w, h, nan_every;
    };
    const Case cases[] = {{37, 1, 0}, {53, 1, 7}, {32, 24, 0}, {32, 24, 5}};
    unsigned seed = 1;
    for (const Case &c : cases) {
        const auto ref = randomCloud<pcl::PointXYZ>(c.w, c.h, c.nan_every, seed++);
        const std::string base = dir + "/c" + std::to_string(seed);
        ASSERT_EQ(pcl::io::savePCDFileASCII(base + "_ascii.pcd", ref), 0);
        ASSERT_EQ(pcl::io::savePCDFileBinary(base + "_bin.pcd", ref), 0);
        ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(base + "_lzf.PCD", ref), 0);  // extension in any case
        SCOPED_TRACE(std::to_string(c.w) + "x" + std::to_string(c.h) + " nan_every " + std::to_string(c.nan_every));
        expectSameCloud(readCloud(base + "_ascii.pcd"), ref, 1e-6, c.h > 1);  // ascii: 8 significant digits
        expectSameCloud(readCloud(base + "_bin.pcd"), ref, 0.0, c.h > 1);
        expectSameCloud(readCloud(base + "_lzf.PCD"), ref, 0.0, c.h > 1);
    }
}

TEST(CloudIoPcd, ExtraFieldsRgbAndNormalsEveryFormat) {
    const std::string dir = freshDir();
    auto ref = randomCloud<pcl::PointXYZRGBNormal>(20, 10, 9, 42);
    for (std::size_t i = 0; i < ref.points.size(); ++i) {
        ref.points[i].r = static_cast<std::uint8_t>(i);
        ref.points[i].g = 7;
        ref.points[i].b = 200;
        ref.points[i].normal_x = 0.6f;
        ref.points[i].normal_y = 0.0f;
        ref.points[i].normal_z = -0.8f;
        ref.points[i].curvature = 0.01f * i;
    }
    ASSERT_EQ(pcl::io::savePCDFileASCII(dir + "/a.pcd", ref), 0);
    ASSERT_EQ(pcl::io::savePCDFileBinary(dir + "/b.pcd", ref), 0);
    ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(dir + "/c.pcd", ref), 0);
    // The files really carry the extra fields, in front of or after x y z.
    EXPECT_NE(readBytes(dir + "/b.pcd").find("normal_x"), std::string::npos);
    EXPECT_NE(readBytes(dir + "/b.pcd").find("rgb"), std::string::npos);
    expectSameCloud(readCloud(dir + "/a.pcd"), ref, 1e-6, true);
    expectSameCloud(readCloud(dir + "/b.pcd"), ref, 0.0, true);
    expectSameCloud(readCloud(dir + "/c.pcd"), ref, 0.0, true);
}

// ---------------------------------------------------------------------------------------
// Hand-written PCDs: COUNT > 1, x/y/z as doubles and integers, fields before x
// ---------------------------------------------------------------------------------------

TEST(CloudIoPcd, CountGreaterThanOneFieldsAsciiBinaryCompressed) {
    const std::string dir = freshDir();
    // A 4-float descriptor and a 3-ushort field around x y z shift every offset.
    const std::string fields = "desc x label y z rgb3", size = "4 4 2 4 4 1", type = "F F U F F U",
                      count = "4 1 1 1 1 3";
    const int n = 6;
    pcl::PointCloud<pcl::PointXYZ> ref;
    for (int i = 0; i < n; ++i) ref.push_back(pcl::PointXYZ(0.5f * i, -1.25f * i, 2.0f + i));
    std::string ascii = pcdHeader(fields, size, type, count, n, 1, n, "ascii");
    std::string binary = pcdHeader(fields, size, type, count, n, 1, n, "binary");
    std::vector<std::string> soa(6);  // field-major blocks for binary_compressed
    for (int i = 0; i < n; ++i) {
        const auto &p = ref.points[i];
        ascii +=
            "9 9 9 9 " + std::to_string(p.x) + " 65535 " + std::to_string(p.y) + " " + std::to_string(p.z) + " 1 2 3\n";
        std::string desc, label, rgb;
        for (int k = 0; k < 4; ++k) appendLE(desc, 9.0f);
        appendLE<std::uint16_t>(label, 65535);
        rgb = "\x01\x02\x03";
        std::string x, y, z;
        appendLE(x, p.x);
        appendLE(y, p.y);
        appendLE(z, p.z);
        binary += desc + x + label + y + z + rgb;
        soa[0] += desc, soa[1] += x, soa[2] += label, soa[3] += y, soa[4] += z, soa[5] += rgb;
    }
    std::string raw;
    for (const auto &block : soa) raw += block;
    std::vector<char> compressed(raw.size() * 2 + 64);
    const unsigned csize = pcl::lzfCompress(raw.data(), static_cast<unsigned>(raw.size()), compressed.data(),
                                            static_cast<unsigned>(compressed.size()));
    ASSERT_GT(csize, 0u);
    std::string lzf = pcdHeader(fields, size, type, count, n, 1, n, "binary_compressed");
    appendLE<std::uint32_t>(lzf, csize);
    appendLE<std::uint32_t>(lzf, static_cast<std::uint32_t>(raw.size()));
    lzf.append(compressed.data(), csize);
    writeBytes(dir + "/a.pcd", ascii);
    writeBytes(dir + "/b.pcd", binary);
    writeBytes(dir + "/c.pcd", lzf);
    expectSameCloud(readCloud(dir + "/a.pcd"), ref, 1e-6, false);
    expectSameCloud(readCloud(dir + "/b.pcd"), ref, 0.0, false);
    expectSameCloud(readCloud(dir + "/c.pcd"), ref, 0.0, false);
}

TEST(CloudIoPcd, DoubleXyzBinaryAsciiCompressedOrganized) {
    const std::string dir = freshDir();
    const int w = 4, h = 3;
    std::vector<double> xs, ys, zs;
    for (int i = 0; i < w * h; ++i) {
        xs.push_back(i == 5 ? std::nan("") : 0.123456789 * i);
        ys.push_back(i == 5 ? std::nan("") : -0.5 * i);
        zs.push_back(i == 5 ? std::nan("") : 1.0 + 0.25 * i);
    }
    std::string bin = pcdHeader("x y z intensity", "8 8 8 4", "F F F F", "1 1 1 1", w, h, w * h, "binary");
    std::string asc = pcdHeader("x y z intensity", "8 8 8 4", "F F F F", "1 1 1 1", w, h, w * h, "ascii");
    std::string raw;
    for (int i = 0; i < w * h; ++i) {
        appendLE(bin, xs[i]);
        appendLE(bin, ys[i]);
        appendLE(bin, zs[i]);
        appendLE(bin, 0.5f);
        std::ostringstream line;
        line.precision(17);
        line << xs[i] << " " << ys[i] << " " << zs[i] << " 0.5\n";
        asc += line.str();
    }
    for (const auto *v : {&xs, &ys, &zs})
        for (double d : *v) appendLE(raw, d);
    for (int i = 0; i < w * h; ++i) appendLE(raw, 0.5f);
    std::vector<char> compressed(raw.size() * 2 + 64);
    const unsigned csize = pcl::lzfCompress(raw.data(), static_cast<unsigned>(raw.size()), compressed.data(),
                                            static_cast<unsigned>(compressed.size()));
    ASSERT_GT(csize, 0u);
    std::string lzf = pcdHeader("x y z intensity", "8 8 8 4", "F F F F", "1 1 1 1", w, h, w * h, "binary_compressed");
    appendLE<std::uint32_t>(lzf, csize);
    appendLE<std::uint32_t>(lzf, static_cast<std::uint32_t>(raw.size()));
    lzf.append(compressed.data(), csize);
    writeBytes(dir + "/bin.pcd", bin);
    writeBytes(dir + "/asc.pcd", asc);
    writeBytes(dir + "/lzf.pcd", lzf);
    pcl::PointCloud<pcl::PointXYZ> ref;
    ref.width = w;
    ref.height = h;
    for (int i = 0; i < w * h; ++i)
        ref.points.push_back(
            pcl::PointXYZ(static_cast<float>(xs[i]), static_cast<float>(ys[i]), static_cast<float>(zs[i])));
    for (const char *name : {"/bin.pcd", "/asc.pcd", "/lzf.pcd"}) {
        SCOPED_TRACE(name);
        expectSameCloud(readCloud(dir + name), ref, 1e-7, true);
    }
}

TEST(CloudIoPcd, IntegerXyzAreConverted) {
    const std::string dir = freshDir();
    std::string s = pcdHeader("x y z", "2 1 4", "I U I", "1 1 1", 2, 1, 2, "binary");
    appendLE<std::int16_t>(s, -300);
    s.push_back(static_cast<char>(250));
    appendLE<std::int32_t>(s, 7);
    appendLE<std::int16_t>(s, 12);
    s.push_back(0);
    appendLE<std::int32_t>(s, -70000);
    writeBytes(dir + "/i.pcd", s);
    const Cloud c = readCloud(dir + "/i.pcd");
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c.points[0], Point(-300, 250, 7));
    EXPECT_EQ(c.points[1], Point(12, 0, -70000));
}

// ---------------------------------------------------------------------------------------
// PLY
// ---------------------------------------------------------------------------------------

TEST(CloudIoPly, RoundTripPclAsciiAndBinary) {
    const std::string dir = freshDir();
    const auto ref = randomCloud<pcl::PointXYZ>(123, 1, 0, 9);
    ASSERT_EQ(pcl::io::savePLYFileASCII(dir + "/a.ply", ref), 0);
    ASSERT_EQ(pcl::io::savePLYFileBinary(dir + "/b.PLY", ref), 0);
    expectSameCloud(readCloud(dir + "/a.ply"), ref, 1e-6, false);
    expectSameCloud(readCloud(dir + "/b.PLY"), ref, 0.0, false);
}

TEST(CloudIoPly, DoublesBothEndiansAsciiAndSkippedElements) {
    const std::string dir = freshDir();
    const double pts[3][3] = {{0.1, 0.2, 1.5}, {-1.0, 2.5, 3.25}, {1e-3, -4.0, 9.5}};
    // An element before the vertices (with a list) must be skipped; faces after are ignored.
    const std::string head_elem = "element meta 2\nproperty uchar tag\nproperty list uchar int ids\n";
    const std::string vertex =
        "element vertex 3\nproperty uchar red\nproperty double x\nproperty float64 y\nproperty double z\n";
    const std::string face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    auto body = [&](bool big) {
        std::string s;
        auto put = [&](auto v) { big ? appendBE(s, v) : appendLE(s, v); };
        put(std::uint8_t{1}), put(std::uint8_t{2}), put(std::int32_t{10}), put(std::int32_t{11});  // meta 0
        put(std::uint8_t{3}), put(std::uint8_t{0});                                                // meta 1: empty list
        for (const auto &p : pts) put(std::uint8_t{255}), put(p[0]), put(p[1]), put(p[2]);
        put(std::uint8_t{3}), put(std::int32_t{0}), put(std::int32_t{1}), put(std::int32_t{2});
        return s;
    };
    writeBytes(dir + "/le.ply",
               "ply\nformat binary_little_endian 1.0\ncomment hand made\n" + head_elem + vertex + face + body(false));
    writeBytes(dir + "/be.ply", "ply\nformat binary_big_endian 1.0\n" + head_elem + vertex + face + body(true));
    std::ostringstream asc;
    asc.precision(17);
    asc << "ply\r\nformat ascii 1.0\r\n" << head_elem << vertex << face << "1 2 10 11\n3 0\n";
    for (const auto &p : pts) asc << "255 " << p[0] << " " << p[1] << " " << p[2] << "\n";
    asc << "3 0 1 2\n";
    writeBytes(dir + "/asc.ply", asc.str());
    pcl::PointCloud<pcl::PointXYZ> ref;
    for (const auto &p : pts)
        ref.push_back(pcl::PointXYZ(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])));
    for (const char *name : {"/le.ply", "/be.ply", "/asc.ply"}) {
        SCOPED_TRACE(name);
        expectSameCloud(readCloud(dir + name), ref, 1e-7, false);
    }
}

// ---------------------------------------------------------------------------------------
// Our writers: read back by us and by PCL
// ---------------------------------------------------------------------------------------

TEST(CloudIoWrite, PcdOrganizedAndPlyRoundTrip) {
    const std::string dir = freshDir();
    const auto ref = randomCloud<pcl::PointXYZ>(16, 9, 4, 5);
    Cloud cloud;
    cloud.width = 16;
    cloud.height = 9;
    for (const auto &p : ref.points) cloud.points.emplace_back(p.x, p.y, p.z);
    writeCloudPcd(dir + "/o.pcd", cloud);
    expectSameCloud(readCloud(dir + "/o.pcd"), ref, 0.0, true);
    pcl::PointCloud<pcl::PointXYZ> by_pcl;
    ASSERT_EQ(pcl::io::loadPCDFile(dir + "/o.pcd", by_pcl), 0);
    EXPECT_EQ(by_pcl.width, 16u);
    EXPECT_EQ(by_pcl.height, 9u);
    ASSERT_EQ(by_pcl.size(), ref.size());
    for (std::size_t i = 0; i < ref.size(); ++i)
        if (std::isfinite(ref.points[i].x)) {
            EXPECT_EQ(by_pcl.points[i].z, ref.points[i].z);
        }

    // PLY keeps only finite points, in order.
    writeCloudPly(dir + "/o.ply", cloud);
    const Cloud back = readCloud(dir + "/o.ply");
    pcl::PointCloud<pcl::PointXYZ> finite;
    for (const auto &p : ref.points)
        if (std::isfinite(p.x)) finite.push_back(p);
    expectSameCloud(back, finite, 0.0, false);
    pcl::PointCloud<pcl::PointXYZ> ply_by_pcl;
    ASSERT_EQ(pcl::io::loadPLYFile(dir + "/o.ply", ply_by_pcl), 0);
    EXPECT_EQ(ply_by_pcl.size(), finite.size());

    // Unorganized clouds are written unorganized; no temp file is left behind.
    Cloud flat = cloud;
    flat.width = static_cast<int>(flat.size());
    flat.height = 1;
    writeCloudPcd(dir + "/f.pcd", flat);
    EXPECT_FALSE(readCloud(dir + "/f.pcd").organized());
    int files = 0;
    for (const auto &e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 3);
}

// ---------------------------------------------------------------------------------------
// Bad inputs: InputError naming the file, never a crash
// ---------------------------------------------------------------------------------------

TEST(CloudIoBadInput, MissingEmptyGarbageAndWrongExtension) {
    const std::string dir = freshDir();
    expectCloudError(dir + "/missing.pcd", "no such file");
    expectCloudError(dir + "/missing.ply", "no such file");
    writeBytes(dir + "/empty.pcd", "");
    writeBytes(dir + "/empty.ply", "");
    expectCloudError(dir + "/empty.pcd", "empty");
    expectCloudError(dir + "/empty.ply", "empty");
    std::mt19937 rng(3);
    std::string garbage(4096, '\0');
    for (char &c : garbage) c = static_cast<char>(rng());
    writeBytes(dir + "/garbage.pcd", garbage);
    writeBytes(dir + "/garbage.ply", garbage);
    expectCloudError(dir + "/garbage.pcd", "malformed PCD header");
    expectCloudError(dir + "/garbage.ply", "malformed PLY header");
    writeBytes(dir + "/cloud.xyz", smallBinaryPcd(3));
    expectCloudError(dir + "/cloud.xyz", "extension");
    writeBytes(dir + "/noext", smallBinaryPcd(3));
    expectCloudError(dir + "/noext", "extension");
    expectCloudError(dir, "extension");
}

TEST(CloudIoBadInput, PcdHeaderProblems) {
    const std::string dir = freshDir();
    auto check = [&](const std::string &name, const std::string &bytes, const std::string &needle) {
        writeBytes(dir + "/" + name, bytes);
        SCOPED_TRACE(name);
        expectCloudError(dir + "/" + name, needle);
    };
    const std::string xyz3 = std::string(36, '\0');
    check("points_mismatch.pcd", pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 3, 1, 4, "binary") + xyz3, "POINTS 4");
    check("no_x.pcd", pcdHeader("a y z", "4 4 4", "F F F", "1 1 1", 3, 1, 3, "binary") + xyz3, "no x field");
    check("no_z_ascii.pcd", pcdHeader("x y", "4 4", "F F", "1 1", 1, 1, 1, "ascii") + "1 2\n", "no z field");
    check("sizes.pcd", pcdHeader("x y z", "4 4", "F F F", "1 1 1", 3, 1, 3, "binary") + xyz3, "SIZE has 2");
    check("float2.pcd", pcdHeader("x y z", "4 2 4", "F F F", "1 1 1", 3, 1, 3, "binary") + xyz3, "SIZE 2");
    check("size3.pcd", pcdHeader("x y z", "4 3 4", "F F F", "1 1 1", 3, 1, 3, "binary") + xyz3, "SIZE of field");
    check("type.pcd", pcdHeader("x y z", "4 4 4", "F Q F", "1 1 1", 3, 1, 3, "binary") + xyz3, "TYPE of field");
    check("count0.pcd", pcdHeader("x y z", "4 4 4", "F F F", "1 0 1", 3, 1, 3, "binary") + xyz3, "COUNT");
    check("data.pcd", pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 3, 1, 3, "binary_zipped") + xyz3, "DATA");
    check("nodata.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nPOINTS 1\n", "no DATA");
    check("nowidth.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n",
          "no WIDTH");
    check("viewpoint.pcd",
          "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 1\nPOINTS 1\nDATA ascii\n1 2 3\n",
          "VIEWPOINT");
    check("width_neg.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH -3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n",
          "WIDTH");
    check("unknown_key.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nFOO 1\nDATA ascii\n1 2 3\n",
          "FOO");
    check("ascii_word.pcd", pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 1, 1, 1, "ascii") + "1 two 3\n",
          "not a number");
    check("ascii_cols.pcd", pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 2, 1, 2, "ascii") + "1 2 3\n1 2\n",
          "expected 3");
}

TEST(CloudIoBadInput, TruncatedAndHugeClaims) {
    const std::string dir = freshDir();
    std::string full = smallBinaryPcd(50);
    writeBytes(dir + "/trunc.pcd", full.substr(0, full.size() - 5));
    expectCloudError(dir + "/trunc.pcd", "truncated");
    writeBytes(dir + "/trunc_ascii.pcd",
               pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 3, 1, 3, "ascii") + "1 2 3\n4 5 6\n");
    expectCloudError(dir + "/trunc_ascii.pcd", "truncated");
    // A header promising 10^12 points over a few bytes must fail at once, without allocating.
    for (const char *data : {"binary", "ascii", "binary_compressed"}) {
        writeBytes(dir + "/huge.pcd",
                   pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 1000000000, 1000, 1000000000000ull, data) +
                       std::string(24, '\x01'));
        SCOPED_TRACE(data);
        expectCloudError(dir + "/huge.pcd");
    }
    writeBytes(dir + "/huge_w.pcd",
               pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 1000000000000ull, 1, 1000000000000ull, "binary"));
    expectCloudError(dir + "/huge_w.pcd", "too large");
    // Compressed sizes that lie.
    std::string lzf = pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 2, 1, 2, "binary_compressed");
    std::string lie = lzf;
    appendLE<std::uint32_t>(lie, 1000);
    appendLE<std::uint32_t>(lie, 24);
    lie += std::string(10, '\0');
    writeBytes(dir + "/lzf_lie.pcd", lie);
    expectCloudError(dir + "/lzf_lie.pcd", "truncated");
    std::string bad_stream = lzf;
    appendLE<std::uint32_t>(bad_stream, 4);
    appendLE<std::uint32_t>(bad_stream, 24);
    bad_stream += std::string("\xe0\xff\x10\x00", 4);  // a back reference before the start
    writeBytes(dir + "/lzf_bad.pcd", bad_stream);
    expectCloudError(dir + "/lzf_bad.pcd", "corrupt");
    // PLY: 10^12 vertices in a few bytes, binary and ascii; a truncated list element before them.
    writeBytes(dir + "/huge.ply",
               "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\nproperty float x\n"
               "property float y\nproperty float z\nend_header\n" +
                   std::string(24, '\0'));
    expectCloudError(dir + "/huge.ply", "exceeds the limit of 16777216 points");
    writeBytes(dir + "/huge_ascii.ply",
               "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\n"
               "property float y\nproperty float z\nend_header\n1 2 3\n");
    expectCloudError(dir + "/huge_ascii.ply", "exceeds the limit of 16777216 points");
    writeBytes(dir + "/list_first.ply",
               "ply\nformat binary_little_endian 1.0\nelement face 1000000000000\n"
               "property list uint int idx\nelement vertex 1\nproperty float x\n"
               "property float y\nproperty float z\nend_header\n\xff\xff\xff\xff");
    expectCloudError(dir + "/list_first.ply", "truncated");
}

TEST(CloudIoBadInput, ZeroPointsAllNanAndPlyProblems) {
    const std::string dir = freshDir();
    writeBytes(dir + "/zero.pcd", pcdHeader("x y z", "4 4 4", "F F F", "1 1 1", 0, 1, 0, "binary"));
    expectCloudError(dir + "/zero.pcd", "zero points");
    writeBytes(dir + "/zero.ply",
               "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
               "property float z\nend_header\n");
    expectCloudError(dir + "/zero.ply", "zero points");
    auto all_nan = randomCloud<pcl::PointXYZ>(4, 3, 0, 1);
    for (auto &p : all_nan.points) p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
    all_nan.is_dense = false;
    // NaN points are allowed (the contract): a cloud of nothing else is read, all NaN.
    ASSERT_EQ(pcl::io::savePCDFileBinary(dir + "/nan.pcd", all_nan), 0);
    ASSERT_EQ(pcl::io::savePCDFileASCII(dir + "/nan_ascii.pcd", all_nan), 0);
    for (const char *name : {"/nan.pcd", "/nan_ascii.pcd"}) {
        const Cloud c = readCloud(dir + name);
        EXPECT_EQ(c.size(), 12u) << name;
        EXPECT_EQ(countFinite(c), 0u) << name;
    }

    writeBytes(dir + "/list.ply",
               "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
               "property float z\nproperty list uchar float extra\nend_header\n1 2 3 2 0 0\n");
    expectCloudError(dir + "/list.ply", "list property");
    writeBytes(dir + "/nox.ply",
               "ply\nformat ascii 1.0\nelement vertex 1\nproperty float u\nproperty float y\n"
               "property float z\nend_header\n1 2 3\n");
    expectCloudError(dir + "/nox.ply", "no x property");
    writeBytes(dir + "/noformat.ply", "ply\nelement vertex 1\nproperty float x\nend_header\n");
    expectCloudError(dir + "/noformat.ply", "format");
    writeBytes(dir + "/badtype.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n1\n");
    expectCloudError(dir + "/badtype.ply", "property type");
    writeBytes(dir + "/noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
    expectCloudError(dir + "/noend.ply", "end_header");
    writeBytes(dir + "/novertex.ply", "ply\nformat ascii 1.0\nelement face 1\nproperty float x\nend_header\n1\n");
    expectCloudError(dir + "/novertex.ply", "no vertex");
}

// ---------------------------------------------------------------------------------------
// Depth PNG + camera YAML
// ---------------------------------------------------------------------------------------

TEST(CloudIoDepth, BadDepthImagesAndCameraFiles) {
    const std::string dir = freshDir();
    CameraIntrinsics cam;
    cam.width = 8;
    cam.height = 6;
    writeCamera(dir + "/camera.yaml", cam);
    cv::Mat depth(6, 8, CV_16UC1, cv::Scalar(1500));
    ASSERT_TRUE(cv::imwrite(dir + "/ok.png", depth));
    const Cloud ok = readDepthCloud(dir + "/ok.png", dir + "/camera.yaml");
    EXPECT_EQ(ok.width, 8);
    EXPECT_EQ(ok.height, 6);
    EXPECT_TRUE(ok.organized());
    EXPECT_NEAR(ok.points[0].z(), 1.5f, 1e-6f);

    ASSERT_TRUE(cv::imwrite(dir + "/eight.png", cv::Mat(6, 8, CV_8UC1, cv::Scalar(100))));
    expectInputError([&] { readDepthCloud(dir + "/eight.png", dir + "/camera.yaml"); }, dir + "/eight.png", "16-bit");
    ASSERT_TRUE(cv::imwrite(dir + "/color16.png", cv::Mat(6, 8, CV_16UC3, cv::Scalar(1, 2, 3))));
    expectInputError([&] { readDepthCloud(dir + "/color16.png", dir + "/camera.yaml"); }, dir + "/color16.png",
                     "channel");
    ASSERT_TRUE(cv::imwrite(dir + "/big.png", cv::Mat(7, 8, CV_16UC1, cv::Scalar(100))));
    expectInputError([&] { readDepthCloud(dir + "/big.png", dir + "/camera.yaml"); }, dir + "/big.png", "8x7");
    ASSERT_TRUE(cv::imwrite(dir + "/zeros.png", cv::Mat(6, 8, CV_16UC1, cv::Scalar(0))));
    expectInputError([&] { readDepthCloud(dir + "/zeros.png", dir + "/camera.yaml"); }, dir + "/zeros.png",
                     "no valid depth");
    writeBytes(dir + "/notpng.png", "this is not an image");
    expectInputError([&] { readDepthCloud(dir + "/notpng.png", dir + "/camera.yaml"); }, dir + "/notpng.png");
    expectInputError([&] { readDepthCloud(dir + "/absent.png", dir + "/camera.yaml"); }, dir + "/absent.png");

    writeBytes(dir + "/bad1.yaml", "camera: [unclosed\n");
    expectInputError([&] { readDepthCloud(dir + "/ok.png", dir + "/bad1.yaml"); }, dir + "/bad1.yaml");
    writeBytes(dir + "/bad2.yaml", "camera:\n  width: 8\n  height: 6\n  fx: abc\n  fy: 1\n  cx: 1\n  cy: 1\n");
    expectInputError([&] { readDepthCloud(dir + "/ok.png", dir + "/bad2.yaml"); }, dir + "/bad2.yaml");
    writeBytes(dir + "/bad3.yaml", "kamera:\n  width: 8\n");
    expectInputError([&] { readDepthCloud(dir + "/ok.png", dir + "/bad3.yaml"); }, dir + "/bad3.yaml");
    expectInputError([&] { readDepthCloud(dir + "/ok.png", dir + "/absent.yaml"); }, dir + "/absent.yaml");
}

TEST(CloudIoDepth, RealTumFrame) {
    const std::string frame = std::string(PROJSURF_SOURCE_DIR) + "/data/tum_o3d_fr3_office_partition";
    const Cloud c = readDepthCloud(frame + "/depth.png", frame + "/camera.yaml");
    EXPECT_EQ(c.width, 640);
    EXPECT_EQ(c.height, 480);
    ASSERT_EQ(c.size(), 640u * 480u);
    const std::size_t finite = countFinite(c);
    EXPECT_GT(finite, c.size() * 7 / 10);  // meta.json: 80.8 % valid
    std::size_t in_range = 0;
    for (const Point &p : c.points)
        if (isFinite(p) && p.z() > 0.3f && p.z() < 10.0f) ++in_range;
    EXPECT_EQ(in_range, finite);
}

// ---------------------------------------------------------------------------------------
// Random mutations: load or InputError, never a crash
// ---------------------------------------------------------------------------------------

TEST(CloudIoFuzz, MutatedPcdAndPlyLoadOrThrowInputError) {
    const std::string dir = freshDir();
    const auto ref = randomCloud<pcl::PointXYZRGB>(12, 8, 6, 77);
    ASSERT_EQ(pcl::io::savePCDFileBinary(dir + "/base_bin.pcd", ref), 0);
    ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(dir + "/base_lzf.pcd", ref), 0);
    ASSERT_EQ(pcl::io::savePLYFileBinary(dir + "/base.ply", randomCloud<pcl::PointXYZ>(60, 1, 0, 78)), 0);
    ASSERT_EQ(pcl::io::savePLYFileASCII(dir + "/base_ascii.ply", randomCloud<pcl::PointXYZ>(30, 1, 0, 79)), 0);
    const std::string bases[] = {dir + "/base_bin.pcd", dir + "/base_lzf.pcd", dir + "/base.ply",
                                 dir + "/base_ascii.ply"};
    std::mt19937 rng(2026);
    int loaded = 0, rejected = 0;
    for (int iter = 0; iter < 2000; ++iter) {
        const std::string &base = bases[iter % 4];
        std::string bytes = readBytes(base);
        const std::size_t header_end =
            std::min(bytes.size(), bytes.find(base.find(".ply") != std::string::npos ? "end_header" : "DATA") + 30);
        const int kind = static_cast<int>(rng() % 5);
        const int edits = 1 + static_cast<int>(rng() % 4);
        for (int e = 0; e < edits && !bytes.empty(); ++e) {
            // Half the edits land in the header, where the parsing decisions are.
            const std::size_t limit = (rng() % 2) ? header_end : bytes.size();
            const std::size_t at = rng() % std::max<std::size_t>(1, limit);
            if (kind == 0)
                bytes[at] = static_cast<char>(bytes[at] ^ (1 << (rng() % 8)));  // bit flip
            else if (kind == 1)
                bytes[at] = static_cast<char>(rng());  // byte set
            else if (kind == 2)
                bytes.resize(rng() % bytes.size());  // truncation
            else if (kind == 3)
                bytes[at] = "0123456789 \n-"[rng() % 13];  // digit / separator
            else
                bytes.insert(at, 1 + rng() % 8, static_cast<char>(rng()));  // insertion
        }
        const std::string path = dir + "/m" + base.substr(base.rfind('.'));
        writeBytes(path, bytes);
        try {
            const Cloud c = readCloud(path);
            ASSERT_GT(c.size(), 0u);
            ASSERT_EQ(static_cast<std::size_t>(c.width) * c.height, c.size());
            ASSERT_GT(countFinite(c), 0u);
            ++loaded;
        } catch (const InputError &e) {
            ASSERT_NE(std::string(e.what()).find(path), std::string::npos);
            ++rejected;
        }
    }
    EXPECT_EQ(loaded + rejected, 2000);
    EXPECT_GT(rejected, 100);  // the mutations do break files
    EXPECT_GT(loaded, 20);     // and some survive (e.g. flips in the data)
}
