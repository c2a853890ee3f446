// Placeholder until the calibrate command lands; it refuses to run.
#include "cli/commands.hpp"
#include "projsurf/io/errors.hpp"

namespace projsurf::cli {

void addCalibrateCommand(CLI::App &app) {
    auto *sub = app.add_subcommand("calibrate", "(not available yet)");
    sub->allow_extras();
    sub->callback([] { throw InputError("calibrate", "this command is not available in this build yet"); });
}

}  // namespace projsurf::cli
