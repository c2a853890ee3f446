#include "projsurf/io/yaml/yaml_settings.hpp"

#include <yaml-cpp/yaml.h>

#include <set>
#include <stdexcept>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/utf8_text.hpp"
#include "projsurf/io/yaml/yaml_tree.hpp"

namespace projsurf {
namespace {

/// Mappings visited at most: aliases can repeat a mapping exponentially often in a small file.
constexpr int kMaxVisits = 100000;

/// Quoted ("6", '6') or tagged as a string (!!str 6): a word, never a number or a bool.
bool isQuoted(const YAML::Node &scalar) {
    const std::string &tag = scalar.Tag();
    return tag == "!" || tag == "tag:yaml.org,2002:str";
}

void flatten(const std::string &path, const YAML::Node &map, const std::string &prefix, int &visits,
             std::vector<SettingText> &out) {
    if (++visits > kMaxVisits) throw InputError(path, "too many keys (aliases repeating a mapping?)");
    if (prefix.size() > 4096) throw InputError(path, "a key is nested too deep");
    for (const auto &pair : map) {
        const std::string under = prefix.empty() ? "the top level" : "'" + shownText(prefix) + "'";
        if (!pair.first.IsScalar() || pair.first.Scalar().empty())
            throw InputError(path, "a key under " + under + " is not a plain word");
        const std::string key = prefix.empty() ? pair.first.Scalar() : prefix + "." + pair.first.Scalar();
        const YAML::Node &value = pair.second;
        if (value.IsMap()) {
            flatten(path, value, key, visits, out);
            continue;
        }
        if (!value.IsDefined() || value.IsNull()) throw InputError(path, "key '" + shownText(key) + "' has no value");
        SettingText s;
        s.key = key;
        if (value.IsScalar()) {
            s.items.push_back(value.Scalar());
            s.quoted = isQuoted(value);
        } else {
            s.sequence = true;
            for (const YAML::Node &item : value) {
                if (!item.IsScalar()) throw InputError(path, "key '" + shownText(key) + "' must be a list of plain values");
                s.items.push_back(item.Scalar());
                s.quoted = s.quoted || isQuoted(item);
            }
        }
        out.push_back(std::move(s));
    }
}

/// Keys sharing a prefix, in first-seen order; `leaf` is the setting's index, or -1 for a mapping.
struct KeyTree {
    std::vector<std::pair<std::string, KeyTree>> children;
    int leaf = -1;
};

void insert(KeyTree &tree, const std::string &key, int index) {
    KeyTree *node = &tree;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = key.find('.', start);
        const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        KeyTree *next = nullptr;
        for (auto &child : node->children)
            if (child.first == part) next = &child.second;
        if (!next) next = &node->children.emplace_back(part, KeyTree{}).second;
        if (next->leaf >= 0) throw std::logic_error("yamlSettingsText: '" + key + "' lies under a value");
        if (dot == std::string::npos) {
            if (!next->children.empty()) throw std::logic_error("yamlSettingsText: '" + key + "' is a mapping");
            next->leaf = index;
            return;
        }
        node = next;
        start = dot + 1;
    }
}

std::string scalarText(const std::string &item, bool quoted) {
    if (!quoted) return item;
    std::string out = "\"";
    for (char c : item) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string valueText(const SettingText &s) {
    if (!s.sequence) return s.items.empty() ? "\"\"" : scalarText(s.items.front(), s.quoted);
    std::string out = "[";
    for (std::size_t i = 0; i < s.items.size(); ++i) out += (i ? ", " : "") + scalarText(s.items[i], s.quoted);
    return out + "]";
}

void emit(const KeyTree &tree, const std::vector<SettingText> &settings, const std::vector<std::string> &comments,
          const std::string &indent, std::string &out) {
    for (const auto &[name, child] : tree.children) {
        if (child.leaf < 0) {
            if (indent.empty() && !out.empty()) out += "\n";
            out += indent + name + ":\n";
            emit(child, settings, comments, indent + "  ", out);
            continue;
        }
        const std::size_t i = static_cast<std::size_t>(child.leaf);
        if (i < comments.size() && !comments[i].empty()) out += indent + "# " + comments[i] + "\n";
        out += indent + name + ": " + valueText(settings[i]) + "\n";
    }
}

}  // namespace

std::vector<SettingText> readYamlSettings(const std::string &path) {
    const std::string text = readSmallTextFile(path, limits::kMaxSettingsYamlBytes, "YAML");
    // One document, no alias cycle, nesting and nodes bounded, no key twice in one mapping:
    // checked before flatten recurses.
    const YAML::Node root = loadCheckedYaml(path, text);
    if (root.IsNull()) return {};  // empty, or comments only
    if (!root.IsMap()) throw InputError(path, "expected a YAML mapping of settings at the top level");
    std::vector<SettingText> out;
    int visits = 0;
    try {
        flatten(path, root, "", visits, out);
    } catch (const YAML::Exception &e) {
        throw InputError(path, "malformed YAML: " + e.msg);
    }
    std::set<std::string> seen;
    for (const SettingText &s : out)
        if (!seen.insert(s.key).second) throw InputError(path, "key '" + shownText(s.key) + "' is given twice");
    return out;
}

std::string yamlSettingsText(const std::vector<SettingText> &settings, const std::vector<std::string> &comments) {
    KeyTree tree;
    for (std::size_t i = 0; i < settings.size(); ++i) insert(tree, settings[i].key, static_cast<int>(i));
    std::string out;
    emit(tree, settings, comments, "", out);
    return out;
}

}  // namespace projsurf
