#include "projsurf/calibration/projector_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <Eigen/Dense>
#include <Eigen/Geometry>

namespace projsurf {

namespace {

/// Parameters: fx fy cx cy k1 k2 | rotation increment (axis-angle) | origin.
constexpr int kParams = 12;

struct Model {
    double fx, fy, cx, cy, k1, k2;
    Eigen::Matrix3d R;  ///< camera -> projector coordinates
    Eigen::Vector3d C;  ///< lens centre, camera frame

    Model moved(const Eigen::Matrix<double, kParams, 1> &d) const {
        Model m = *this;
        m.fx += d[0], m.fy += d[1], m.cx += d[2], m.cy += d[3], m.k1 += d[4], m.k2 += d[5];
        const Eigen::Vector3d w(d[6], d[7], d[8]);
        if (w.norm() > 0) m.R = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix() * R;
        m.C += Eigen::Vector3d(d[9], d[10], d[11]);
        return m;
    }
    bool project(const Eigen::Vector3d &X, Eigen::Vector2d &px) const {
        const Eigen::Vector3d q = R * (X - C);
        if (!(q.z() > 1e-6)) return false;
        const double x = q.x() / q.z(), y = q.y() / q.z(), r2 = x * x + y * y;
        const double radial = 1.0 + r2 * (k1 + r2 * k2);
        px = {cx + fx * x * radial, cy + fy * y * radial};
        return true;
    }
    Projector toProjector(int width, int height) const {
        Projector p;
        p.width = width;
        p.height = height;
        p.origin = C;
        p.intrinsics = ProjectorIntrinsics{fx, fy, cx, cy};
        p.distortion = {k1, k2, 0, 0, 0};
        p.setRotation(R.transpose());
        const auto fov = fieldOfView(p);
        p.fov_h = fov[0];
        p.fov_v = fov[1];
        return p;
    }
};

/// DLT with Hartley normalisation; nullopt when degenerate.
bool linearStart(const std::vector<ProjectorCorrespondence> &pairs, Model &m) {
    const std::size_t n = pairs.size();
    const std::size_t step = std::max<std::size_t>(1, n / 6000);
    Eigen::Vector3d mean3 = Eigen::Vector3d::Zero();
    Eigen::Vector2d mean2 = Eigen::Vector2d::Zero();
    std::size_t used = 0;
    for (std::size_t i = 0; i < n; i += step, ++used) mean3 += pairs[i].point, mean2 += pairs[i].pixel;
    mean3 /= used;
    mean2 /= used;
    double s3 = 0, s2 = 0;
    for (std::size_t i = 0; i < n; i += step)
        s3 += (pairs[i].point - mean3).norm(), s2 += (pairs[i].pixel - mean2).norm();
    s3 = std::sqrt(3.0) / (s3 / used);
    s2 = std::sqrt(2.0) / (s2 / used);
    Eigen::MatrixXd A(2 * used, 12);
    std::size_t row = 0;
    for (std::size_t i = 0; i < n; i += step) {
        const Eigen::Vector3d X = (pairs[i].point - mean3) * s3;
        const Eigen::Vector2d u = (pairs[i].pixel - mean2) * s2;
        const Eigen::Vector4d Xh(X.x(), X.y(), X.z(), 1.0);
        A.row(row) << Xh.transpose(), Eigen::RowVector4d::Zero(), -u.x() * Xh.transpose();
        A.row(row + 1) << Eigen::RowVector4d::Zero(), Xh.transpose(), -u.y() * Xh.transpose();
        row += 2;
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
    const Eigen::VectorXd h = svd.matrixV().col(11);
    Eigen::Matrix<double, 3, 4> Pn;
    Pn << h.segment<4>(0).transpose(), h.segment<4>(4).transpose(), h.segment<4>(8).transpose();
    // Undo the normalisations: P = T2^-1 Pn T3.
    Eigen::Matrix3d T2inv = Eigen::Matrix3d::Identity();
    T2inv(0, 0) = T2inv(1, 1) = 1.0 / s2;
    T2inv.block<2, 1>(0, 2) = mean2;
    Eigen::Matrix4d T3 = Eigen::Matrix4d::Identity();
    T3.block<3, 3>(0, 0) *= s3;
    T3.block<3, 1>(0, 3) = -s3 * mean3;
    Eigen::Matrix<double, 3, 4> P = T2inv * Pn * T3;
    Eigen::Matrix3d M = P.block<3, 3>(0, 0);
    if (M.determinant() < 0) {
        P = -P;
        M = -M;
    }
    if (!(std::abs(M.determinant()) > 0) || !P.allFinite()) return false;
    // RQ decomposition of M = K R via QR of the flipped transpose.
    Eigen::Matrix3d flip;
    flip << 0, 0, 1, 0, 1, 0, 1, 0, 0;
    Eigen::HouseholderQR<Eigen::Matrix3d> qr((flip * M).transpose());
    Eigen::Matrix3d Q = qr.householderQ();
    Eigen::Matrix3d Rt = qr.matrixQR().triangularView<Eigen::Upper>();
    Eigen::Matrix3d K = flip * Rt.transpose() * flip;
    Eigen::Matrix3d R = flip * Q.transpose();
    for (int i = 0; i < 3; ++i)
        if (K(i, i) < 0) {
            K.col(i) *= -1;
            R.row(i) *= -1;
        }
    if (R.determinant() < 0) return false;
    K /= K(2, 2);
    m.fx = K(0, 0);
    m.fy = K(1, 1);
    m.cx = K(0, 2);
    m.cy = K(1, 2);
    m.k1 = m.k2 = 0;
    m.R = R;
    m.C = -M.inverse() * P.col(3);
    return std::isfinite(m.fx) && m.fx > 0 && m.fy > 0 && m.C.allFinite();
}

struct Stats {
    double rms = 0, max = 0;
    std::size_t inliers = 0;
};

/// The Huber cost of the reprojection errors (points behind the projector: 1e6 each).
double huberCost(const std::vector<ProjectorCorrespondence> &pts, const std::vector<char> &use, const Model &m,
                 double huber) {
    double c = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (!use[i]) continue;
        Eigen::Vector2d px;
        if (!m.project(pts[i].point, px)) {
            c += 1e6;
            continue;
        }
        const double e = (px - pts[i].pixel).norm();
        c += e <= huber ? 0.5 * e * e : huber * (e - 0.5 * huber);
    }
    return c;
}

/// Weighted LM; `active[j]` says which parameters move; points with weight 0 are skipped.
/// Runs until no step lowers the cost by more than `cost_eps` of it, or `iterations` steps.
FitConvergence levenbergMarquardt(const std::vector<ProjectorCorrespondence> &pts, const std::vector<char> &use,
                                  Model &m, const std::array<bool, kParams> &active, double huber, int iterations,
                                  double cost_eps, const char *name) {
    FitConvergence conv;
    conv.fit = name;
    conv.cap = iterations;
    const double steps[kParams] = {1e-3, 1e-3, 1e-3, 1e-3, 1e-6, 1e-6, 1e-7, 1e-7, 1e-7, 1e-7, 1e-7, 1e-7};
    double lambda = 1e-3;
    auto cost = [&](const Model &mm) { return huberCost(pts, use, mm, huber); };
    double current = cost(m);
    for (int it = 0; it < iterations; ++it) {
        Eigen::Matrix<double, kParams, kParams> JtJ = Eigen::Matrix<double, kParams, kParams>::Zero();
        Eigen::Matrix<double, kParams, 1> Jtr = Eigen::Matrix<double, kParams, 1>::Zero();
        std::array<Model, kParams> shifted;
        for (int j = 0; j < kParams; ++j) {
            Eigen::Matrix<double, kParams, 1> d = Eigen::Matrix<double, kParams, 1>::Zero();
            d[j] = steps[j];
            shifted[j] = m.moved(d);
        }
        for (std::size_t i = 0; i < pts.size(); ++i) {
            if (!use[i]) continue;
            Eigen::Vector2d px;
            if (!m.project(pts[i].point, px)) continue;
            const Eigen::Vector2d r = px - pts[i].pixel;
            const double e = r.norm();
            const double w = e <= huber ? 1.0 : huber / e;  // IRLS weight of the Huber loss
            Eigen::Matrix<double, 2, kParams> J = Eigen::Matrix<double, 2, kParams>::Zero();
            for (int j = 0; j < kParams; ++j) {
                if (!active[j]) continue;
                Eigen::Vector2d pj;
                if (!shifted[j].project(pts[i].point, pj)) continue;
                J.col(j) = (pj - px) / steps[j];
            }
            JtJ.noalias() += w * J.transpose() * J;
            Jtr.noalias() += w * J.transpose() * r;
        }
        for (int j = 0; j < kParams; ++j)
            if (!active[j]) JtJ(j, j) = 1.0, Jtr[j] = 0.0;
        bool improved = false;
        for (int tries = 0; tries < 10; ++tries) {
            Eigen::Matrix<double, kParams, kParams> A = JtJ;
            for (int j = 0; j < kParams; ++j) A(j, j) += lambda * std::max(JtJ(j, j), 1e-12);
            Eigen::Matrix<double, kParams, 1> step = A.ldlt().solve(-Jtr);
            // The rotation increment is in the step's scale of 1: fine; the others are absolute.
            for (int j = 0; j < kParams; ++j)
                if (!active[j]) step[j] = 0;
            const Model trial = m.moved(step);
            const double c = cost(trial);
            if (c < current) {
                const double gain = (current - c) / std::max(current, 1e-30);
                conv.last_step = gain;
                conv.last_step_px = std::max({std::abs(trial.fx - m.fx), std::abs(trial.fy - m.fy),
                                              std::abs(trial.cx - m.cx), std::abs(trial.cy - m.cy)});
                m = trial;
                current = c;
                lambda = std::max(lambda / 3, 1e-9);
                improved = gain > cost_eps;
                break;
            }
            lambda *= 4;
        }
        conv.iterations = it + 1;
        if (!improved) return conv;
    }
    // Every step still lowered the cost by more than cost_eps: stopped on the cap.
    conv.on_cap = iterations > 0;
    return conv;
}

Stats residuals(const std::vector<ProjectorCorrespondence> &pts, const std::vector<char> &use, const Model &m) {
    Stats s;
    double sum = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (!use[i]) continue;
        Eigen::Vector2d px;
        if (!m.project(pts[i].point, px)) continue;
        const double e = (px - pts[i].pixel).norm();
        sum += e * e;
        s.max = std::max(s.max, e);
        ++s.inliers;
    }
    s.rms = s.inliers ? std::sqrt(sum / s.inliers) : 0;
    return s;
}

}  // namespace

