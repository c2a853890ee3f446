#include "projsurf/frontend/method_words.hpp"

#include "projsurf/io/errors.hpp"

namespace projsurf::frontend {

Method parseMethod(const std::string &what, const std::string &word) {
    if (word == "default") return Method::Default;
    if (word == "paper") return Method::Paper;
    throw InputError(what, "expected 'default' or 'paper', got '" + word + "'");
}

const char *methodName(Method method) { return method == Method::Paper ? "paper" : "default"; }

HullKind parseHull(const std::string &what, const std::string &word) {
    if (word == "concave") return HullKind::Concave;
    if (word == "convex") return HullKind::Convex;
    throw InputError(what, "expected 'concave' or 'convex', got '" + word + "'");
}

const char *hullName(HullKind hull) { return hull == HullKind::Convex ? "convex" : "concave"; }

}  // namespace projsurf::frontend
