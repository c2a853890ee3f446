#include "projsurf/io/formats/procam_xml.hpp"

#include <cmath>

#include <Eigen/LU>
#include <opencv2/core.hpp>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"

namespace projsurf {
namespace {

cv::Mat matrix(const cv::FileStorage &fs, const std::string &path, const std::string &key, int rows, int cols,
               const std::string &alias = "") {
    cv::Mat m;
    cv::FileNode n = fs[key];
    if (n.empty() && !alias.empty()) n = fs[alias];
    if (!n.empty()) {
        // Its declared size checked before OpenCV allocates it (a flipped bit in `rows` asked
        // for 48 GB); a vector may be stored as a row or a column.
        const int want = rows * cols;
        const bool sized = n.isMap() && n["rows"].isInt() && n["cols"].isInt() && static_cast<int>(n["rows"]) >= 1 &&
                           static_cast<int>(n["rows"]) <= want && static_cast<int>(n["cols"]) >= 1 &&
                           static_cast<int>(n["cols"]) <= want &&
                           static_cast<int>(n["rows"]) * static_cast<int>(n["cols"]) == want;
        if (!sized)
            throw InputError(path,
                             "lacks a " + std::to_string(rows) + "x" + std::to_string(cols) + " matrix '" + key + "'");
        n >> m;
    }
    if (m.empty() || static_cast<int>(m.total()) != rows * cols)
        throw InputError(path,
                         "lacks a " + std::to_string(rows) + "x" + std::to_string(cols) + " matrix '" + key + "'");
    m.convertTo(m, CV_64F);
    for (int i = 0; i < static_cast<int>(m.total()); ++i)
        if (!std::isfinite(m.at<double>(i)))
            throw InputError(path, "matrix '" + key + "' holds a number that is not finite");
    return m.reshape(1, rows);
}

/// What the comparison divides by and takes angles of: positive focal lengths (at most the
/// camera limit), a rotation, a translation of non-zero length.
void checkPublished(const std::string &path, const PublishedProcam &p) {
    auto focal = [&](double fx, double fy, const char *key) {
        if (!(fx > 0 && fy > 0 && fx <= 1e6 && fy <= 1e6))
            throw InputError(path, std::string("'") + key + "' focal lengths must be positive and at most 1e6 px");
    };
    focal(p.cam_fx, p.cam_fy, "cam_int");
    focal(p.proj_fx, p.proj_fy, "proj_int");
    if ((p.rotation.transpose() * p.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-2 ||
        !(p.rotation.determinant() > 0))
        throw InputError(path, "'rotation' is not a rotation (orthonormal to 1e-2, determinant +1)");
    if (!(p.translation.norm() > 0) || !(p.translation.norm() < 1e9))
        throw InputError(path, "'translation' must have a positive, finite length");
    if (!std::isfinite(p.rms)) throw InputError(path, "'rms' is not finite");
}

/// OpenCV's XML reader is handed only a whole document: its `<?xml ...?>` header closed on the
/// first line and one `<opencv_storage>` element closed at the end (OpenCV 4.6's reader reads
/// through a null pointer on a header cut short, `<?xml versi=`: found by fuzz_procam_xml).
void checkXmlDocument(const std::string &path, const std::string &text) {
    const std::size_t start = text.find_first_not_of(" \t\r\n");
    const std::size_t eol = text.find('\n', start == std::string::npos ? 0 : start);
    const std::string first = start == std::string::npos ? "" : text.substr(start, eol - start);
    if (first.rfind("<?xml", 0) != 0 || first.find("?>") == std::string::npos)
        throw InputError(path, "not an OpenCV XML file (its first line is not an <?xml ...?> header)");
    const std::string closing = "</opencv_storage>";
    const std::size_t open = text.find("<opencv_storage>");
    const std::size_t close = text.rfind(closing);
    const std::size_t end = text.find_last_not_of(" \t\r\n");
    if (open == std::string::npos || close == std::string::npos || close < open || close + closing.size() != end + 1)
        throw InputError(path, "not an OpenCV XML file (no <opencv_storage> element from after the header to the end)");
}

}  // namespace

PublishedProcam readProcamXml(const std::string &path) {
    // Read and checked first (size, nesting, a whole document): OpenCV's parser recurses once
    // per element and trusts its input's shape.
    const std::string text = readSmallTextFile(path, limits::kMaxJsonBytes, "XML");
    checkXmlDocument(path, text);
    cv::FileStorage fs;
    try {
        fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
    } catch (const cv::Exception &) {
        throw InputError(path, "not a readable OpenCV FileStorage file");
    }
    if (!fs.isOpened()) throw InputError(path, "not a readable OpenCV FileStorage file");
    PublishedProcam p;
    try {
        const cv::Mat ci = matrix(fs, path, "cam_int", 3, 3), cd = matrix(fs, path, "cam_dist", 1, 5);
        const cv::Mat pi = matrix(fs, path, "proj_int", 3, 3), pd = matrix(fs, path, "proj_dist", 1, 5);
        const cv::Mat r = matrix(fs, path, "rotation", 3, 3, "roration"), t = matrix(fs, path, "translation", 3, 1);
        p.cam_fx = ci.at<double>(0, 0);
        p.cam_fy = ci.at<double>(1, 1);
        p.cam_cx = ci.at<double>(0, 2);
        p.cam_cy = ci.at<double>(1, 2);
        p.proj_fx = pi.at<double>(0, 0);
        p.proj_fy = pi.at<double>(1, 1);
        p.proj_cx = pi.at<double>(0, 2);
        p.proj_cy = pi.at<double>(1, 2);
        for (int i = 0; i < 5; ++i) {
            p.cam_distortion[i] = cd.at<double>(0, i);
            p.proj_distortion[i] = pd.at<double>(0, i);
        }
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) p.rotation(i, j) = r.at<double>(i, j);
            p.translation[i] = t.at<double>(i, 0);
        }
        const cv::FileNode rms = fs["rms"];
        if (rms.isReal() || rms.isInt()) p.rms = static_cast<double>(rms);
    } catch (const cv::Exception &) {
        throw InputError(path, "a matrix could not be read");
    }
    checkPublished(path, p);
    return p;
}

}  // namespace projsurf
