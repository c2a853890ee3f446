#pragma once
// Each subcommand lives in its own file and registers itself on the app. A command reports
// bad input by throwing projsurf::InputError (main prints it and exits 2).
#include <CLI/CLI.hpp>
#include <string>

namespace projsurf::cli {

/// A command that finished and said why on stderr, but whose result must not be used as it
/// is: main exits with `code` (calibrate: 3 when the fit's verdict is redo).
struct ExitStatus {
    int code;
};
constexpr int kExitRedo = 3;  ///< calibrate: written, but the captures disagree (verdict redo)
constexpr int kExitCheckFailed = 3;  ///< verify: result written, but a corner landed beyond --tolerance

/// " with the settings of FILE" when a settings file was given, else "": appended to the input
/// that a detection's OpenCV failure names, so that a settings value at the end of its range
/// that still fails names the file it came from (issue 39), not only the frame.
inline std::string withSettings(const std::string &config_file) {
    return config_file.empty() ? std::string() : " with the settings of " + config_file;
}

void addDetectCommand(CLI::App &app);     // cmd_detect.cpp
void addCalibrateCommand(CLI::App &app);  // cmd_calibrate.cpp
void addCorrectCommand(CLI::App &app);    // cmd_correct.cpp
void addShowCommand(CLI::App &app);       // cmd_show.cpp
void addSimulateCommand(CLI::App &app);   // cmd_simulate.cpp
void addDemoCommand(CLI::App &app);       // cmd_demo.cpp
void addEvalCommand(CLI::App &app);       // cmd_eval.cpp
void addBagCommand(CLI::App &app);        // cmd_bag.cpp
void addPlanCommand(CLI::App &app);       // cmd_plan.cpp
void addPatternsCommand(CLI::App &app);   // cmd_patterns.cpp
void addVerifyCommand(CLI::App &app);     // cmd_verify.cpp

}  // namespace projsurf::cli
