#include "eval/plot/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace projsurf::eval {
namespace {

const cv::Scalar kWhite(255, 255, 255), kBlack(30, 30, 30), kGrid(225, 225, 225), kGreyText(90, 90, 90);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

std::string fmt(double v) {
    v += 0.0;  // no "-0"
    if (std::abs(v) < 1e-12) v = 0.0;
    char buf[32];
    const double a = std::abs(v);
    if (a >= 10000)
        std::snprintf(buf, sizeof buf, "%.0fk", v / 1000.0);
    else if (a >= 100 || v == std::round(v))
        std::snprintf(buf, sizeof buf, "%.0f", v);
    else if (a >= 1)
        std::snprintf(buf, sizeof buf, "%.1f", v);
    else
        std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

void text(cv::Mat &img, const std::string &s, cv::Point at, double scale, const cv::Scalar &color, int align = 0,
          int thickness = 1) {
    int base = 0;
    const cv::Size sz = cv::getTextSize(s, kFont, scale, thickness, &base);
    if (align == 1) at.x -= sz.width / 2;
    if (align == 2) at.x -= sz.width;
    cv::putText(img, s, at, kFont, scale, color, thickness, cv::LINE_AA);
}

/// Text rotated by 90 degrees (reads bottom to top), centred on `center`.
void verticalText(cv::Mat &img, const std::string &s, cv::Point center, double scale, const cv::Scalar &color) {
    int base = 0;
    const cv::Size sz = cv::getTextSize(s, kFont, scale, 1, &base);
    cv::Mat strip(sz.height + base + 4, sz.width + 4, CV_8UC3, kWhite);
    cv::putText(strip, s, {2, sz.height + 1}, kFont, scale, color, 1, cv::LINE_AA);
    cv::Mat rotated;
    cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
    cv::Rect r(center.x - rotated.cols / 2, center.y - rotated.rows / 2, rotated.cols, rotated.rows);
    r &= cv::Rect(0, 0, img.cols, img.rows);
    if (r.area() > 0) rotated(cv::Rect(0, 0, r.width, r.height)).copyTo(img(r));
}

void dashedLine(cv::Mat &img, cv::Point2d a, cv::Point2d b, const cv::Scalar &color, int thickness) {
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const double dash = 8.0, gap = 5.0;
    for (double s = 0.0; s < len; s += dash + gap) {
        const double e = std::min(len, s + dash);
        const cv::Point2d p = a + (b - a) * (s / len), q = a + (b - a) * (e / len);
        cv::line(img, p, q, color, thickness, cv::LINE_AA);
    }
}

void drawMarker(cv::Mat &img, cv::Point2d p, int marker, const cv::Scalar &color, bool hollow) {
    const int r = 5, t = hollow ? 2 : cv::FILLED;
    switch (marker % 4) {
    case 0: cv::circle(img, p, r, color, t, cv::LINE_AA); break;
    case 1:
        cv::rectangle(img, cv::Rect(cvRound(p.x) - r, cvRound(p.y) - r, 2 * r, 2 * r), color, t, cv::LINE_AA);
        break;
    case 2: {
        std::vector<cv::Point> tri{{cvRound(p.x), cvRound(p.y) - r - 1},
                                   {cvRound(p.x) - r, cvRound(p.y) + r},
                                   {cvRound(p.x) + r, cvRound(p.y) + r}};
        if (hollow)
            cv::polylines(img, tri, true, color, 2, cv::LINE_AA);
        else
            cv::fillConvexPoly(img, tri, color, cv::LINE_AA);
        break;
    }
    default: {
        std::vector<cv::Point> dia{{cvRound(p.x), cvRound(p.y) - r - 1},
                                   {cvRound(p.x) + r + 1, cvRound(p.y)},
                                   {cvRound(p.x), cvRound(p.y) + r + 1},
                                   {cvRound(p.x) - r - 1, cvRound(p.y)}};
        if (hollow)
            cv::polylines(img, dia, true, color, 2, cv::LINE_AA);
        else
            cv::fillConvexPoly(img, dia, color, cv::LINE_AA);
    }
    }
}

/// Legend entries laid out in rows under the plot; returns the height used.
int legendHeight(const std::vector<Series> &series, int width) {
    int x = 0, rows = series.empty() ? 0 : 1;
    for (const auto &s : series) {
        int base = 0;
        const int w = 40 + cv::getTextSize(s.label, kFont, 0.45, 1, &base).width + 18;
        if (x + w > width && x > 0) {
            ++rows;
            x = 0;
        }
        x += w;
    }
    return rows * 22;
}

void drawLegend(cv::Mat &img, const std::vector<Series> &series, int left, int top, int width, bool bars) {
    int x = 0, y = top + 14;
    for (const auto &s : series) {
        int base = 0;
        const int w = 40 + cv::getTextSize(s.label, kFont, 0.45, 1, &base).width + 18;
        if (x + w > width && x > 0) {
            x = 0;
            y += 22;
        }
        const cv::Point2d a(left + x + 2, y - 4), b(left + x + 34, y - 4);
        if (bars) {
            cv::rectangle(img, cv::Rect(left + x + 8, y - 12, 20, 14), s.color, cv::FILLED);
            if (s.dashed) cv::rectangle(img, cv::Rect(left + x + 8, y - 12, 20, 14), kBlack, 1);
        } else {
            if (s.dashed)
                dashedLine(img, a, b, s.color, 2);
            else
                cv::line(img, a, b, s.color, 2, cv::LINE_AA);
            drawMarker(img, (a + b) * 0.5, s.marker, s.color, s.dashed);
        }
        text(img, s.label, {left + x + 40, y}, 0.45, kBlack);
        x += w;
    }
}

struct Axis {
    double lo = 0, hi = 1;
    bool log = false;
    double t(double v) const {
        if (log) {
            const double l = std::log10(std::max(v, lo));
            return (l - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
        }
        return (v - lo) / (hi - lo);
    }
};

/// "Nice" ticks between lo and hi.
std::vector<double> niceTicks(double lo, double hi, bool log) {
    std::vector<double> out;
    if (log) {
        for (double p = std::pow(10.0, std::floor(std::log10(lo))); p <= hi * 1.0001; p *= 10.0)
            if (p >= lo * 0.9999) out.push_back(p);
        return out;
    }
    const double span = hi - lo;
    const double raw = span / 5.0;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (m * mag >= raw) {
            step = m * mag;
            break;
        }
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * span; v += step) out.push_back(v);
    return out;
}

double niceCeil(double v) {
    if (!(v > 0)) return 1.0;
    const double mag = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0})
        if (m * mag >= v * 1.0001) return m * mag;
    return 10.0 * mag;
}

