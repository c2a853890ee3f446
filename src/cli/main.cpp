// projsurf: find where a robot's projector can show a picture on a wall, and warp the
// picture so it appears undistorted there. See README.md and the contract (docs/interface.md).
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/output_paths.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/utf8_text.hpp"

namespace {

/// "--gravity -0.2,0.9,0.3": glue a value that starts with a minus sign to its option so
/// that it is not mistaken for an option of its own.
std::vector<std::string> glueNegativeValues(int argc, char **argv) {
    std::vector<std::string> out;
    for (int i = 0; i < argc; ++i) {
        std::string a = argv[i];
        const bool is_long_without_value = a.rfind("--", 0) == 0 && a.find('=') == std::string::npos && a.size() > 2;
        if (is_long_without_value && i + 1 < argc) {
            const char *next = argv[i + 1];
            if (next[0] == '-' && (std::isdigit(static_cast<unsigned char>(next[1])) || next[1] == '.')) {
                out.push_back(a + "=" + next);
                ++i;
                continue;
            }
        }
        out.push_back(a);
    }
    return out;
}

/// A message on one line of UTF-8: line breaks become "; ", bytes that are not UTF-8 (a file's
/// content or name quoted in the message) \xNN.
std::string oneLine(std::string s) {
    for (std::size_t i; (i = s.find_first_of("\r\n")) != std::string::npos;) s.replace(i, 1, "; ");
    return projsurf::utf8Escaped(s);
}

/// Every numeric option (and each number of a list) must be finite: CLI11's ranges let NaN
/// through (every comparison with it is false), and 1e400 reads as infinity.
void refuseNonFiniteNumbers(CLI::App &app) {
    const CLI::Validator finite(
        [](std::string &value) -> std::string {
            std::size_t start = 0;
            while (start <= value.size()) {
                const std::size_t end = std::min(value.find(',', start), value.size());
                const std::string word = value.substr(start, end - start);
                char *stop = nullptr;
                const double x = std::strtod(word.c_str(), &stop);
                if (!word.empty() && stop && *stop == '\0' && !std::isfinite(x))
                    return "'" + word + "' is not a finite number";
                start = end + 1;
            }
            return "";
        },
        "FINITE");
    for (CLI::App *sub : app.get_subcommands(static_cast<bool (*)(const CLI::App *)>(nullptr)))
        for (CLI::Option *opt : sub->get_options()) {
            const std::string type = opt->get_type_name();
            if (type.find("FLOAT") != std::string::npos || type.find("INT") != std::string::npos) opt->check(finite);
        }
}

/// CLI11 checks required options before it complains about unknown words, so `detect --bogus`
/// would say "--calib is required". An unknown word, when there is one, is the mistake to name.
std::string unknownWord(const CLI::App &app) {
    auto what = [](const std::string &word) {
        return (word.rfind("-", 0) == 0 ? "unknown option '" : "unexpected argument '") + word + "'";
    };
    for (const CLI::App *sub : app.get_subcommands()) {
        const std::vector<std::string> left = sub->remaining();
        if (!left.empty())
            return what(left.front()) + " for projsurf " + sub->get_name() + " (see projsurf " + sub->get_name() +
                   " --help)";
    }
    std::string names;
    for (const CLI::App *sub : app.get_subcommands(static_cast<bool (*)(const CLI::App *)>(nullptr)))
        names += (names.empty() ? "" : ", ") + sub->get_name();
    const std::vector<std::string> left = app.remaining();
    if (left.empty()) return app.get_subcommands().empty() ? "a command is required (commands: " + names + ")" : "";
    if (left.front().rfind("-", 0) == 0) return what(left.front()) + " (see projsurf --help)";
    return "unknown command '" + left.front() + "' (commands: " + names + ")";
}

}  // namespace

int main(int argc, char **argv) {
    CLI::App app{"projsurf: projection surface detection and keystone correction for mobile robots"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("projsurf ") + PROJSURF_VERSION_STRING);
    projsurf::cli::addDetectCommand(app);
    projsurf::cli::addCalibrateCommand(app);
    projsurf::cli::addCorrectCommand(app);
    projsurf::cli::addShowCommand(app);
    projsurf::cli::addSimulateCommand(app);
    projsurf::cli::addDemoCommand(app);
    projsurf::cli::addEvalCommand(app);
    projsurf::cli::addBagCommand(app);
    projsurf::cli::addPlanCommand(app);
    projsurf::cli::addPatternsCommand(app);
    projsurf::cli::addVerifyCommand(app);

    refuseNonFiniteNumbers(app);
    std::vector<std::string> args = glueNegativeValues(argc, argv);
    std::vector<char *> cargs;
    for (auto &a : args) cargs.push_back(a.data());
    try {
        projsurf::cli::refuseOutputOverInput(args);  // before any command reads or writes
        app.parse(static_cast<int>(cargs.size()), cargs.data());
    } catch (const projsurf::cli::ExitStatus &e) {
        return e.code;
    } catch (const CLI::CallForHelp &e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp &e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion &e) {
        return app.exit(e);
    } catch (const CLI::ParseError &e) {
        // Usage mistakes too carry the one error prefix (an InputError's line form).
        const std::string unknown = unknownWord(app);
        if (!unknown.empty())
            std::cerr << "projsurf: error: " << oneLine(unknown) << "\n";
        else
            std::cerr << "projsurf: error: " << oneLine(e.what()) << " (see projsurf "
                      << (app.get_subcommands().empty() ? "" : app.get_subcommands().front()->get_name() + " ")
                      << "--help)\n";
        return 2;
    } catch (const projsurf::InputError &e) {
        std::cerr << "projsurf: error: " << oneLine(e.what()) << "\n";
        return 2;
    } catch (const cv::Exception &e) {
        // OpenCV's what() spans several lines: its one-line message only.
        std::cerr << "projsurf: error: " << oneLine(e.func + ": " + e.err) << "\n";
        return 2;
    } catch (const std::bad_alloc &) {
        std::cerr << "projsurf: error: out of memory\n";
        return 2;
    } catch (const std::exception &e) {
        std::cerr << "projsurf: error: " << oneLine(e.what()) << "\n";
        return 2;
    }
    return 0;
}
