#pragma once
// The one way projsurf parses a YAML file (settings, calibration, camera, patterns.yaml): one
// document, its tree checked before any reader walks it. yaml-cpp resolves an alias to the
// node it names, so `a: &p {b: *p}` is a mapping that holds itself: a reader that recurses
// (or follows keys) without a bound never ends. The walk here is bounded before it recurses.
#include <cstdint>
#include <string>

namespace YAML {
class Node;
}

namespace projsurf {

/// Nodes visited at most by the check (aliases count each time they are followed: they can
/// repeat a mapping exponentially often in a small file).
constexpr std::uint64_t kMaxYamlNodesVisited = 100000;

/// Parses `text`, read from `path`. InputError naming the file (and the key, escaped) on:
/// malformed YAML, more than one document (a `---`, or a stray ','
/// ']' or '}' that yaml-cpp reads as the start of another), nesting deeper than
/// limits::kMaxNesting levels with aliases followed, an alias of a mapping or list that holds
/// it (a cycle), more than kMaxYamlNodesVisited nodes, a key given twice in one mapping. An
/// empty file (or comments only) is a null node.
YAML::Node loadCheckedYaml(const std::string &path, const std::string &text);

}  // namespace projsurf
