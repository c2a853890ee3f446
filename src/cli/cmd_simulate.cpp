// Placeholder until the simulate command lands; it refuses to run.
#include "cli/commands.hpp"
#include "projsurf/io/errors.hpp"

namespace projsurf::cli {

void addSimulateCommand(CLI::App &app) {
    auto *sub = app.add_subcommand("simulate", "(not available yet)");
    sub->allow_extras();
    sub->callback([] { throw InputError("simulate", "this command is not available in this build yet"); });
}

}  // namespace projsurf::cli
