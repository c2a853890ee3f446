// Placeholder until the correct command lands; it refuses to run.
#include "cli/commands.hpp"
#include "projsurf/io/errors.hpp"

namespace projsurf::cli {

void addCorrectCommand(CLI::App &app) {
    auto *sub = app.add_subcommand("correct", "(not available yet)");
    sub->allow_extras();
    sub->callback([] { throw InputError("correct", "this command is not available in this build yet"); });
}

}  // namespace projsurf::cli