/// Where a line chart's values land in its picture: the plot box and the two axes.
struct ChartMapping {
    cv::Rect box;
    Axis x, y;
    double px(double v) const { return box.x + x.t(v) * box.width; }
    double py(double v) const { return box.y + box.height - std::clamp(y.t(v), -0.02, 1.02) * box.height; }
};

/// The data's extent: x and y over every drawn point (y with its error bar), and the x ticks
/// (the chart's, else every x that has a point), unsorted.
struct DataRange {
    double xlo = 1e300, xhi = -1e300, ylo = 1e300, yhi = -1e300;
    std::vector<double> x_ticks;
};

DataRange dataRange(const LineChart &c) {
    DataRange r;
    r.x_ticks = c.x_ticks;
    for (const auto &s : c.series)
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (std::isnan(s.y[i])) continue;
            r.xlo = std::min(r.xlo, s.x[i]);
            r.xhi = std::max(r.xhi, s.x[i]);
            const double e = i < s.err.size() && !std::isnan(s.err[i]) ? s.err[i] : 0.0;
            r.ylo = std::min(r.ylo, s.y[i] - e);
            r.yhi = std::max(r.yhi, s.y[i] + e);
            if (c.x_ticks.empty() && std::find(r.x_ticks.begin(), r.x_ticks.end(), s.x[i]) == r.x_ticks.end())
                r.x_ticks.push_back(s.x[i]);
        }
    for (double x : c.x_ticks) {
        r.xlo = std::min(r.xlo, x);
        r.xhi = std::max(r.xhi, x);
    }
    for (const auto &h : c.h_lines) r.yhi = std::max(r.yhi, h.value);
    return r;
}

