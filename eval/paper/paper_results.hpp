#pragma once
// The paper's published results (Fernandez-Rodicio et al. 2017, section 4), copied from its
// text so that the evaluation can print them beside ours. Values exactly as printed,
// including what look like typos (Table 1/2 "0,7" at 17.19 deg, 3 m is probably 0.07).
#include <optional>
#include <string>
#include <vector>

namespace projsurf::eval {

/// One row of Tables 1 and 2: success rate (%) and mean area error (m^2) per distance.
struct PaperSuccessRow {
    std::string table;    ///< "1" or "2"
    std::string variant;  ///< "concave", "convex" (Table 1); "uncluttered", "cluttered" (Table 2)
    double angle_deg = 0.0;
    std::vector<double> distances;  ///< m: 1, 1.5, 2, 2.5, 3
    std::vector<double> success_pct;
    std::vector<double> area_error_m2;
    double average_success_pct = 0.0;  ///< the table's "Average" column
    double average_area_error_m2 = 0.0;
};
const std::vector<PaperSuccessRow> &paperSuccessRows();
/// The row for (table, variant, angle), or nullptr.
const PaperSuccessRow *findPaperRow(const std::string &table, const std::string &variant, double angle_deg);
/// Value of a row at a distance, nullopt when the paper has none there.
std::optional<double> paperSuccessAt(const PaperSuccessRow &row, double distance);
std::optional<double> paperErrorAt(const PaperSuccessRow &row, double distance);

/// Table 3: eq. 8 errors (%) of the corrected picture, mean (std), per angle and distance.
struct PaperKeystoneCell {
    double angle_deg = 0.0;
    double distance = 0.0;
    double horizontal_mean = 0, horizontal_std = 0;
    double vertical_mean = 0, vertical_std = 0;
    double diagonal_mean = 0, diagonal_std = 0;
};
const std::vector<PaperKeystoneCell> &paperKeystoneCells();
const PaperKeystoneCell *findPaperKeystone(double angle_deg, double distance);

/// Figure 15 and section 4.3 (the figure's bars are not in the text; only these numbers are).
struct PaperOutlierFacts {
    double highest_median_no_obstacle = 4285;  ///< outliers, NO case
    double smallest_median_obstacles = 7383;   ///< outliers, SO or BO case
    int outlier_limit = 5000;                  ///< the paper's chosen limit
    double threshold_m = 0.05;                 ///< |z - mean z| beyond this is an outlier
};
PaperOutlierFacts paperOutlierFacts();

/// Timing per detection (s, paper 4.1-4.2, on the Mbot's CPU).
struct PaperTiming {
    double uncluttered_1m_s = 1.29;  ///< both hulls, 4.1
    double uncluttered_3m_s = 1.46;  ///< both hulls, 4.1 (4.2 says 1.55 s)
    double cluttered_3m_s = 1.6;     ///< 4.2
    double whole_process_s = 1.5;    ///< 4.5, "around 1.5 seconds"
};
PaperTiming paperTiming();

}  // namespace projsurf::eval