ProjectorFit fitProjector(const std::vector<ProjectorCorrespondence> &all, const ProjectorFitConfig &cfg) {
    ProjectorFit fit;
    char buf[400];
    if (all.size() < cfg.min_points) {
        std::snprintf(buf, sizeof buf,
                      "only %zu decoded projector pixels (need %zu): darken the room, point the projector at a "
                      "plain light surface the camera sees, and capture again",
                      all.size(), cfg.min_points);
        fit.problem = buf;
        return fit;
    }
    std::vector<ProjectorCorrespondence> pts;
    const std::size_t step = std::max<std::size_t>(1, (all.size() + cfg.max_points - 1) / cfg.max_points);
    for (std::size_t i = 0; i < all.size(); i += step) pts.push_back(all[i]);
    fit.points = pts.size();

    // Relief: a single plane (one flat wall from one pose) cannot separate focal length from distance.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto &p : pts) mean += p.point;
    mean /= pts.size();
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto &p : pts) cov += (p.point - mean) * (p.point - mean).transpose();
    cov /= pts.size();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    fit.relief_m = std::sqrt(std::max(0.0, es.eigenvalues()[0]));
    // Coverage of the framebuffer by the decoded pixels.
    std::vector<char> cells(16 * 10, 0);
    for (const auto &p : pts) {
        const int cx = std::clamp(static_cast<int>((p.pixel.x() + 0.5) / cfg.width * 16), 0, 15);
        const int cy = std::clamp(static_cast<int>((p.pixel.y() + 0.5) / cfg.height * 10), 0, 9);
        cells[cy * 16 + cx] = 1;
    }
    fit.coverage = std::count(cells.begin(), cells.end(), 1) / 160.0;
    if (fit.relief_m < cfg.min_relief_m) {
        std::snprintf(buf, sizeof buf,
                      "the decoded points lie on one plane (%.1f mm from it, RMS): a flat wall from one position "
                      "cannot fix the lens; capture 2-3 robot positions (pose_0, pose_1, ...) at different distances "
                      "and angles, or one position where the picture falls on a wall and the floor or a box",
                      fit.relief_m * 1000);
        fit.problem = buf;
        return fit;
    }

    Model m;
    if (!linearStart(pts, m)) {
        fit.problem = "the linear start (DLT) failed: the decoded points do not determine a projector; capture again";
        return fit;
    }
    std::array<bool, kParams> active;
    active.fill(true);
    active[4] = active[5] = false;  // distortion after the pinhole has settled
    std::vector<char> use(pts.size(), 1);
    const int cap = std::max(1, cfg.max_iterations);
    fit.convergence.push_back(levenbergMarquardt(pts, use, m, active, cfg.huber_px, cap, cfg.cost_eps, "pinhole"));
    fit.distortion_terms = fit.coverage >= cfg.coverage_k2 ? 2 : (fit.coverage >= cfg.coverage_k1 ? 1 : 0);
    active[4] = fit.distortion_terms >= 1;
    active[5] = fit.distortion_terms >= 2;
    fit.convergence.push_back(levenbergMarquardt(pts, use, m, active, cfg.huber_px, cap, cfg.cost_eps, "distortion"));
    // Trim gross outliers (misdecoded pixels, mixed depth at edges) and refit.
    for (std::size_t i = 0; i < pts.size(); ++i) {
        Eigen::Vector2d px;
        use[i] = m.project(pts[i].point, px) && (px - pts[i].pixel).norm() <= cfg.trim_px;
    }
    fit.convergence.push_back(levenbergMarquardt(pts, use, m, active, cfg.huber_px, cap, cfg.cost_eps, "trimmed"));
    const Stats s = residuals(pts, use, m);
    fit.rms_px = s.rms;
    fit.max_px = s.max;
    fit.inliers = s.inliers;
    fit.projector = m.toProjector(cfg.width, cfg.height);
    if (!isValidProjector(fit.projector) || s.inliers < cfg.min_points / 2) {
        fit.problem =
            "the fit did not converge to a usable projector; capture again with more of the picture on "
            "surfaces the camera sees";
        return fit;
    }
    fit.ok = true;
    return fit;
}