/// The x axis: the data's extent padded by 6 % (a unit around a single x).
Axis lineChartXAxis(double xlo, double xhi) {
    if (xlo > xhi) xlo = 0, xhi = 1;
    if (xhi - xlo < 1e-9) xlo -= 0.5, xhi += 0.5;
    const double xpad = 0.06 * (xhi - xlo);
    return Axis{xlo - xpad, xhi + xpad, false};
}

/// The y axis: the chart's fixed range, else decades (log) or zero to a nice ceiling.
Axis lineChartYAxis(const LineChart &c, double ylo, double yhi) {
    Axis ay;
    ay.log = c.log_y;
    if (c.y_max > c.y_min) {
        ay.lo = c.y_min;
        ay.hi = c.y_max;
    } else if (c.log_y) {
        ay.lo = std::pow(10.0, std::floor(std::log10(std::max(1.0, ylo > 0 && ylo < 1e300 ? ylo : 1.0))));
        ay.hi = std::pow(10.0, std::ceil(std::log10(std::max(10.0, yhi > -1e300 ? yhi : 10.0))));
    } else {
        ay.lo = std::min(0.0, ylo < 1e300 ? ylo : 0.0);
        ay.hi = niceCeil(yhi > -1e300 ? yhi : 1.0);
    }
    if (ay.log && ay.lo <= 0) ay.lo = 1.0;
    return ay;
}

/// Grid, axes, ticks, the title and the axis labels.
void drawLineChartFrame(cv::Mat &img, const LineChart &c, const ChartMapping &m, std::vector<double> x_ticks) {
    const cv::Rect &box = m.box;
    for (double v : niceTicks(m.y.lo, m.y.hi, m.y.log)) {
        const double y = m.py(v);
        cv::line(img, cv::Point2d(box.x, y), cv::Point2d(box.x + box.width, y), kGrid, 1);
        text(img, fmt(v), {box.x - 8, cvRound(y) + 5}, 0.45, kGreyText, 2);
    }
    std::sort(x_ticks.begin(), x_ticks.end());
    for (double v : x_ticks) {
        const double x = m.px(v);
        cv::line(img, cv::Point2d(x, box.y), cv::Point2d(x, box.y + box.height), kGrid, 1);
        text(img, fmt(v), {cvRound(x), box.y + box.height + 20}, 0.45, kGreyText, 1);
    }
    cv::rectangle(img, box, kBlack, 1);
    text(img, c.title, {c.size.width / 2, 26}, 0.6, kBlack, 1, 1);
    text(img, c.x_label, {box.x + box.width / 2, box.y + box.height + 42}, 0.5, kBlack, 1);
    verticalText(img, c.y_label, {18, box.y + box.height / 2}, 0.5, kBlack);
}

void drawReferenceLines(cv::Mat &img, const LineChart &c, const ChartMapping &m) {
    for (const auto &h : c.h_lines) {
        const double y = m.py(h.value);
        dashedLine(img, cv::Point2d(m.box.x, y), cv::Point2d(m.box.x + m.box.width, y), kGreyText, 1);
        const int ty = h.label_below ? cvRound(y) + 15 : cvRound(y) - 5;
        if (h.label_left)
            text(img, h.label, {m.box.x + 6, ty}, 0.42, kGreyText, 0);
        else
            text(img, h.label, {m.box.x + m.box.width - 6, ty}, 0.42, kGreyText, 2);
    }
}

