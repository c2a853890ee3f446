#include "projsurf/io/yaml_stray_comma.hpp"

#include <cstddef>

namespace projsurf {
namespace {

// What came last on the current line outside flow collections.
enum class Last { TokenStart, Plain, Closed };

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool isFlowIndicator(char c) { return c == ',' || c == '[' || c == ']' || c == '{' || c == '}'; }

struct Scanner {
    const std::string &t;
    std::size_t i = 0;
    int line = 1;
    int depth = 0;            // [ ] and { } open
    char quote = 0;           // the open quote, or 0
    int blockScalarIndent = -1;  // the indent of the line that opened a | or > scalar, or -1
    Last last = Last::TokenStart;

    char at(std::size_t k) const { return k < t.size() ? t[k] : '\n'; }
    bool endsToken(std::size_t k) const { return blank(at(k)) || at(k) == '\n'; }
    bool tokenStarts() const { return i == 0 || blank(t[i - 1]) || t[i - 1] == '\n' || (depth > 0 && (t[i - 1] == '[' || t[i - 1] == '{' || t[i - 1] == ',')); }

    void skipToLineEnd() {
        while (i < t.size() && t[i] != '\n') ++i;
    }

    // At a line's first character: skips a block scalar's lines, directives, comments and the
    // indentation; returns the line's indent.
    void startLine() {
        std::size_t indent = 0;
        while (at(i + indent) == ' ') ++indent;
        if (blockScalarIndent >= 0) {
            const bool empty = endsToken(i + indent) && at(i + indent) != '\t';
            if (empty || static_cast<int>(indent) > blockScalarIndent) return skipToLineEnd();
            blockScalarIndent = -1;
        }
        if (quote == 0 && depth == 0) last = Last::TokenStart;
        if (quote == 0 && t[i] == '%') return skipToLineEnd();
        i += quote == 0 ? indent : 0;
    }

    void quoted() {
        const char c = t[i++];
        if (quote == '"' && c == '\\') ++i;
        else if (quote == '\'' && c == '\'' && at(i) == '\'') ++i;
        else if (c == quote) {
            quote = 0;
            if (depth == 0) last = Last::Closed;
        }
    }

    void inFlow() {
        const char c = t[i];
        if ((c == '"' || c == '\'') && tokenStarts()) quote = c;
        else if (c == '[' || c == '{') ++depth;
        else if (c == ']' || c == '}') {
            if (--depth == 0) last = Last::Closed;
        }
        ++i;
    }

    // Returns true on a stray ','.
    bool inBlock(int indent) {
        const char c = t[i];
        const bool start = tokenStarts();
        if (c == ',') {
            ++i;
            return last != Last::Plain;  // "a, b" is one plain scalar
        }
        if (start && (c == '"' || c == '\'')) quote = c, ++i;
        else if (start && (c == '[' || c == '{')) depth = 1, ++i;
        else if (start && (c == '&' || c == '!')) {
            // An anchor or a tag (its name ends at a flow indicator): the node's value to come.
            while (!endsToken(i) && !isFlowIndicator(at(i))) ++i;
            last = Last::TokenStart;
        } else if (start && (c == '|' || c == '>')) {
            ++i;
            while (at(i) == '+' || at(i) == '-' || (at(i) >= '0' && at(i) <= '9')) ++i;
            while (blank(at(i))) ++i;
            if (at(i) == '\n' || at(i) == '#') blockScalarIndent = indent;
            last = Last::Plain;
            skipToLineEnd();
        } else if ((c == '-' || c == '?' || c == ':') && (c == ':' || start) && endsToken(i + 1)) {
            last = Last::TokenStart, ++i;
        } else if (start && (c == '-' || c == '.') && at(i + 1) == c && at(i + 2) == c && endsToken(i + 3) &&
                   (i == 0 || t[i - 1] == '\n')) {
            last = Last::TokenStart, i += 3;  // "---" or "..."
        } else {
            last = Last::Plain, ++i;
        }
        return false;
    }

    int run() {
        while (i < t.size()) {
            const std::size_t lineStart = i;
            startLine();
            int indent = static_cast<int>(i - lineStart);
            while (i < t.size() && t[i] != '\n') {
                if (quote != 0) quoted();
                else if (blank(t[i])) ++i;
                else if (t[i] == '#' && (i == 0 || blank(t[i - 1]) || t[i - 1] == '\n')) skipToLineEnd();
                else if (depth > 0) inFlow();
                else if (inBlock(indent)) return line;
            }
            ++i;
            ++line;
        }
        return 0;
    }
};

}  // namespace

int strayCommaLine(const std::string &text) { return Scanner{text}.run(); }

}  // namespace projsurf
