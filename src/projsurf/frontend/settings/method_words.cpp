#include "projsurf/frontend/settings/method_words.hpp"

#include "projsurf/io/files/errors.hpp"

namespace projsurf::frontend {

Method parseMethod(const std::string &what, const std::string &word) {
    Method method = Method::Default;
    if (!methodFromName(word, method)) throw InputError(what, "expected 'default' or 'paper', got '" + word + "'");
    return method;
}

HullKind parseHull(const std::string &what, const std::string &word) {
    HullKind hull = HullKind::Concave;
    if (!hullFromName(word, hull)) throw InputError(what, "expected 'concave' or 'convex', got '" + word + "'");
    return hull;
}

}  // namespace projsurf::frontend
