#pragma once
// Spatially correlated random fields on an image grid, for sensor errors that are not
// independent per pixel: smooth low-frequency distortions fixed per sensor unit, stereo
// matching errors correlated over a few pixels, column bands. All fields have zero mean and
// unit RMS over the image (before any caller's scaling) and are deterministic for a seed.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace projsurf::sim {

/// CV_32F width x height: independent N(0, 1) values on a grid every `cell_px` pixels,
/// bicubically interpolated (features about `cell_px` across), then shifted to zero mean and
/// scaled to unit RMS.
cv::Mat smoothField(int width, int height, double cell_px, std::uint32_t seed);

/// CV_32F: white noise blurred by a Gaussian of `sigma_px` (sigma_px <= 0: white), zero mean,
/// unit RMS. Draws from `rng` (per-frame noise).
cv::Mat correlatedNoise(int width, int height, double sigma_px, std::mt19937 &rng);

/// One value per column, zero mean, unit RMS: a smooth 1-D field with features about
/// `period_px` wide (vertical bands across the image).
std::vector<float> columnBands(int width, double period_px, std::uint32_t seed);

/// Seed for the systematic (per-unit) errors of sensor `sensor` number `unit`: independent
/// of the per-frame noise seed, different for every (sensor, unit, purpose).
std::uint32_t unitSeed(const std::string &sensor, int unit, const std::string &purpose);

/// Rescales `field` in place to zero mean and unit RMS (no-op on a constant field).
void normalizeField(cv::Mat &field);

}  // namespace projsurf::sim
