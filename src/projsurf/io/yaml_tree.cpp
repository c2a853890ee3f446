#include "projsurf/io/yaml_tree.hpp"

#include <yaml-cpp/yaml.h>

#include <set>
#include <vector>

#include "projsurf/io/errors.hpp"
#include "projsurf/io/limits.hpp"
#include "projsurf/io/utf8_text.hpp"
#include "projsurf/io/yaml_stray_comma.hpp"

namespace projsurf {
namespace {

struct TreeCheck {
    const std::string &path;
    std::uint64_t visits = 0;
    std::vector<YAML::Node> ancestors;  // the mappings and lists above the node being checked

    std::string named(const std::string &key) const {
        return key.empty() ? "the top level" : "key '" + shownText(key) + "'";
    }

    /// Checks `node` at `key` (dotted), `depth` levels down. Every bound is tested before the
    /// walk goes one level further.
    void check(const YAML::Node &node, const std::string &key, int depth) {
        if (++visits > kMaxYamlNodesVisited)
            throw InputError(path, "more than " + std::to_string(kMaxYamlNodesVisited) +
                                       " YAML nodes (aliases repeating a mapping?)");
        if (!node.IsMap() && !node.IsSequence()) return;
        for (const YAML::Node &a : ancestors)
            if (a.is(node))
                throw InputError(path, named(key) + " is an alias of a mapping or list that holds it (an alias cycle)");
        if (depth >= limits::kMaxNesting)
            throw InputError(path, named(key) + " is nested deeper than " + std::to_string(limits::kMaxNesting) +
                                       " levels (aliases followed)");
        ancestors.push_back(node);
        if (node.IsMap()) {
            std::set<std::string> keys;
            for (const auto &pair : node) {
                std::string name = "?";
                if (pair.first.IsScalar()) {
                    name = pair.first.Scalar();
                    if (!keys.insert(name).second)
                        throw InputError(path, named(key.empty() ? name : key + "." + name) + " is given twice");
                } else {
                    check(pair.first, key.empty() ? "?" : key + ".?", depth + 1);
                }
                check(pair.second, key.empty() ? name : key + "." + name, depth + 1);
            }
        } else {
            std::size_t i = 0;
            for (const YAML::Node &item : node) check(item, key + "[" + std::to_string(i++) + "]", depth + 1);
        }
        ancestors.pop_back();
    }
};

}  // namespace

YAML::Node loadCheckedYaml(const std::string &path, const std::string &text) {
    if (!isUtf8(text)) throw InputError(path, "is not UTF-8 text, as YAML must be");
    if (const int line = strayCommaLine(text))
        throw InputError(path, "malformed YAML: a ',' outside [ ] or { } begins a value (line " + std::to_string(line) + ")");
    std::vector<YAML::Node> docs;
    try {
        docs = YAML::LoadAll(text);
    } catch (const YAML::Exception &e) {
        throw InputError(path, "malformed YAML: " + shownText(e.msg) + " (line " + std::to_string(e.mark.line + 1) + ")");
    }
    if (docs.size() > 1)
        throw InputError(path, "holds " + std::to_string(docs.size()) +
                                   " YAML documents ('---' separators); one is read, so the others would be lost");
    if (docs.empty()) return YAML::Node();
    TreeCheck tree{path, 0, {}};
    try {
        tree.check(docs.front(), "", 0);
    } catch (const YAML::Exception &e) {
        throw InputError(path, "malformed YAML: " + shownText(e.msg));
    }
    return docs.front();
}

}  // namespace projsurf
