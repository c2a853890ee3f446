#pragma once
// Point-cloud files: PCD and PLY readers and writers, and depth PNG + camera YAML.
// Headers and data are parsed here (not by PCL): PCL 1.13's PCD reader crashes on some
// malformed headers and silently drops x/y/z stored as doubles.
#include <string>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

/// Reads a PCD (ascii, binary, binary_compressed; organized or not) or PLY (ascii,
/// binary_little_endian, binary_big_endian) file chosen by extension (.pcd/.ply, any case).
/// x, y, z may be stored as any numeric type (float32/64, signed/unsigned 8-64 bit ints).
/// Keeps the organized width x height when the file has one (PCD HEIGHT > 1). NaN points
/// are kept (a cloud of NaN points only is returned too: the detector answers found: false);
/// the caller ignores them. Throws InputError(path, problem) for a missing file, unknown
/// extension, malformed header, missing x/y/z, truncated data, zero points, or a file over
/// io/files/limits.hpp (points, bytes, decompressed bytes). Every allocation is bounded by the
/// file size and those limits.
Cloud readCloud(const std::string &path);

/// Reads a 16-bit single-channel depth PNG and camera intrinsics (readCamera) into an
/// organized cloud (depthToCloud). Throws InputError naming the offending file for an
/// unreadable image, an image that is not 16-bit single-channel, a size different from
/// the camera's width x height, or an image with no valid (non-zero) depth at all.
Cloud readDepthCloud(const std::string &depth_png, const std::string &camera_yaml);

/// Writes a cloud as binary PCD (x y z float32), organized when cloud.organized(),
/// NaN points included; atomically (writeFileAtomic).
void writeCloudPcd(const std::string &path, const Cloud &cloud);

/// Writes a cloud as binary little-endian PLY (x y z float32), atomically. PLY has no
/// pixel grid, so only the finite points are written.
void writeCloudPly(const std::string &path, const Cloud &cloud);

}  // namespace projsurf
