// projsurf show: put a framebuffer (image or video) full screen on a display, the way a robot
// drives its projector (an X display; OpenCV's highgui window).
#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <opencv2/highgui.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <optional>

#include "cli/commands.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/video_files.hpp"

namespace projsurf::cli {
namespace {

struct ShowOptions {
    std::string image, video, display;
    int screen = -1;       // X screen number (":0.N"); -1 = the display's default
    double seconds = 0.0;  // 0 = until a key is pressed (or the video ends)
    bool loop = false;     // restart the video at its end
};

const char *kWindow = "projsurf";

/// "host:D.S" with the screen part replaced by `screen` (when >= 0).
std::string withScreen(std::string display, int screen) {
    if (screen < 0) return display;
    const auto colon = display.rfind(':');
    const auto dot = display.find('.', colon == std::string::npos ? 0 : colon);
    if (dot != std::string::npos) display.erase(dot);
    return display + "." + std::to_string(screen);
}

/// The size of the X screen on `display`; nullopt when no X server answers there. GTK exits
/// the process when it cannot open the display, so ask Xlib first (loaded at run time: nothing
/// else of projsurf needs it). A zero size when Xlib itself is unavailable.
std::optional<cv::Size> xScreenSize(const std::string &display) {
    void *lib = dlopen("libX11.so.6", RTLD_LAZY | RTLD_LOCAL);
    if (!lib) return cv::Size();  // cannot check; let highgui try
    using Open = void *(*)(const char *);
    using Close = int (*)(void *);
    using Screen = int (*)(void *);
    using Extent = int (*)(void *, int);
    auto open = reinterpret_cast<Open>(dlsym(lib, "XOpenDisplay"));
    auto close = reinterpret_cast<Close>(dlsym(lib, "XCloseDisplay"));
    auto screen = reinterpret_cast<Screen>(dlsym(lib, "XDefaultScreen"));
    auto width = reinterpret_cast<Extent>(dlsym(lib, "XDisplayWidth"));
    auto height = reinterpret_cast<Extent>(dlsym(lib, "XDisplayHeight"));
    std::optional<cv::Size> size = cv::Size();
    if (open && close && screen && width && height) {
        void *d = open(display.c_str());
        if (!d) {
            size.reset();
        } else {
            const int s = screen(d);
            size = cv::Size(width(d, s), height(d, s));
            close(d);
        }
    }
    // (libX11 stays loaded: unloading it under the GUI toolkit is not safe)
    return size;
}

/// A borderless window covering the screen, showing `first`. Full screen is asked of the
/// window manager; a projector's X server often runs without one, so the window is also placed
/// at (0, 0) and sized to the screen, and the picture fills it (no aspect-ratio bars). Qt's
/// highgui only honours this once the window has been shown, hence the first imshow.
void openFullscreen(const cv::Mat &first, cv::Size screen) {
    cv::namedWindow(kWindow, cv::WINDOW_NORMAL | cv::WINDOW_FREERATIO | cv::WINDOW_GUI_NORMAL);
    cv::imshow(kWindow, first);
    cv::waitKey(50);
    cv::moveWindow(kWindow, 0, 0);
    if (screen.area() > 0) cv::resizeWindow(kWindow, screen.width, screen.height);
    cv::setWindowProperty(kWindow, cv::WND_PROP_FULLSCREEN, cv::WINDOW_FULLSCREEN);
}

/// False once the user closed the window.
bool windowOpen() {
    try {
        return cv::getWindowProperty(kWindow, cv::WND_PROP_VISIBLE) > 0 ||
               cv::getWindowProperty(kWindow, cv::WND_PROP_AUTOSIZE) >= 0;
    } catch (const cv::Exception &) {
        return false;
    }
}

void run(const ShowOptions &o) {
    if (o.image.empty() == o.video.empty()) throw InputError("show", "give exactly one of --image or --video");
    if (o.seconds < 0) throw InputError("--seconds", "must not be negative");
    // Inputs first.
    cv::Mat image;
    cv::VideoCapture cap;
    double fps = 25.0;
    if (!o.image.empty()) {
        image = readImage(o.image, cv::IMREAD_COLOR);
    } else {
        cap = openVideoInput(o.video);
        bool first = false;
        try {
            first = cap.read(image) && !image.empty();
        } catch (const cv::Exception &) {
        }
        if (!first) throw InputError(o.video, "no frame could be read");
        const double f = cap.get(cv::CAP_PROP_FPS);
        if (f > 0 && f < 1000) fps = f;
    }
    // Then the display.
    std::string display = o.display;
    if (display.empty()) {
        const char *env = std::getenv("DISPLAY");
        display = env ? env : "";
    }
    if (display.empty()) throw InputError("show", "no display: set DISPLAY or pass --display (e.g. --display :0)");
    display = withScreen(display, o.screen);
    const auto screen = xScreenSize(display);
    if (!screen) throw InputError(display, "cannot open this X display");
    if (screen->area() > 0 && screen.value() != image.size())
        std::cerr << "projsurf: warning: the framebuffer is " << image.cols << "x" << image.rows
                  << " but the screen is " << screen->width << "x" << screen->height
                  << "; it is stretched to fill the screen\n";
    ::setenv("DISPLAY", display.c_str(), 1);
    if (!std::getenv("XDG_RUNTIME_DIR")) {
        // Qt wants a private runtime directory and warns when it has to pick one itself.
        const std::string dir = "/tmp/runtime-" + std::to_string(::getuid());
        ::mkdir(dir.c_str(), 0700);
        ::setenv("XDG_RUNTIME_DIR", dir.c_str(), 1);
    }

    openFullscreen(image, *screen);
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const int frame_ms = std::max(1, static_cast<int>(1000.0 / fps));
    for (;;) {
        cv::imshow(kWindow, image);
        const int key = cv::waitKey(o.video.empty() ? 30 : frame_ms);
        if (key >= 0 || !windowOpen()) break;
        if (o.seconds > 0 && elapsed() >= o.seconds) break;
        if (!o.video.empty()) {
            cv::Mat next;
            if (!cap.read(next) || next.empty()) {
                if (!o.loop) {
                    if (o.seconds > 0) continue;  // hold the last frame until the time is up
                    break;
                }
                cap.set(cv::CAP_PROP_POS_FRAMES, 0);
                if (!cap.read(next) || next.empty()) break;
            }
            image = next;
        }
    }
    cv::destroyAllWindows();
    cv::waitKey(1);
}

}  // namespace

void addShowCommand(CLI::App &app) {
    auto opts = std::make_shared<ShowOptions>();
    auto *sub = app.add_subcommand("show", "show a framebuffer image or video full screen (the projector's output)");
    sub->add_option("--image", opts->image, "framebuffer image (projsurf correct --out)");
    sub->add_option("--video", opts->video, "framebuffer video or image-sequence pattern");
    sub->add_option("--display", opts->display, "X display, e.g. :0 (default: $DISPLAY)");
    sub->add_option("--screen-index", opts->screen, "X screen of that display (:D.N), e.g. the projector's");
    sub->add_option("--seconds", opts->seconds, "close after this many seconds (default: at a key press)");
    sub->add_flag("--loop", opts->loop, "play the video again at its end");
    sub->callback([opts] { run(*opts); });
}

}  // namespace projsurf::cli
