#pragma once
// Input problems that the front ends turn into one line on stderr and exit status 2.
#include <stdexcept>
#include <string>

namespace projsurf {

/// A file or argument the user gave cannot be used. what() is the whole line to print:
/// "<file>: <problem>".
struct InputError : std::runtime_error {
    InputError(const std::string &file, const std::string &problem) : std::runtime_error(file + ": " + problem) {}
    explicit InputError(const std::string &message) : std::runtime_error(message) {}
};

}  // namespace projsurf
