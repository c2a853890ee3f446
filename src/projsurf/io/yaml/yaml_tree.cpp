#include "projsurf/io/yaml/yaml_tree.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <set>
#include <sstream>
#include <vector>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/utf8_text.hpp"

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

// Counts document starts only. yaml-cpp 0.7 begins a new, empty document at a token it cannot
// place at a document's root (",a", "- a\n,b", "[1], 2") without consuming it, so LoadAll never
// returns and takes memory until killed (found by scripts/fuzz.sh): the documents are counted
// here, two at most, before the first is loaded.
struct DocumentStarts : YAML::EventHandler {
    std::vector<YAML::Mark> starts;
    void OnDocumentStart(const YAML::Mark &mark) override { starts.push_back(mark); }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark &, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark &, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark &, const std::string &, YAML::anchor_t, const std::string &) override {}
    void OnSequenceStart(const YAML::Mark &, const std::string &, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark &, const std::string &, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
};

/// The line (1-based) where a second document starts, or 0 when there is at most one.
int secondDocumentLine(const std::string &text) {
    std::istringstream in(text);
    YAML::Parser parser(in);
    DocumentStarts docs;
    while (docs.starts.size() < 2 && parser.HandleNextDocument(docs)) {
    }
    return docs.starts.size() < 2 ? 0 : docs.starts[1].line + 1;
}

}  // namespace

YAML::Node loadCheckedYaml(const std::string &path, const std::string &text) {
    YAML::Node root;
    try {
        if (const int line = secondDocumentLine(text))
            throw InputError(path, "holds 2 YAML documents or more (the second from line " + std::to_string(line) +
                                       ": a '---' separator, or a ',' ']' or '}' that no mapping or list holds);"
                                       " one is read, so the rest would be lost");
        root = YAML::Load(text);
    } catch (const YAML::Exception &e) {
        throw InputError(path, "malformed YAML: " + shownText(e.msg) + " (line " + std::to_string(e.mark.line + 1) + ")");
    }
    if (root.IsNull()) return root;
    TreeCheck tree{path, 0, {}};
    try {
        tree.check(root, "", 0);
    } catch (const YAML::Exception &e) {
        throw InputError(path, "malformed YAML: " + shownText(e.msg));
    }
    return root;
}

}  // namespace projsurf
