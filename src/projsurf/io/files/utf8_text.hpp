#pragma once
// Whether bytes are well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates, at most
// U+10FFFF): what a string must be before it goes into JSON or onto a terminal.
#include <string>

namespace projsurf {

bool isUtf8(const std::string &bytes);
/// The bytes with each one that is not part of well-formed UTF-8 written as \xNN (a message
/// that quotes a file's bytes or a non-UTF-8 file name stays readable UTF-8).
std::string utf8Escaped(const std::string &bytes);
/// Text from a file (a key, a value) as a message may quote it: one line of UTF-8, every
/// control character (a newline that would start a forged `projsurf: error:` line, a tab, an
/// escape sequence) and every byte that is not UTF-8 written \xNN, and at most `max_bytes` of
/// it (then "...").
std::string shownText(const std::string &bytes, std::size_t max_bytes = 80);

}  // namespace projsurf
