#include "projsurf/io/formats/cloud_format_parsing.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <system_error>

namespace projsurf::cloud_format {
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
    case Kind::UInt: return static_cast<double>(u);
    case Kind::Int:
        if (t.size < 8 && (u >> (8 * t.size - 1)) & 1u) u |= ~std::uint64_t{0} << (8 * t.size);
        return static_cast<double>(static_cast<std::int64_t>(u));
    }
    return 0.0;
}

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

std::string_view nextLine(const std::string &bytes, std::size_t &pos) {
    const std::size_t nl = bytes.find('\n', pos);
    const std::size_t end = nl == std::string::npos ? bytes.size() : nl;
    std::string_view line(bytes.data() + pos, end - pos);
    pos = nl == std::string::npos ? bytes.size() : nl + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

}  // namespace projsurf::cloud_format
