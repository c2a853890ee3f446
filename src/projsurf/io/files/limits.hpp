#pragma once
// Input limits: what projsurf accepts from files and messages (docs/limits.md tells why each
// value). Every reader checks them before it allocates; exceeding one is an InputError
// (one stderr line, exit 2). Each one is far above what real sensors, projectors and
// pictures produce, and low enough that any input up to all of them stays under 2 GiB.
#include <cstddef>
#include <cstdint>

namespace projsurf::limits {

/// Points in one cloud (PCD, PLY, PointCloud2, depth image): 2^24 = 4096 x 4096.
constexpr std::uint64_t kMaxCloudPoints = std::uint64_t{1} << 24;
/// Bytes of one point-cloud file (PCD, PLY): 768 MiB (2^24 points of 48 bytes).
constexpr std::uint64_t kMaxCloudFileBytes = std::uint64_t{768} << 20;
/// Bytes a compressed block may decompress to (PCD binary_compressed, bag chunks): 512 MiB,
/// and never more than kMaxLzfRatio times its compressed size for LZF.
constexpr std::uint64_t kMaxDecompressedBytes = std::uint64_t{512} << 20;
/// Pixels of a picture, a video frame or a colour image: 2^25 (8K UHD 7680 x 4320 fits).
constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 25;
/// Pixels of a depth image: as many as a cloud may have points.
constexpr std::uint64_t kMaxDepthPixels = kMaxCloudPoints;
/// Bytes of one image file: 256 MiB.
constexpr std::uint64_t kMaxImageFileBytes = std::uint64_t{256} << 20;
/// Projector framebuffer (calibration resolution): each side 2..16384 px, at most 2^25 px.
constexpr int kMaxFramebufferSide = 16384;
constexpr std::uint64_t kMaxFramebufferPixels = std::uint64_t{1} << 25;
/// Camera intrinsics: each side of the image 1..16384 px (the pixel count is kMaxImagePixels').
constexpr int kMaxCameraSide = 16384;
/// Frames of one image sequence or video: 100000 (over an hour at 25 fps).
constexpr std::uint64_t kMaxSequenceFrames = 100000;
/// Messages of one bag topic: 100000; bytes of one bag record (a message or an
/// uncompressed chunk): 512 MiB; bytes of a record header: 1 MiB.
constexpr std::uint64_t kMaxBagMessages = 100000;
constexpr std::uint64_t kMaxBagRecordBytes = std::uint64_t{512} << 20;
constexpr std::uint64_t kMaxBagHeaderBytes = std::uint64_t{1} << 20;
/// Decompression of a bag's chunks (bz2 turns 574 bytes of zeros into 512 MiB): a chunk above
/// 64 MiB may announce at most 1000 times its compressed size, and all the chunks of one bag
/// (every decompression counted) above 1 GiB at most 100 times theirs.
constexpr std::uint64_t kMaxBagChunkFreeBytes = std::uint64_t{64} << 20;
constexpr std::uint64_t kMaxBagChunkRatio = 1000;
constexpr std::uint64_t kMaxBagFreeBytes = std::uint64_t{1} << 30;
constexpr std::uint64_t kMaxBagRatio = 100;
/// Calibration captures: numbered 0..99, at most 2^26 pixels in all (about 5 bytes each
/// once decoded: 64 captures of 1280 x 720, 32 of 1920 x 1080).
constexpr std::uint64_t kMaxCaptures = 100;
constexpr std::uint64_t kMaxCapturePixels = std::uint64_t{1} << 26;
/// Structured-light calibration: at most 100 poses, and the bytes the decoding allocates (one
/// pose's captures and decoding at a time, every pose's lifted points; see
/// structuredLightBytes in io/formats/pattern_files.hpp) at most 1.5 GiB.
constexpr std::uint64_t kMaxStructuredLightBytes = std::uint64_t{1536} << 20;
/// Chessboard mode (procam capture folders): one pose decoded at a time within
/// kMaxStructuredLightBytes, and at most this many bytes of 8-bit captures over all the poses
/// (the decoding time, 1.4 s per lit 1280 x 1024 pose here: 19 such poses in 26.5 s, 11 of
/// 1920 x 1200; links to one pose count as many times as they are listed).
constexpr std::uint64_t kMaxChessboardCaptureBytes = std::uint64_t{1} << 30;
/// Bytes of a YAML file (camera, calibration): 64 KiB; of a detection JSON file (and a procam
/// calibration_result.xml): 1 MiB; nesting depth of any of them: 64.
constexpr std::uint64_t kMaxYamlBytes = std::uint64_t{64} << 10;
constexpr std::uint64_t kMaxJsonBytes = std::uint64_t{1} << 20;
/// How far from the camera a detection's corners may lie, m: no projector lights a wall 1 km away
/// (a larger number is millimetres or garbage, and 1e300 overflows the rectangle's sides).
constexpr double kMaxDetectionDistanceM = 1000.0;
constexpr int kMaxNesting = 64;
/// How far a camera pose (Python's camera_pose=, the node's ~fixed_frame transform) may put the
/// camera from its fixed frame's origin, m: no robot's map is 100 km across (1e300 overflowed).
constexpr double kMaxPoseTranslationM = 1e5;
/// Bytes of a settings YAML file (detect --config): 1 MiB (every key with its comment is 10 KiB).
constexpr std::uint64_t kMaxSettingsYamlBytes = std::uint64_t{1} << 20;

}  // namespace projsurf::limits
