#include "eval/report/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "eval/paper/paper_results.hpp"
#include "eval/plot/plot.hpp"
#include "projsurf/io/files/files.hpp"

namespace fs = std::filesystem;

namespace projsurf::eval {
namespace {

// Chart colours (BGR), one per method; the paper's published values use the same colour, dashed.
const cv::Scalar kConcave(190, 110, 30), kConvex(30, 140, 240), kDefault(60, 160, 60), kGrey(110, 110, 110);
const cv::Scalar kNo(60, 160, 60), kSo(30, 140, 240), kBo(50, 50, 210);

std::string num(double v, int precision) {
    if (std::isnan(v)) return "–";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f", precision, v);
    return buf;
}
std::string pct(double v) { return num(v, 0); }
std::string meanStd(double m, double s) { return std::isnan(m) ? "–" : num(m, 2) + " (" + num(s, 2) + ")"; }

std::string distanceLabel(double d) {
    std::ostringstream s;
    s << d;
    return s.str();
}
std::string angleLabel(double a) {
    std::ostringstream s;
    s << a << "°";
    return s.str();
}
/// OpenCV's Hershey fonts have no degree sign.
std::string plotAngle(double a) {
    std::ostringstream s;
    s << a << " deg";
    return s.str();
}

bool same(double a, double b) { return std::abs(a - b) < 1e-9; }

std::vector<double> distancesOf(const std::vector<Trial> &trials, const std::string &scenario) {
    std::set<double> s;
    for (const auto &t : trials)
        if (t.scenario == scenario) s.insert(t.distance);
    return {s.begin(), s.end()};
}

std::vector<double> anglesOf(const std::vector<Trial> &trials, const std::string &scenario) {
    std::vector<double> out;
    for (const auto &t : trials)
        if (t.scenario == scenario &&
            std::none_of(out.begin(), out.end(), [&](double a) { return same(a, t.angle_deg); }))
            out.push_back(t.angle_deg);
    return out;
}

bool hasMethod(const std::vector<Trial> &trials, const std::string &scenario, const std::string &method) {
    return std::any_of(trials.begin(), trials.end(),
                       [&](const Trial &t) { return t.scenario == scenario && t.method == method; });
}

/// Summary of a scenario and method; NaN angle or distance = all of them.
Summary sumFor(const std::vector<Trial> &trials, const std::string &scenario, const std::string &method, double angle,
               double distance) {
    return summarize(select(trials, [&](const Trial &t) {
        return t.scenario == scenario && t.method == method && (std::isnan(angle) || same(t.angle_deg, angle)) &&
               (std::isnan(distance) || same(t.distance, distance));
    }));
}

/// One Markdown table: a column per distance plus "Average"; rows give a cell per distance
/// (NaN = the average over all distances).
struct Row {
    std::string label;
    std::function<std::string(double)> cell;
};
std::string distanceTable(const std::vector<double> &distances, const std::vector<Row> &rows) {
    std::ostringstream s;
    s << "| Distance (m) |";
    for (double d : distances) s << " " << distanceLabel(d) << " |";
    s << " Average |\n|---|";
    for (std::size_t i = 0; i <= distances.size(); ++i) s << "---:|";
    s << "\n";
    for (const auto &r : rows) {
        s << "| " << r.label << " |";
        for (double d : distances) s << " " << r.cell(d) << " |";
        s << " " << r.cell(kNaN) << " |\n";
    }
    return s.str();
}

Row paperSuccessRow(const PaperSuccessRow *row, const std::string &label) {
    return {label, [row](double d) {
                if (!row) return std::string("–");
                if (std::isnan(d)) return pct(row->average_success_pct);
                const auto v = paperSuccessAt(*row, d);
                return v ? pct(*v) : std::string("–");
            }};
}
Row paperErrorRow(const PaperSuccessRow *row, const std::string &label) {
    return {label, [row](double d) {
                if (!row) return std::string("–");
                if (std::isnan(d)) return num(row->average_area_error_m2, 2);
                const auto v = paperErrorAt(*row, d);
                return v ? num(*v, 3) : std::string("–");
            }};
}

/// The rows of our results for one scenario, angle and method.
std::vector<Row> ourRows(const std::vector<Trial> &trials, const std::string &scenario, double angle,
                         const std::string &method, const std::string &who, bool surfaces) {
    auto S = [&trials, scenario, angle, method](double d) { return sumFor(trials, scenario, method, angle, d); };
    std::vector<Row> rows{
        {who + ", success, paper's criterion (%)", [S](double d) { return pct(S(d).paperRatePct()); }},
        {who + ", success, ground truth (%)", [S](double d) { return pct(S(d).truthRatePct()); }},
        {who + ", success, ground truth, 40 px framebuffer slack (%)",
         [S](double d) { return pct(S(d).slackRatePct()); }},
        {who + ", area error vs best round (m²)", [S](double d) { return num(S(d).paper_area_error, 3); }},
        {who + ", area error vs ground truth (m²)", [S](double d) { return num(S(d).truth_area_error, 3); }},
        {who + ", found and accepted (%)", [S](double d) { return pct(S(d).foundPct()); }},
    };
    if (surfaces)
        rows.push_back({who + ", rounds on the closet / wall", [&trials, scenario, angle, method](double d) {
                            int closet = 0, wall = 0;
                            for (const auto &t : trials)
                                if (t.scenario == scenario && t.method == method && same(t.angle_deg, angle) &&
                                    (std::isnan(d) || same(t.distance, d)) && t.found) {
                                    closet += t.surface == "closet";
                                    wall += t.surface == "wall";
                                }
                            return std::to_string(closet) + " / " + std::to_string(wall);
                        }});
    return rows;
}

struct KeyStats {
    int n = 0, shown = 0;
    double overshoot = 0.0;
    double h = kNaN, hs = kNaN, v = kNaN, vs = kNaN, g = kNaN, gs = kNaN;
};
KeyStats keyStats(const std::vector<KeystoneTrial> &k, double angle, double distance, const std::string &method) {
    KeyStats s;
    std::vector<double> h, v, g;
    for (const auto &t : k)
        if (same(t.angle_deg, angle) && same(t.distance, distance) && t.method == method) {
            ++s.n;
            if (!t.shown) continue;
            ++s.shown;
            s.overshoot = std::max(s.overshoot, t.overshoot_px);
            h.push_back(t.errors.horizontal_pct);
            v.push_back(t.errors.vertical_pct);
            g.push_back(t.errors.diagonal_pct);
        }
    auto ms = [](const std::vector<double> &x, double &m, double &sd) {
        if (x.empty()) return;
        m = 0.0;
        for (double a : x) m += a;
        m /= static_cast<double>(x.size());
        double q = 0.0;
        for (double a : x) q += (a - m) * (a - m);
        sd = x.size() > 1 ? std::sqrt(q / static_cast<double>(x.size() - 1)) : 0.0;
    };
    ms(h, s.h, s.hs);
    ms(v, s.v, s.vs);
    ms(g, s.g, s.gs);
    return s;
}

std::vector<std::pair<double, double>> keystonePoses(const std::vector<KeystoneTrial> &k) {
    std::vector<std::pair<double, double>> poses;  // (angle, distance) in run order
    for (const auto &t : k)
        if (std::none_of(poses.begin(), poses.end(),
                         [&](const auto &p) { return same(p.first, t.angle_deg) && same(p.second, t.distance); }))
            poses.emplace_back(t.angle_deg, t.distance);
    return poses;
}

/// A failure reason without its numbers: "not found: surface check rejected the area: 89906 ..." ->
/// "not found: surface check rejected the area".
std::string failureKind(const std::string &why) {
    const auto a = why.find(':');
    if (a == std::string::npos) return why;
    const auto b = why.find(':', a + 1);
    return b == std::string::npos ? why : why.substr(0, b);
}

const std::vector<std::pair<std::string, std::string>> kCheckScenarios{
    {"wall", "NO"}, {"small_obstacles", "SO"}, {"big_obstacle", "BO"}};

std::vector<double> successSeries(const std::vector<Trial> &trials, const std::string &scenario,
                                  const std::string &method, double angle, const std::vector<double> &ds, bool paper) {
    std::vector<double> y;
    for (double d : ds) {
        const Summary s = sumFor(trials, scenario, method, angle, d);
        y.push_back(paper ? s.paperRatePct() : s.truthRatePct());
    }
    return y;
}

std::vector<double> publishedSeries(const PaperSuccessRow *row, const std::vector<double> &ds) {
    std::vector<double> y;
    for (double d : ds) {
        const auto v = row ? paperSuccessAt(*row, d) : std::nullopt;
        y.push_back(v ? *v : kNaN);
    }
    return y;
}

/// A chart over the distance to the wall (the paper's x axis), `size` px.
LineChart distanceChart(const std::string &title, const std::string &y_label, cv::Size size) {
    LineChart c;
    c.title = title;
    c.x_label = "distance to the wall (m)";
    c.y_label = y_label;
    c.size = size;
    return c;
}

cv::Mat successPanel(const std::vector<Trial> &trials, const std::string &scenario, double angle, bool paper_criterion,
                     const std::vector<std::tuple<std::string, std::string, cv::Scalar, int>> &methods,
                     const std::vector<std::tuple<std::string, const PaperSuccessRow *, cv::Scalar>> &published) {
    const std::vector<double> ds = distancesOf(trials, scenario);
    LineChart c = distanceChart(
        scenario + " at " + plotAngle(angle) + (paper_criterion ? ": paper's criterion" : ": ground truth"),
        "success rate (%)", cv::Size(620, 430));
    c.y_min = 0;
    c.y_max = 105;
    for (const auto &[name, label, color, marker] : methods)
        if (hasMethod(trials, scenario, name))
            c.series.push_back({label,
                                color,
                                ds,
                                successSeries(trials, scenario, name, angle, ds, paper_criterion),
                                {},
                                false,
                                marker});
    for (const auto &[label, row, color] : published) {
        std::vector<double> pd = row ? row->distances : ds;
        c.series.push_back({label, color, pd, publishedSeries(row, pd), {}, true, 0});
    }
    return drawLineChart(c);
}

/// Table 1: concave vs convex hull (and the default method) on the plain wall.
cv::Mat unclutteredSuccessPlot(const std::vector<Trial> &T) {
    std::vector<cv::Mat> panels;
    for (bool paper : {false, true})
        for (double a : anglesOf(T, "wall"))
            panels.push_back(successPanel(T, "wall", a, paper,
                                          {{"paper-concave", "ours: paper method, concave", kConcave, 0},
                                           {"paper-convex", "ours: paper method, convex", kConvex, 1},
                                           {"default", "ours: default method", kDefault, 2}},
                                          {{"published: concave", findPaperRow("1", "concave", a), kConcave},
                                           {"published: convex", findPaperRow("1", "convex", a), kConvex}}));
    return tilePanels(panels, 2, "Table 1: success rate on the plain wall (solid: ours, dashed: paper)");
}

/// Table 2: cluttered scenario (closet in front of the wall).
cv::Mat clutteredSuccessPlot(const std::vector<Trial> &T) {
    std::vector<cv::Mat> panels;
    for (bool paper : {false, true})
        for (double a : anglesOf(T, "closet"))
            panels.push_back(successPanel(T, "closet", a, paper,
                                          {{"paper-concave", "ours: paper method", kConcave, 0},
                                           {"default", "ours: default method", kDefault, 2}},
                                          {{"published", findPaperRow("2", "cluttered", a), kConcave}}));
    return tilePanels(panels, 2, "Table 2: success rate, cluttered scene (solid: ours, dashed: paper)");
}

/// Fig 15: surface-check outliers and decisions; empty when no check scenario ran.
cv::Mat surfaceCheckPlot(const std::vector<Trial> &T) {
    LineChart outl = distanceChart("Outliers in the checked area (paper method, median; 0 drawn at 1)",
                                   "outliers (log scale)", cv::Size(640, 440));
    outl.log_y = true;
    LineChart acc = distanceChart("Surface-check decisions that were right (ground truth)", "right decisions (%)",
                                  cv::Size(640, 440));
    acc.y_min = 0;
    acc.y_max = 105;
    const cv::Scalar colors[] = {kNo, kSo, kBo};
    int k = 0;
    bool any = false;
    for (const auto &[scenario, tag] : kCheckScenarios) {
        const std::vector<double> ds = distancesOf(T, scenario);
        std::vector<double> med, lo, accp, accd;
        for (double d : ds) {
            const Summary p = sumFor(T, scenario, "paper-concave", kNaN, d);
            med.push_back(std::max(1.0, p.outliers_median));
            const Summary q = sumFor(T, scenario, "default", kNaN, d);
            accp.push_back(p.checked ? 100.0 * p.decisions_correct / p.checked : kNaN);
            accd.push_back(q.checked ? 100.0 * q.decisions_correct / q.checked : kNaN);
        }
        if (!ds.empty()) any = true;
        outl.series.push_back({tag + " (" + scenario + ")", colors[k], ds, med, {}, false, k});
        acc.series.push_back({tag + " paper method", colors[k], ds, accp, {}, true, k});
        acc.series.push_back({tag + " default", colors[k], ds, accd, {}, false, k});
        ++k;
    }
    const PaperOutlierFacts f = paperOutlierFacts();
    outl.h_lines = {{static_cast<double>(f.outlier_limit), "paper's limit 5000", true, false},
                    {f.highest_median_no_obstacle, "paper: NO max median 4285", false, true},
                    {f.smallest_median_obstacles, "paper: SO/BO min median 7383", false, false}};
    if (!any) return cv::Mat();
    return tilePanels({drawLineChart(outl), drawLineChart(acc)}, 2, "Fig 15: surface check on NO / SO / BO");
}

/// Table 3, one error of eq. 8 (0 horizontal, 1 vertical, 2 diagonals): published, ours with
/// the paper's method and with the default one, per pose.
cv::Mat keystoneErrorChart(const std::vector<KeystoneTrial> &keystone, int e) {
    const char *names[] = {"horizontal", "vertical", "diagonals"};
    BarChart b;
    b.title = std::string(names[e]) + " error (eq. 8), mean and std";
    b.y_label = "error (%)";
    b.size = cv::Size(1100, 380);
    Series pub{"published (paper)", kGrey, {}, {}, {}, true, 0}, ours_p{"ours: paper method", kConcave, {}, {}, {}},
        ours_d{"ours: default method", kDefault, {}, {}, {}};
    for (const auto &[a, d] : keystonePoses(keystone)) {
        b.categories.push_back(distanceLabel(d) + " m|" + plotAngle(a));
        const PaperKeystoneCell *pc = findPaperKeystone(a, d);
        const KeyStats kp = keyStats(keystone, a, d, "paper-concave"), kd = keyStats(keystone, a, d, "default");
        const double pm[] = {pc ? pc->horizontal_mean : kNaN, pc ? pc->vertical_mean : kNaN,
                             pc ? pc->diagonal_mean : kNaN};
        const double ps[] = {pc ? pc->horizontal_std : kNaN, pc ? pc->vertical_std : kNaN,
                             pc ? pc->diagonal_std : kNaN};
        pub.y.push_back(pm[e]);
        pub.err.push_back(ps[e]);
        ours_p.y.push_back(e == 0 ? kp.h : e == 1 ? kp.v : kp.g);
        ours_p.err.push_back(e == 0 ? kp.hs : e == 1 ? kp.vs : kp.gs);
        ours_d.y.push_back(e == 0 ? kd.h : e == 1 ? kd.v : kd.g);
        ours_d.err.push_back(e == 0 ? kd.hs : e == 1 ? kd.vs : kd.gs);
    }
    b.series = {pub, ours_p, ours_d};
    return drawBarChart(b);
}

/// Table 3: shape errors of the corrected picture on the wall.
cv::Mat keystonePlot(const std::vector<KeystoneTrial> &keystone) {
    std::vector<cv::Mat> panels;
    for (int e = 0; e < 3; ++e) panels.push_back(keystoneErrorChart(keystone, e));
    return tilePanels(panels, 1, "Table 3: shape errors of the corrected picture on the wall");
}

/// Time per detection on the plain wall, ours per method and the paper's.
cv::Mat timingPlot(const std::vector<Trial> &T) {
    LineChart c =
        distanceChart("Time per detection on the plain wall (median, one core)", "ms (log scale)", cv::Size(700, 460));
    c.log_y = true;
    const std::vector<double> ds = distancesOf(T, "wall");
    const std::tuple<std::string, std::string, cv::Scalar, int> methods[] = {
        {"paper-concave", "ours: paper method, concave", kConcave, 0},
        {"paper-convex", "ours: paper method, convex", kConvex, 1},
        {"default", "ours: default method", kDefault, 2}};
    for (const auto &[name, label, color, marker] : methods) {
        if (!hasMethod(T, "wall", name)) continue;
        std::vector<double> y, err;
        for (double d : ds) y.push_back(sumFor(T, "wall", name, kNaN, d).time_median_ms);
        c.series.push_back({label, color, ds, y, {}, false, marker});
    }
    const PaperTiming pt = paperTiming();
    c.series.push_back({"published (Mbot CPU)",
                        kGrey,
                        {1.0, 3.0},
                        {1000 * pt.uncluttered_1m_s, 1000 * pt.uncluttered_3m_s},
                        {},
                        true,
                        0});
    return drawLineChart(c);
}

/// A success row of Table 1 or 2 at angle `a`: published | the paper method by its criterion,
/// ground truth and with slack | the default method by ground truth.
HeadlineRow successRow(const std::vector<Trial> &T, const std::string &label, const char *scenario, const char *table,
                       const char *variant, double a) {
    const PaperSuccessRow *row = findPaperRow(table, variant, a);
    const Summary paper = sumFor(T, scenario, "paper-concave", a, kNaN);
    return {label, row ? pct(row->average_success_pct) : "–", pct(paper.paperRatePct()), pct(paper.truthRatePct()),
            pct(paper.slackRatePct()), pct(sumFor(T, scenario, "default", a, kNaN).truthRatePct())};
}

}  // namespace

std::vector<std::pair<std::string, cv::Mat>> evalPlots(const EvalResults &res) {
    std::vector<std::pair<std::string, cv::Mat>> out;
    const auto &T = res.trials;
    if (hasMethod(T, "wall", "paper-concave")) out.emplace_back("success_uncluttered.png", unclutteredSuccessPlot(T));
    if (hasMethod(T, "closet", "paper-concave")) out.emplace_back("success_cluttered.png", clutteredSuccessPlot(T));
    if (cv::Mat check = surfaceCheckPlot(T); !check.empty()) out.emplace_back("outliers.png", check);
    if (!res.keystone.empty()) out.emplace_back("keystone.png", keystonePlot(res.keystone));
    if (!T.empty()) out.emplace_back("timing.png", timingPlot(T));
    return out;
}

std::vector<HeadlineRow> evalHeadline(const EvalResults &res) {
    const auto &T = res.trials;
    std::vector<HeadlineRow> rows;
    for (double a : anglesOf(T, "wall"))
        rows.push_back(successRow(T, "Table 1, plain wall, " + angleLabel(a) + ", concave hull: success (%)", "wall",
                                  "1", "concave", a));
    for (double a : anglesOf(T, "closet"))
        rows.push_back(successRow(T, "Table 2, cluttered (closet), " + angleLabel(a) + ": success (%)", "closet", "2",
                                  "cluttered", a));
    {
        // Fig 15: the surface check's decisions, judged by ground truth.
        int pn = 0, pc = 0, dn = 0, dc = 0;
        for (const auto &[scenario, tag] : kCheckScenarios) {
            const Summary p = sumFor(T, scenario, "paper-concave", kNaN, kNaN),
                          d = sumFor(T, scenario, "default", kNaN, kNaN);
            pn += p.checked;
            pc += p.decisions_correct;
            dn += d.checked;
            dc += d.decisions_correct;
        }
        if (pn + dn > 0)
            rows.push_back({"Fig 15, NO/SO/BO: surface-check decisions that were right (%)", "–",
                            pct(pn ? 100.0 * pc / pn : kNaN), "", "", pct(dn ? 100.0 * dc / dn : kNaN)});
    }
    if (!res.keystone.empty()) {
        double worst_p = kNaN, worst_d = kNaN;
        for (const auto &[a, d] : keystonePoses(res.keystone)) {
            const KeyStats kp = keyStats(res.keystone, a, d, "paper-concave"),
                           kd = keyStats(res.keystone, a, d, "default");
            for (double v : {kp.h, kp.v, kp.g})
                if (!std::isnan(v)) worst_p = std::isnan(worst_p) ? v : std::max(worst_p, v);
            for (double v : {kd.h, kd.v, kd.g})
                if (!std::isnan(v)) worst_d = std::isnan(worst_d) ? v : std::max(worst_d, v);
        }
        rows.push_back({"Table 3: worst mean eq. 8 error of the corrected picture (%)", "3.46", num(worst_p, 2), "", "",
                        num(worst_d, 2)});
    }
    {
        const auto all = [&](const std::string &m) {
            return summarize(select(T, [&](const Trial &t) { return t.method == m; }));
        };
        rows.push_back({"Time per detection, median (ms)", "~1500", num(all("paper-concave").time_median_ms, 1), "", "",
                        num(all("default").time_median_ms, 1)});
    }
    return rows;
}

std::string evalHeadlineText(const EvalResults &res) {
    std::string out =
        "Tables 1-3 (published | ours, paper method: paper's criterion, ground truth, + 40 px slack | ours, default "
        "method: ground truth; report.md's Headline):";
    for (const HeadlineRow &r : evalHeadline(res)) {
        out += "\n  " + r.experiment + ": " + r.published + " | " + r.paper_criterion;
        if (!r.paper_truth.empty()) out += ", " + r.paper_truth + ", " + r.paper_slack;
        out += " | " + r.default_truth;
    }
    return out;
}

std::string paperCriterionRoundsNote(int rounds) {
    if (rounds > 2) return "";
    return "with " + std::to_string(rounds) + (rounds == 1 ? " round" : " rounds") +
           " per pose the paper's criterion is near 100 % by construction: a round passes when its area is within "
           "0.05 m^2 of the best round of its pose, " +
           (rounds == 1 ? std::string("which is itself") : std::string("one of the two")) +
           ", so a cell falls below 100 % only when a round found nothing" +
           (rounds == 1 ? std::string("") : std::string(" or the two differ by more than 0.05 m^2")) +
           "; the paper's 10 rounds (eval without --quick) make it a measure";
}

namespace {

/// The title, what was run, the command and the machine's load.
void writeReportIntro(std::ostream &md, const EvalResults &res, const ReportInfo &info) {
    const auto &T = res.trials;
    md << "# projsurf: the paper's experiments re-run in simulation\n\n";
    md << "Fernández-Rodicio et al. 2017, section 4 (Tables 1–3, Fig 15), re-run on the simulator (Kinect v1 class "
          "depth noise, the paper's scenes) with `--method paper` (the paper's steps) and the default method. "
       << res.rounds << " rounds of sensor noise per pose"
       << (info.quick ? " (**quick run: a subset of the poses, not the full evaluation**)" : "") << "; "
       << T.size() + res.keystone.size() << " detections; " << num(res.seconds, 1)
       << " s in all, one core, sequential.\n\n";
    if (!info.command.empty()) md << "Command: `" << info.command << "`\n\n";
    if (!info.load.empty())
        md << "Machine: " << info.load
           << ". Times are wall-clock in-process times of one thread; on a busy machine they include waiting for a "
              "core, so compare methods within this report rather than with other runs.\n\n";
}

/// The headline: every experiment's success rate, published and ours.
void writeHeadlineSection(std::ostream &md, const EvalResults &res) {
    md << "## Headline\n\n";
    md << "Success rates are averages over the distances of each table. *Paper's criterion* = area within 0.05 m² of "
          "the best of the rounds for that pose and method (paper 4.1); *ground truth* = the simulator's true "
          "largest free rectangle: the answer must be on a real surface, upright, inside the projector's "
          "framebuffer (within 2 px), at least 97 % truly free, and within 0.05 m² of the true best area "
          "(`scoreDetection`); *+ 40 px slack* lets the corners leave the framebuffer by up to 40 px (the "
          "paper method's 2 cm raster often overshoots the projector's footprint by about one cell).\n\n";
    md << "| Experiment | published | ours, paper method, paper's criterion | ours, paper method, ground truth | "
          "ours, paper method, ground truth + 40 px slack | ours, default method, ground truth |\n"
          "|---|---:|---:|---:|---:|---:|\n";
    for (const HeadlineRow &r : evalHeadline(res))
        md << "| " << r.experiment << " | " << r.published << " | " << r.paper_criterion << " | " << r.paper_truth
           << " | " << r.paper_slack << " | " << r.default_truth << " |\n";
    md << "\n";
    md << "Published timings are the paper's (its robot's CPU, PCL); ours are this machine, one core.\n\n";
    md << "![Table 1](success_uncluttered.png)\n\n";
}

/// Table 1: concave vs convex hull on the plain wall, per angle.
void writeTable1Section(std::ostream &md, const EvalResults &res) {
    const auto &T = res.trials;
    md << "## Table 1: concave vs convex hull on the plain wall (paper 4.1)\n\n";
    md << "Wall scenario, " << res.rounds << " rounds per pose. Rows *published* are copied from the paper.\n\n";
    for (double a : anglesOf(T, "wall")) {
        md << "### " << angleLabel(a) << "\n\n";
        std::vector<Row> rows;
        for (const std::string hull : {"concave", "convex"}) {
            if (!hasMethod(T, "wall", "paper-" + hull)) continue;
            const auto *row = findPaperRow("1", hull, a);
            rows.push_back(paperSuccessRow(row, "**" + hull + " hull**: published, success (%)"));
            rows.push_back(paperErrorRow(row, "published, mean area error (m²)"));
            for (auto &r : ourRows(T, "wall", a, "paper-" + hull, "ours (paper method)", false)) rows.push_back(r);
        }
        for (auto &r : ourRows(T, "wall", a, "default", "**ours (default method)**", false)) rows.push_back(r);
        md << distanceTable(distancesOf(T, "wall"), rows) << "\n";
    }
}

/// Table 2: the cluttered scene (a closet against the wall), per angle.
void writeTable2Section(std::ostream &md, const EvalResults &res) {
    const auto &T = res.trials;
    md << "## Table 2: uncluttered and cluttered scenes (paper 4.2)\n\n";
    md << "Uncluttered = the plain wall above (Table 1, concave hull). Cluttered = a closet (1.0 m wide, 0.6 m deep, "
          "2.0 m tall) standing against the wall; the simulator's scene has no 1 m pose (the closet front would be "
          "0.4 m from the camera, inside the Kinect's minimum range), so the published average includes a distance "
          "we do not run. *Rounds on the closet / wall* counts where the found rectangles lie (the paper's detector "
          "switches between the two beyond 2 m, section 4.2).\n\n";
    md << "![Table 2](success_cluttered.png)\n\n";
    for (double a : anglesOf(T, "closet")) {
        md << "### Cluttered, " << angleLabel(a) << "\n\n";
        std::vector<Row> rows;
        const auto *row = findPaperRow("2", "cluttered", a);
        rows.push_back(paperSuccessRow(row, "published, success (%)"));
        rows.push_back(paperErrorRow(row, "published, mean area error (m²)"));
        for (auto &r : ourRows(T, "closet", a, "paper-concave", "ours (paper method)", true)) rows.push_back(r);
        for (auto &r : ourRows(T, "closet", a, "default", "**ours (default method)**", true)) rows.push_back(r);
        std::vector<double> ds = distancesOf(T, "closet");
        if (row && !ds.empty() && ds.front() > 1.0) ds.insert(ds.begin(), 1.0);  // show the paper's 1 m column
        md << distanceTable(ds, rows) << "\n";
    }
}

/// Fig 15: the surface check's outliers and decisions, no / small / big obstacles.
void writeSurfaceCheckSection(std::ostream &md, const EvalResults &res) {
    const auto &T = res.trials;
    md << "## Figure 15: surface-check outliers, no / small / big obstacles (paper 4.3)\n\n";
    const PaperOutlierFacts f = paperOutlierFacts();
    md << "The paper counts points of the checked area farther than " << f.threshold_m
       << " m from the area's mean depth and rejects the area above " << f.outlier_limit
       << " outliers. Its figure's bars are not in the text; the text gives the highest median without obstacles ("
       << f.highest_median_no_obstacle << ") and the smallest median with obstacles (" << f.smallest_median_obstacles
       << "). Both angles pooled (the paper found no clear angle effect). *Right decisions*: accepted when the "
          "checked rectangle is truly free and valid, rejected when it is not (ground truth). The default method's "
          "check is relative (reject above 3 % of the checked points).\n\n";
    md << "![Fig 15](outliers.png)\n\n";
    md << "| Case | Distance (m) | paper method: outliers, median [min–max] | accepted (%) | right decisions (%) | "
          "default: outlier share, median (%) | accepted (%) | right decisions (%) "
          "|\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
    double our_no_max = kNaN, our_obst_min = kNaN;
    for (const auto &[scenario, tag] : kCheckScenarios)
        for (double d : distancesOf(T, scenario)) {
            const Summary p = sumFor(T, scenario, "paper-concave", kNaN, d),
                          q = sumFor(T, scenario, "default", kNaN, d);
            md << "| " << tag << " (" << scenario << ") | " << distanceLabel(d) << " | " << num(p.outliers_median, 0)
               << " [" << num(p.outliers_min, 0) << "–" << num(p.outliers_max, 0) << "] | " << pct(p.acceptedPct())
               << " | " << pct(p.checked ? 100.0 * p.decisions_correct / p.checked : kNaN) << " | "
               << num(100.0 * q.outlier_share_median, 2) << " | " << pct(q.acceptedPct()) << " | "
               << pct(q.checked ? 100.0 * q.decisions_correct / q.checked : kNaN) << " |\n";
            if (std::isnan(p.outliers_median)) continue;
            if (tag == "NO")
                our_no_max = std::isnan(our_no_max) ? p.outliers_median : std::max(our_no_max, p.outliers_median);
            else
                our_obst_min = std::isnan(our_obst_min) ? p.outliers_median : std::min(our_obst_min, p.outliers_median);
        }
    md << "\nHighest median without obstacles: published " << f.highest_median_no_obstacle << ", ours (paper method) "
       << num(our_no_max, 0) << ". Smallest median with obstacles: published " << f.smallest_median_obstacles
       << ", ours " << num(our_obst_min, 0) << ".\n\n";
}

/// Table 3: keystone errors of the corrected picture, with the calibrations' errors.
void writeKeystoneSection(std::ostream &md, const EvalResults &res) {
    if (!res.keystone.empty()) {
        md << "## Table 3: keystone errors of the corrected picture (paper 4.4)\n\n";
        int ok = 0;
        double axis_mean = 0.0, axis_max = 0.0, origin_mean = 0.0;
        for (const auto &c : res.calibrations)
            if (c.ok) {
                ++ok;
                axis_mean += c.axis_error_deg;
                axis_max = std::max(axis_max, c.axis_error_deg);
                origin_mean += c.origin_error_m;
            }
        md << "Per round, the projector is calibrated (`calibrateProjector`, paper 3.1) from 5 simulated captures of "
              "the white disc; detection and correction (eq. 7, homography) use that estimate; the picture's corners "
              "are then cast through the TRUE projector onto the simulated wall and eq. 8 is measured there. "
           << ok << "/" << res.calibrations.size() << " calibrations succeeded; axis error mean "
           << num(ok ? axis_mean / ok : kNaN, 3) << "°, max " << num(axis_max, 3) << "°; lens centre error mean "
           << num(ok ? 1000.0 * origin_mean / ok : kNaN, 1)
           << " mm. Cells: mean (std) over the rounds in percent; *shown* = rounds whose picture landed on the "
              "wall; *cut* = how far the paper method's rectangle left the framebuffer (its picture is measured "
              "as if uncut). The simulated projector has no lens distortion, no roll against the camera and exactly "
              "the field of view the calibration assumes, so what remains is the estimated plane's tilt and the "
              "rectangle's placement; the published errors also include those real-world sources.\n\n";
        md << "![Table 3](keystone.png)\n\n";
        md << "| Angle | Distance (m) | Error | published | ours, paper method | ours, default method |\n"
              "|---:|---:|---|---:|---:|---:|\n";
        for (const auto &[a, d] : keystonePoses(res.keystone)) {
            const PaperKeystoneCell *pc = findPaperKeystone(a, d);
            const KeyStats kp = keyStats(res.keystone, a, d, "paper-concave"),
                           kd = keyStats(res.keystone, a, d, "default");
            md << "| " << angleLabel(a) << " | " << distanceLabel(d) << " | horizontal | "
               << (pc ? meanStd(pc->horizontal_mean, pc->horizontal_std) : "–") << " | " << meanStd(kp.h, kp.hs)
               << " | " << meanStd(kd.h, kd.hs) << " |\n";
            md << "| | | vertical | " << (pc ? meanStd(pc->vertical_mean, pc->vertical_std) : "–") << " | "
               << meanStd(kp.v, kp.vs) << " | " << meanStd(kd.v, kd.vs) << " |\n";
            md << "| | | diagonals | " << (pc ? meanStd(pc->diagonal_mean, pc->diagonal_std) : "–") << " | "
               << meanStd(kp.g, kp.gs) << " | " << meanStd(kd.g, kd.gs) << " |\n";
            md << "| | | shown (cut at the edge, max px) | | " << kp.shown << "/" << kp.n << " ("
               << num(kp.overshoot, 0) << ") | " << kd.shown << "/" << kd.n << " (" << num(kd.overshoot, 0) << ") |\n";
        }
        md << "\n";
    }
}

/// Why rounds failed: the first condition of `scoreDetection` that failed, per scene and method.
void writeFailureSection(std::ostream &md, const EvalResults &res) {
    const auto &T = res.trials;
    md << "## Why rounds failed (ground truth)\n\n";
    md << "The first condition of `scoreDetection` that failed, counted over all rounds of a scene and "
          "method.\n\n| Scene | Method | rounds | failed | reasons (count) |\n|---|---|---:|---:|---|\n";
    for (const std::string sc : {"wall", "closet", "small_obstacles", "big_obstacle"})
        for (const std::string m : {"paper-concave", "paper-convex", "default"}) {
            if (!hasMethod(T, sc, m)) continue;
            std::map<std::string, int> why;
            int n = 0, failed = 0;
            for (const auto &t : T)
                if (t.scenario == sc && t.method == m) {
                    ++n;
                    if (t.score.success) continue;
                    ++failed;
                    ++why[failureKind(t.score.why)];
                }
            md << "| " << sc << " | " << m << " | " << n << " | " << failed << " | ";
            bool first = true;
            for (const auto &[k, c] : why) {
                md << (first ? "" : "; ") << k << " (" << c << ")";
                first = false;
            }
            md << " |\n";
        }
    md << "\n";
}

/// Time per detection, per method, scene and distance.
void writeTimingSection(std::ostream &md, const EvalResults &res) {
    const auto &T = res.trials;
    md << "## Time per detection\n\n";
    md << "In-process time from a loaded cloud to the result (`timing_ms.total`), this machine, one core. "
          "Published: 1.29 s at 1 m and 1.46 s at 3 m on the plain wall, 1.6 s at 3 m cluttered, \"around 1.5 s\" "
          "overall (paper 4.1, 4.2, 4.5).\n\n";
    md << "![timing](timing.png)\n\n";
    {
        const std::vector<double> ds = distancesOf(T, "wall");
        md << "| Method | scene |";
        for (double d : ds) md << " " << distanceLabel(d) << " m |";
        md << " all: median | all: p90 |\n|---|---|";
        for (std::size_t i = 0; i < ds.size() + 2; ++i) md << "---:|";
        md << "\n";
        for (const std::string m : {"paper-concave", "paper-convex", "default"}) {
            for (const std::string sc : {"wall", "closet"}) {
                if (!hasMethod(T, sc, m)) continue;
                md << "| " << m << " | " << sc << " |";
                for (double d : ds) md << " " << num(sumFor(T, sc, m, kNaN, d).time_median_ms, 1) << " |";
                const Summary all = sumFor(T, sc, m, kNaN, kNaN);
                md << " " << num(all.time_median_ms, 1) << " | " << num(all.time_p90_ms, 1) << " |\n";
            }
        }
        md << "\n";
    }
}

/// The real frames: one row per frame of the gallery.
void writeGallerySection(std::ostream &md, const ReportInfo &info, const std::vector<GalleryEntry> &gallery) {
    md << "## Real frames\n\n";
    if (info.paper_only) {
        md << "Not run (`--paper-only`: the paper's experiments alone).\n\n";
    } else if (info.real_dir.empty() || gallery.empty()) {
        md << "No real frames were given (or none found" << (info.real_dir.empty() ? "" : " in `" + info.real_dir + "`")
           << ").\n\n";
    } else {
        md << "Detection (default method) on every frame in `" << info.real_dir
           << "`, with the contract's example calibration (`sim::exampleProjector()`): these frames have no real "
              "projector and no IMU, so gravity is taken from the floor (as `detect --gravity auto` does) and the "
              "rectangle "
              "shows where that projector *would* project. No ground truth: look at the overlays. "
           << num(info.real_seconds, 1) << " s in all.\n\n";
        md << "![gallery](gallery/contact_sheet.png)\n\n";
        md << "| Frame | found | size (m) | area (m²) | plane distance (m) | orientation (°) | check: outliers / "
              "points | "
              "time (ms) | note |\n|---|---|---:|---:|---:|---:|---:|---:|---|\n";
        for (const auto &g : gallery) {
            md << "| [" << g.name << "](gallery/" << g.name << ".png) | ";
            if (!g.read) {
                md << "unreadable | | | | | | | " << g.problem << " |\n";
                continue;
            }
            md << (g.found ? "yes" : "no") << " | " << (g.found ? num(g.width, 2) + " × " + num(g.height, 2) : "")
               << " | " << (g.found ? num(g.area, 2) : "") << " | " << (g.found ? num(g.distance, 2) : "") << " | "
               << (g.found ? num(g.orientation_deg, 1) : "") << " | " << g.outliers << " / " << g.points << " | "
               << num(g.time_ms, 1) << " | " << (g.found ? "" : g.reason) << " |\n";
        }
        md << "\n";
    }
}

/// How it was measured: scenes, noise, the criteria.
void writeMethodNotes(std::ostream &md, const EvalResults &res) {
    md << "## How it was measured\n\n";
    md << "- Scenes: `sim::makeScenario` (wall, closet, small_obstacles, big_obstacle) at the paper's distances and "
          "angles (`sim::paperExperiments()`); camera 1.0 m above the floor, level; the contract's example projector "
          "(1280×800, 39.3°×24°) for Tables 1, 2 and Fig 15.\n";
    md << "- Noise: `sim::SensorModel` (Kinect v1: σz = 1.425e-3·z², disparity quantisation, dropouts, IR shadow); "
          "round r of pose j uses seed 1000·j + r + 1 for the sensor and for RANSAC.\n";
    md << "- Paper's criterion: per pose and method, the largest area over the rounds; a round succeeds when it "
          "found a rectangle within 0.05 m² of it; rounds that found nothing fail and have no area error "
          "(*area error vs best round* = mean of best − area over the rounds that found something). It cannot see "
          "a rectangle that is consistently wrong (e.g. always on the wrong surface).\n";
    if (const std::string note = paperCriterionRoundsNote(res.rounds); !note.empty())
        md << "- **This run**: " << note << ".\n";
    md << "- Ground truth: `sim::computeGroundTruth` (1 cm raster on every vertical surface: seen by the camera, lit "
          "by "
          "the projector, not occluded) and `scoreDetection`; *area error vs ground truth* = mean |best − area| "
          "over all rounds (a round that found nothing counts the whole best area).\n";
    md << "- Table 3 uses the wall scenario at 1, 2, 3 m and 27.5°, 17.19°, −12.06° with a picture of the "
          "framebuffer's "
          "aspect (letterbox = the whole rectangle).\n";
}

}  // namespace

std::string evalReportMarkdown(const EvalResults &res, const std::vector<GalleryEntry> &gallery,
                               const ReportInfo &info) {
    std::ostringstream md;
    writeReportIntro(md, res, info);
    writeHeadlineSection(md, res);
    writeTable1Section(md, res);
    writeTable2Section(md, res);
    writeSurfaceCheckSection(md, res);
    writeKeystoneSection(md, res);
    writeFailureSection(md, res);
    writeTimingSection(md, res);
    writeGallerySection(md, info, gallery);
    if (info.labelled) md << labelledReportMarkdown(*info.labelled, info.labels_dir, "labels");
    writeMethodNotes(md, res);
    if (!info.realistic_markdown.empty()) md << "\n## Realistic simulated suite\n\n" << info.realistic_markdown;
    return md.str();
}

void writeEvalReport(const std::string &dir, const EvalResults &results, const std::vector<GalleryEntry> &gallery,
                     const ReportInfo &info) {
    const fs::path out(dir);
    for (const auto &[name, image] : evalPlots(results)) writeImageAtomic((out / name).string(), image);
    if (!gallery.empty()) {
        const fs::path g = out / "gallery";
        std::error_code ec;
        fs::create_directories(g, ec);
        for (const auto &e : gallery)
            if (!e.overlay.empty()) writeImageAtomic((g / (e.name + ".png")).string(), e.overlay);
        writeImageAtomic((g / "contact_sheet.png").string(), contactSheet(gallery));
    }
    if (info.labelled && !info.labelled->empty()) writeLabelledPictures((out / "labels").string(), *info.labelled);
    writeFileAtomic((out / "report.md").string(), evalReportMarkdown(results, gallery, info));
}

}  // namespace projsurf::eval
