#include "projsurf/detection/method_names.hpp"

namespace projsurf {
namespace {

struct MethodWord {
    Method method;
    const char *word;
};
constexpr MethodWord kMethods[] = {{Method::Default, "default"}, {Method::Paper, "paper"}};

struct HullWord {
    HullKind hull;
    const char *word;
};
constexpr HullWord kHulls[] = {{HullKind::Concave, "concave"}, {HullKind::Convex, "convex"}};

}  // namespace

const char *methodName(Method method) {
    for (const MethodWord &m : kMethods)
        if (m.method == method) return m.word;
    return kMethods[0].word;
}

const char *hullName(HullKind hull) {
    for (const HullWord &h : kHulls)
        if (h.hull == hull) return h.word;
    return kHulls[0].word;
}

bool methodFromName(std::string_view word, Method &out) {
    for (const MethodWord &m : kMethods)
        if (word == m.word) {
            out = m.method;
            return true;
        }
    return false;
}

bool hullFromName(std::string_view word, HullKind &out) {
    for (const HullWord &h : kHulls)
        if (word == h.word) {
            out = h.hull;
            return true;
        }
    return false;
}

}  // namespace projsurf
