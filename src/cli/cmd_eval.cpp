// Placeholder until the eval command lands; it refuses to run.
#include "cli/commands.hpp"
#include "projsurf/io/errors.hpp"

namespace projsurf::cli {

void addEvalCommand(CLI::App &app) {
    auto *sub = app.add_subcommand("eval", "(not available yet)");
    sub->allow_extras();
    sub->callback([] { throw InputError("eval", "this command is not available in this build yet"); });
}

}  // namespace projsurf::cli
