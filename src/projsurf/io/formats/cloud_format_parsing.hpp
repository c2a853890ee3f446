#pragma once
// What the PCD and PLY readers share: stored scalars (any width, either byte order), header
// words and numbers parsed without locale or exceptions, and a header line as a message shows it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace projsurf::cloud_format {

enum class Kind { Int, UInt, Float };

struct Scalar {
    Kind kind = Kind::Float;
    int size = 4;  // bytes: 1, 2, 4 or 8 (Float: 4 or 8)
};

/// Value of a stored scalar; `big_endian` tells the byte order in the file.
double decodeScalar(const unsigned char *p, Scalar t, bool big_endian);
/// double -> float without undefined behaviour for values beyond the float range.
float toFloat(double d);
void appendFloatLE(std::string &out, float f);
std::uint32_t readU32LE(const unsigned char *p);

bool isSpace(char c);
/// The whitespace-separated words of `line` (views into it).
void splitWords(std::string_view line, std::vector<std::string_view> &words);
/// A header line as it may appear in a message: short and printable.
std::string shown(std::string_view s);
/// Whole-string parses; false on anything else (signs, spaces, trailing bytes).
bool parseU64(std::string_view s, std::uint64_t &value);
bool parseDouble(std::string_view s, double &value);
/// Next line of `bytes` from `pos` (without '\n' and a trailing '\r'); advances `pos`.
std::string_view nextLine(const std::string &bytes, std::size_t &pos);

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

}  // namespace projsurf::cloud_format
