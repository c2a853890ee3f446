#include "projsurf/io/files/utf8_text.hpp"

#include <cstdio>

namespace projsurf {
namespace {

/// The length of the well-formed UTF-8 sequence at s[i] (1 for ASCII), 0 when there is none.
std::size_t sequenceLength(const unsigned char *s, std::size_t n, std::size_t i) {
    const unsigned c = s[i];
    if (c < 0x80) return 1;
    // The sequence's length and the range its second byte must fall in (RFC 3629, table 3-7
    // of the Unicode standard): this excludes overlong forms, surrogates and > U+10FFFF.
    std::size_t len = 0;
    unsigned lo = 0x80, hi = 0xBF;
    if (c >= 0xC2 && c <= 0xDF)
        len = 2;
    else if (c == 0xE0)
        len = 3, lo = 0xA0;
    else if (c >= 0xE1 && c <= 0xEC)
        len = 3;
    else if (c == 0xED)
        len = 3, hi = 0x9F;
    else if (c >= 0xEE && c <= 0xEF)
        len = 3;
    else if (c == 0xF0)
        len = 4, lo = 0x90;
    else if (c >= 0xF1 && c <= 0xF3)
        len = 4;
    else if (c == 0xF4)
        len = 4, hi = 0x8F;
    else
        return 0;
    if (n - i < len) return 0;
    if (s[i + 1] < lo || s[i + 1] > hi) return 0;
    for (std::size_t k = 2; k < len; ++k)
        if (s[i + k] < 0x80 || s[i + k] > 0xBF) return 0;
    return len;
}

}  // namespace

bool isUtf8(const std::string &bytes) {
    const auto *s = reinterpret_cast<const unsigned char *>(bytes.data());
    for (std::size_t i = 0, len; i < bytes.size(); i += len)
        if ((len = sequenceLength(s, bytes.size(), i)) == 0) return false;
    return true;
}

std::string utf8Escaped(const std::string &bytes) {
    const auto *s = reinterpret_cast<const unsigned char *>(bytes.data());
    std::string out;
    out.reserve(bytes.size());
    for (std::size_t i = 0; i < bytes.size();) {
        const std::size_t len = sequenceLength(s, bytes.size(), i);
        if (len == 0) {
            char buf[5];
            std::snprintf(buf, sizeof buf, "\\x%02X", s[i]);
            out += buf;
            ++i;
        } else {
            out.append(bytes, i, len);
            i += len;
        }
    }
    return out;
}

std::string shownText(const std::string &bytes, std::size_t max_bytes) {
    const std::string escaped = utf8Escaped(bytes);
    std::string out;
    for (std::size_t i = 0; i < escaped.size(); ++i) {
        const auto c = static_cast<unsigned char>(escaped[i]);
        if (out.size() >= max_bytes && (c & 0xC0) != 0x80) return out + "...";  // never inside a sequence
        if (c < 0x20 || c == 0x7F) {
            char buf[5];
            std::snprintf(buf, sizeof buf, "\\x%02X", c);
            out += buf;
        } else {
            out += escaped[i];
        }
    }
    return out;
}

}  // namespace projsurf
