#pragma once
// The size of an encoded image read from its header alone, so that a decoder is only given
// images whose pixels fit the limits (a 555 KB PNG can announce 16384 x 16384 pixels).
#include <cstdint>
#include <string>

namespace projsurf {

struct ImageHeader {
    std::string format;                   ///< "PNG", "JPEG", "BMP", "PNM"; empty when not recognised
    std::uint64_t width = 0, height = 0;  ///< pixels, from the header
};

/// Reads the format and size from the first bytes of an encoded image (PNG IHDR, JPEG SOF,
/// BMP info header, PNM P1-P6). Format empty: not one of these, or a header that ends early.
ImageHeader readImageHeader(const std::string &bytes);

}  // namespace projsurf
