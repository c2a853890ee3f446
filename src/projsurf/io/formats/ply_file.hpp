#pragma once
// PLY files (ascii, binary_little_endian, binary_big_endian; the vertex element), parsed here rather than by PCL
// (see cloud_io.hpp). readCloud() chooses this reader by extension.
#include <string>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

/// The cloud stored in `bytes`, the contents of the PLY file `path`; throws InputError(path, ...).
Cloud readPly(const std::string &path, const std::string &bytes);

}  // namespace projsurf