/// One series: its line (broken at NaN), error bars and markers.
void drawLineSeries(cv::Mat &img, const Series &s, const ChartMapping &m) {
    cv::Point2d prev;
    bool have_prev = false;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
        if (std::isnan(s.y[i])) {
            have_prev = false;
            continue;
        }
        const cv::Point2d p(m.px(s.x[i]), m.py(s.y[i]));
        if (have_prev) {
            if (s.dashed)
                dashedLine(img, prev, p, s.color, 2);
            else
                cv::line(img, prev, p, s.color, 2, cv::LINE_AA);
        }
        if (i < s.err.size() && !std::isnan(s.err[i]) && s.err[i] > 0) {
            const double y0 = m.py(s.y[i] - s.err[i]), y1 = m.py(s.y[i] + s.err[i]);
            cv::line(img, cv::Point2d(p.x, y0), cv::Point2d(p.x, y1), s.color, 1, cv::LINE_AA);
            cv::line(img, cv::Point2d(p.x - 4, y0), cv::Point2d(p.x + 4, y0), s.color, 1, cv::LINE_AA);
            cv::line(img, cv::Point2d(p.x - 4, y1), cv::Point2d(p.x + 4, y1), s.color, 1, cv::LINE_AA);
        }
        drawMarker(img, p, s.marker, s.color, s.dashed);
        prev = p;
        have_prev = true;
    }
}

}  // namespace

cv::Mat drawLineChart(const LineChart &c) {
    cv::Mat img(c.size, CV_8UC3, kWhite);
    const int left = 78, right = 20, top = 40;
    const int legend_h = legendHeight(c.series, c.size.width - left - right);
    const int bottom = 52 + legend_h;
    const DataRange range = dataRange(c);
    ChartMapping m;
    m.box = cv::Rect(left, top, c.size.width - left - right, c.size.height - top - bottom);
    m.x = lineChartXAxis(range.xlo, range.xhi);
    m.y = lineChartYAxis(c, range.ylo, range.yhi);
    drawLineChartFrame(img, c, m, range.x_ticks);
    drawReferenceLines(img, c, m);
    for (const auto &s : c.series) drawLineSeries(img, s, m);
    drawLegend(img, c.series, m.box.x, m.box.y + m.box.height + 50, m.box.width, false);
    return img;
}

