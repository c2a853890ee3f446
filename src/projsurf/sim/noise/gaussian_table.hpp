#pragma once
// Fast standard-normal draws for per-pixel noise: a fixed table of 65536 quantiles of N(0, 1),
// indexed by a seeded generator (deterministic, far cheaper than std::normal_distribution).
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

namespace projsurf::sim {

class GaussianTable {
public:
    static const GaussianTable &instance() {
        static const GaussianTable table;
        return table;
    }
    /// One standard-normal sample.
    float draw(std::mt19937 &rng) const { return values_[rng() & (kSize - 1)]; }
    /// The sample at a 16-bit index (for callers that split one 32-bit draw in two).
    float at(std::uint32_t index16) const { return values_[index16 & (kSize - 1)]; }

private:
    static constexpr std::uint32_t kSize = 1u << 16;
    GaussianTable() {
        // Quantiles at (i + 0.5) / kSize: exact mean 0 and a variance within 0.1 % of 1.
        for (std::uint32_t i = 0; i < kSize; ++i) values_[i] = static_cast<float>(inverseNormal((i + 0.5) / kSize));
    }
    /// Inverse of the standard normal CDF by Newton steps on erfc (accurate to ~1e-12).
    static double inverseNormal(double p) {
        double x = 0.0;
        for (int it = 0; it < 60; ++it) {
            const double cdf = 0.5 * std::erfc(-x / std::sqrt(2.0));
            const double pdf = std::exp(-0.5 * x * x) / std::sqrt(2.0 * 3.14159265358979323846);
            const double step = (cdf - p) / pdf;
            x -= step;
            if (std::abs(step) < 1e-13) break;
        }
        return x;
    }
    std::array<float, kSize> values_{};
};

/// Standard-normal samples from a seeded std::mt19937, two per generator call.
class NormalSource {
public:
    explicit NormalSource(std::mt19937 &rng) : rng_(rng), table_(GaussianTable::instance()) {}
    float next() {
        if (!have_) {
            bits_ = rng_();
            have_ = true;
            return table_.at(bits_);
        }
        have_ = false;
        return table_.at(bits_ >> 16);
    }

private:
    std::mt19937 &rng_;
    const GaussianTable &table_;
    std::uint32_t bits_ = 0;
    bool have_ = false;
};

}  // namespace projsurf::sim
