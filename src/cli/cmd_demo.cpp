// Placeholder until the demo command lands; it refuses to run.
#include "cli/commands.hpp"
#include "projsurf/io/errors.hpp"

namespace projsurf::cli {

void addDemoCommand(CLI::App &app) {
    auto *sub = app.add_subcommand("demo", "(not available yet)");
    sub->allow_extras();
    sub->callback([] { throw InputError("demo", "this command is not available in this build yet"); });
}

}  // namespace projsurf::cli
