#include "projsurf/io/files/image_header.hpp"

#include <cctype>
#include <cstring>

namespace projsurf {
namespace {

std::uint32_t be16(const unsigned char *p) { return static_cast<std::uint32_t>(p[0]) << 8 | p[1]; }
std::uint32_t be32(const unsigned char *p) { return be16(p) << 16 | be16(p + 2); }
std::uint32_t le16(const unsigned char *p) { return static_cast<std::uint32_t>(p[1]) << 8 | p[0]; }
std::uint32_t le32(const unsigned char *p) { return le16(p + 2) << 16 | le16(p); }

ImageHeader png(const unsigned char *p, std::size_t n) {
    ImageHeader h;
    if (n < 24 || std::memcmp(p + 12, "IHDR", 4) != 0) return h;
    h.format = "PNG";
    h.width = be32(p + 16);
    h.height = be32(p + 20);
    return h;
}

ImageHeader jpeg(const unsigned char *p, std::size_t n) {
    ImageHeader h;
    std::size_t i = 2;
    while (i + 4 <= n) {
        if (p[i] != 0xFF) return h;
        const unsigned m = p[i + 1];
        if (m == 0xFF) {  // fill byte
            ++i;
            continue;
        }
        if (m == 0xD8 || m == 0x01 || (m >= 0xD0 && m <= 0xD7)) {  // markers without a length
            i += 2;
            continue;
        }
        if (m == 0xD9 || m == 0xDA) return h;  // end or scan before any frame header
        const std::size_t len = be16(p + i + 2);
        if (len < 2) return h;
        const bool sof = m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
        if (sof) {
            if (i + 9 > n || len < 7) return h;
            h.format = "JPEG";
            h.height = be16(p + i + 5);
            h.width = be16(p + i + 7);
            return h;
        }
        i += 2 + len;
    }
    return h;
}

ImageHeader bmp(const unsigned char *p, std::size_t n) {
    ImageHeader h;
    if (n < 26) return h;
    const std::uint32_t info = le32(p + 14);
    if (info == 12) {
        h.width = le16(p + 18);
        h.height = le16(p + 20);
    } else {
        if (info < 16) return h;
        const auto w = static_cast<std::int32_t>(le32(p + 18)), ht = static_cast<std::int32_t>(le32(p + 22));
        h.width = w < 0 ? 0 : static_cast<std::uint64_t>(w);
        h.height = ht < 0 ? static_cast<std::uint64_t>(-static_cast<std::int64_t>(ht)) : static_cast<std::uint64_t>(ht);
    }
    h.format = "BMP";
    return h;
}

ImageHeader pnm(const unsigned char *p, std::size_t n) {
    ImageHeader h;
    std::size_t i = 2;
    std::uint64_t v[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        while (i < n && (std::isspace(p[i]) || p[i] == '#')) {
            if (p[i] == '#')
                while (i < n && p[i] != '\n') ++i;
            else
                ++i;
        }
        if (i >= n || !std::isdigit(p[i])) return h;
        while (i < n && std::isdigit(p[i])) {
            v[k] = v[k] * 10 + (p[i++] - '0');
            if (v[k] > (std::uint64_t{1} << 40)) return h;
        }
    }
    h.format = "PNM";
    h.width = v[0];
    h.height = v[1];
    return h;
}

}  // namespace

ImageHeader readImageHeader(const std::string &bytes) {
    const auto *p = reinterpret_cast<const unsigned char *>(bytes.data());
    const std::size_t n = bytes.size();
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (n >= 8 && std::memcmp(p, kPng, 8) == 0) return png(p, n);
    if (n >= 3 && p[0] == 0xFF && p[1] == 0xD8 && p[2] == 0xFF) return jpeg(p, n);
    if (n >= 2 && p[0] == 'B' && p[1] == 'M') return bmp(p, n);
    if (n >= 3 && p[0] == 'P' && p[1] >= '1' && p[1] <= '6' && std::isspace(p[2])) return pnm(p, n);
    return {};
}

}  // namespace projsurf
