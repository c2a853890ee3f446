#include "eval/paper/paper_results.hpp"

#include <cmath>

namespace projsurf::eval {
namespace {

const std::vector<double> kD5{1.0, 1.5, 2.0, 2.5, 3.0};

bool near(double a, double b) { return std::abs(a - b) < 1e-6; }

std::optional<double> at(const std::vector<double> &xs, const std::vector<double> &ys, double x) {
    for (std::size_t i = 0; i < xs.size() && i < ys.size(); ++i)
        if (near(xs[i], x)) return ys[i];
    return std::nullopt;
}

}  // namespace

const std::vector<PaperSuccessRow> &paperSuccessRows() {
    static const std::vector<PaperSuccessRow> rows{
        // Table 1 (section 4.1).
        {"1", "concave", 27.5, kD5, {100, 100, 80, 90, 50}, {0, 0, 0.05, 0.07, 0.073}, 84, 0.07},
        {"1", "concave", 17.19, kD5, {90, 100, 50, 40, 50}, {0.05, 0, 0.07, 0.07, 0.7}, 66, 0.15},
        {"1", "convex", 27.5, kD5, {70, 100, 100, 50, 60}, {0.17, 0, 0, 0.08, 0.12}, 76, 0.07},
        {"1", "convex", 17.19, kD5, {100, 90, 60, 80, 50}, {0, 0.06, 0.06, 0.08, 0.12}, 76, 0.06},
        // Table 2 (section 4.2); the uncluttered rows repeat Table 1's concave hull.
        {"2", "uncluttered", 27.5, kD5, {100, 100, 80, 90, 50}, {0, 0, 0.07, 0.07, 0.07}, 84, 0.04},
        {"2", "uncluttered", 17.19, kD5, {90, 100, 50, 40, 50}, {0.05, 0, 0.07, 0.07, 0.7}, 66, 0.17},
        {"2", "cluttered", -26.01, kD5, {100, 100, 60, 40, 10}, {0, 0, 0.25, 0.27, 0.38}, 62, 0.18},
        {"2", "cluttered", -16.62, kD5, {100, 70, 20, 10, 10}, {0, 0.06, 0.35, 0.36, 0.35}, 42, 0.23},
    };
    return rows;
}

const PaperSuccessRow *findPaperRow(const std::string &table, const std::string &variant, double angle_deg) {
    for (const auto &r : paperSuccessRows())
        if (r.table == table && r.variant == variant && near(r.angle_deg, angle_deg)) return &r;
    return nullptr;
}

std::optional<double> paperSuccessAt(const PaperSuccessRow &row, double distance) {
    return at(row.distances, row.success_pct, distance);
}
std::optional<double> paperErrorAt(const PaperSuccessRow &row, double distance) {
    return at(row.distances, row.area_error_m2, distance);
}

const std::vector<PaperKeystoneCell> &paperKeystoneCells() {
    // Table 3 (section 4.4): horizontal, vertical, diagonal error, mean (std), percent.
    static const std::vector<PaperKeystoneCell> cells{
        {27.5, 1.0, 1.8, 0.2, 1.77, 1.18, 1.68, 0.71},    {27.5, 2.0, 1.14, 0.34, 1.15, 0.69, 3.2, 0.51},
        {27.5, 3.0, 1.36, 0.5, 0.84, 0.95, 2.95, 0.5},    {17.19, 1.0, 0.89, 0.54, 0.71, 0.67, 1.55, 0.56},
        {17.19, 2.0, 0.75, 0.29, 1.81, 0.61, 1.2, 0.32},  {17.19, 3.0, 1.47, 0.6, 1.58, 1.24, 1.49, 0.67},
        {-12.06, 1.0, 2.24, 0.93, 0.67, 0.78, 1.3, 0.62}, {-12.06, 2.0, 2.36, 0.8, 2.27, 1.33, 1.11, 0.46},
        {-12.06, 3.0, 1.41, 0.94, 3.46, 0.8, 0.79, 0.26},
    };
    return cells;
}

const PaperKeystoneCell *findPaperKeystone(double angle_deg, double distance) {
    for (const auto &c : paperKeystoneCells())
        if (near(c.angle_deg, angle_deg) && near(c.distance, distance)) return &c;
    return nullptr;
}

PaperOutlierFacts paperOutlierFacts() { return {}; }
PaperTiming paperTiming() { return {}; }

}  // namespace projsurf::eval
