#include "projsurf/detection/method_names.hpp"

#include <cstddef>

namespace projsurf {
namespace {

template <typename E>
struct Word {
    E value;
    const char *word;
};
constexpr Word<Method> kMethods[] = {{Method::Default, "default"}, {Method::Paper, "paper"}};
constexpr Word<HullKind> kHulls[] = {{HullKind::Concave, "concave"}, {HullKind::Convex, "convex"}};

/// The word of `value` (the first entry's for a value the table lacks).
template <typename E, std::size_t N>
const char *wordOf(const Word<E> (&table)[N], E value) {
    for (const Word<E> &w : table)
        if (w.value == value) return w.word;
    return table[0].word;
}

template <typename E, std::size_t N>
bool valueOf(const Word<E> (&table)[N], std::string_view word, E &out) {
    for (const Word<E> &w : table)
        if (word == w.word) {
            out = w.value;
            return true;
        }
    return false;
}

}  // namespace

const char *methodName(Method method) { return wordOf(kMethods, method); }
const char *hullName(HullKind hull) { return wordOf(kHulls, hull); }
bool methodFromName(std::string_view word, Method &out) { return valueOf(kMethods, word, out); }
bool hullFromName(std::string_view word, HullKind &out) { return valueOf(kHulls, word, out); }

}  // namespace projsurf