ProjectorFit fitProjectorPoses(const std::vector<std::vector<ProjectorCorrespondence>> &poses,
                               const ProjectorFitConfig &cfg) {
    auto joined = [&](std::size_t skip) {
        std::vector<ProjectorCorrespondence> all;
        for (std::size_t k = 0; k < poses.size(); ++k)
            if (k != skip) all.insert(all.end(), poses[k].begin(), poses[k].end());
        return all;
    };
    ProjectorFit fit = fitProjector(joined(poses.size()), cfg);
    if (!fit.ok || poses.size() < 3) return fit;
    std::vector<std::optional<ProjectorEstimate>> loo;
    int on_cap = 0;
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const ProjectorFit f = fitProjector(joined(k), cfg);
        if (f.ok)
            loo.emplace_back(projectorEstimate(f.projector));
        else
            loo.emplace_back();
        for (const auto &c : f.convergence) on_cap += c.on_cap ? 1 : 0;
    }
    fit.spread = poseSpread(projectorEstimate(fit.projector), loo);
    fit.spread.on_cap = on_cap;
    return fit;
}

std::vector<std::string> projectorFitWarnings(const ProjectorFit &fit, const SpreadLimits &limits) {
    std::vector<std::string> out;
    for (const auto &c : fit.convergence)
        if (c.on_cap) {
            char buf[300];
            std::snprintf(buf, sizeof buf,
                          "the projector fit's %s stage stopped on its iteration cap (%d) still moving (last step "
                          "lowered the cost by %.1e, moved the intrinsics %.2g px): not converged",
                          c.fit.c_str(), c.cap, c.last_step, c.last_step_px);
            out.push_back(buf);
        }
    if (fit.spread.on_cap > 0)
        out.push_back(std::to_string(fit.spread.on_cap) +
                      " stage(s) of the leave-one-pose-out fits stopped on their iteration cap: the spread is uncertain");
    const std::string s = spreadWarning(fit.spread, limits);
    if (!s.empty()) out.push_back(s);
    return out;
}

}  // namespace projsurf
