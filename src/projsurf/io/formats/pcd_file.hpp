#pragma once
// PCD files (ascii, binary, binary_compressed; organized or not), parsed here rather than by PCL
// (see cloud_io.hpp). readCloud() chooses this reader by extension.
#include <string>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

/// The cloud stored in `bytes`, the contents of the PCD file `path`; throws InputError(path, ...).
Cloud readPcd(const std::string &path, const std::string &bytes);

}  // namespace projsurf
