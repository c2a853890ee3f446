#pragma once
// yaml-cpp 0.7 (Debian 12's) never returns, and takes memory until it is killed, on a ',' that
// its scanner reads as a flow-collection separator where a document's root is expected:
// ",a", "- a\n,b", "[1], 2", "\"x\", b", "&a , b" (found by scripts/fuzz.sh). YAML 1.2 lets a
// ',' begin no plain scalar, so a ',' at the start of a token outside [ ] and { } is malformed
// wherever it stands; this finds one before yaml-cpp sees the text.
#include <string>

namespace projsurf {

/// The line (1-based) of the first ',' outside quotes, comments, block scalars and flow
/// collections that begins a token: first on its line, or after "- ", ": ", "? ", a closed
/// flow collection, a quoted scalar, an anchor or a tag. 0 when there is none.
int strayCommaLine(const std::string &text);

}  // namespace projsurf
