#pragma once
// Third-party decoders (libpng, libjpeg, FFmpeg, OpenCV) print their own diagnostics on
// stderr; projsurf's contract is one line per failure, its own. While a QuietStderr lives,
// file descriptor 2 goes to /dev/null (the process's one stderr: use it around library
// calls in the command-line tool's thread, never around projsurf's own messages).
namespace projsurf {

class QuietStderr {
public:
    QuietStderr();
    ~QuietStderr();
    QuietStderr(const QuietStderr &) = delete;
    QuietStderr &operator=(const QuietStderr &) = delete;

private:
    int saved_ = -1;
};

}  // namespace projsurf
