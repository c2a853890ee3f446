#pragma once
// Whether bytes are well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates, at most
// U+10FFFF): what a string must be before it goes into JSON.
#include <string>

namespace projsurf {

bool isUtf8(const std::string &bytes);

}  // namespace projsurf