cv::Mat drawBarChart(const BarChart &c) {
    cv::Mat img(c.size, CV_8UC3, kWhite);
    const int left = 70, right = 16, top = 40;
    const int legend_h = legendHeight(c.series, c.size.width - left - right);
    const int bottom = 58 + legend_h;
    const cv::Rect box(left, top, c.size.width - left - right, c.size.height - top - bottom);
    double yhi = 0.0;
    for (const auto &s : c.series)
        for (std::size_t i = 0; i < s.y.size(); ++i)
            if (!std::isnan(s.y[i]))
                yhi = std::max(yhi, s.y[i] + (i < s.err.size() && !std::isnan(s.err[i]) ? s.err[i] : 0.0));
    const double ymax = c.y_max > 0 ? c.y_max : niceCeil(yhi);
    auto Y = [&](double y) { return box.y + box.height - std::clamp(y / ymax, 0.0, 1.0) * box.height; };
    for (double v : niceTicks(0.0, ymax, false)) {
        const double y = Y(v);
        cv::line(img, cv::Point2d(box.x, y), cv::Point2d(box.x + box.width, y), kGrid, 1);
        text(img, fmt(v), {box.x - 8, cvRound(y) + 5}, 0.45, kGreyText, 2);
    }
    const int n = static_cast<int>(c.categories.size());
    const int m = std::max<int>(1, static_cast<int>(c.series.size()));
    const double group = n > 0 ? static_cast<double>(box.width) / n : box.width;
    const double bar = 0.8 * group / m;
    for (int i = 0; i < n; ++i) {
        const double gx = box.x + i * group + 0.1 * group;
        for (int k = 0; k < static_cast<int>(c.series.size()); ++k) {
            const Series &s = c.series[k];
            if (i >= static_cast<int>(s.y.size()) || std::isnan(s.y[i])) continue;
            const double x0 = gx + k * bar, x1 = x0 + bar - 2;
            const cv::Rect r(cv::Point(cvRound(x0), cvRound(Y(s.y[i]))), cv::Point(cvRound(x1), box.y + box.height));
            cv::rectangle(img, r, s.color, cv::FILLED);
            if (s.dashed) cv::rectangle(img, r, kBlack, 1);
            if (i < static_cast<int>(s.err.size()) && !std::isnan(s.err[i]) && s.err[i] > 0) {
                const double cx = 0.5 * (x0 + x1);
                const double y0 = Y(s.y[i] - s.err[i]), y1 = Y(s.y[i] + s.err[i]);
                cv::line(img, cv::Point2d(cx, y0), cv::Point2d(cx, y1), kBlack, 1, cv::LINE_AA);
                cv::line(img, cv::Point2d(cx - 3, y1), cv::Point2d(cx + 3, y1), kBlack, 1, cv::LINE_AA);
            }
        }
        // Category label, split at '|' into two lines.
        const std::string &cat = c.categories[i];
        const auto bar_pos = cat.find('|');
        const int cx = cvRound(box.x + (i + 0.5) * group);
        text(img, cat.substr(0, bar_pos), {cx, box.y + box.height + 18}, 0.42, kBlack, 1);
        if (bar_pos != std::string::npos)
            text(img, cat.substr(bar_pos + 1), {cx, box.y + box.height + 36}, 0.42, kGreyText, 1);
        if (i > 0) {
            const double x = box.x + i * group;
            cv::line(img, cv::Point2d(x, box.y + box.height), cv::Point2d(x, box.y + box.height + 6), kBlack, 1);
        }
    }
    cv::rectangle(img, box, kBlack, 1);
    text(img, c.title, {c.size.width / 2, 26}, 0.6, kBlack, 1);
    verticalText(img, c.y_label, {16, box.y + box.height / 2}, 0.5, kBlack);
    drawLegend(img, c.series, box.x, box.y + box.height + 52, box.width, true);
    return img;
}

cv::Mat tilePanels(const std::vector<cv::Mat> &panels, int cols, const std::string &title) {
    cols = std::max(1, cols);
    const int rows = static_cast<int>((panels.size() + cols - 1) / cols);
    int cw = 0, ch = 0;
    for (const auto &p : panels) {
        cw = std::max(cw, p.cols);
        ch = std::max(ch, p.rows);
    }
    const int title_h = title.empty() ? 0 : 44;
    cv::Mat page(title_h + rows * ch, std::max(1, cols * cw), CV_8UC3, kWhite);
    if (!title.empty()) text(page, title, {page.cols / 2, 30}, 0.75, kBlack, 1, 2);
    for (std::size_t i = 0; i < panels.size(); ++i) {
        cv::Mat p = panels[i];
        if (p.channels() == 1) cv::cvtColor(p, p, cv::COLOR_GRAY2BGR);
        const int r = static_cast<int>(i) / cols, c = static_cast<int>(i) % cols;
        p.copyTo(page(cv::Rect(c * cw + (cw - p.cols) / 2, title_h + r * ch, p.cols, p.rows)));
    }
    return page;
}

cv::Mat withCaption(const cv::Mat &image, const std::string &caption, double font_scale) {
    int base = 0;
    const cv::Size sz = cv::getTextSize(caption, kFont, font_scale, 2, &base);
    const int h = sz.height + base + 18;
    cv::Mat out(image.rows + h, image.cols, CV_8UC3, cv::Scalar(50, 50, 50));
    cv::Mat img = image;
    if (img.channels() == 1) cv::cvtColor(img, img, cv::COLOR_GRAY2BGR);
    img.copyTo(out(cv::Rect(0, h, img.cols, img.rows)));
    cv::putText(out, caption, {12, sz.height + 9}, kFont, font_scale, kWhite, 2, cv::LINE_AA);
    return out;
}

}  // namespace projsurf::eval
