// Placeholder until the show command lands; it refuses to run.
#include "cli/commands.hpp"
#include "projsurf/io/errors.hpp"

namespace projsurf::cli {

void addShowCommand(CLI::App &app) {
    auto *sub = app.add_subcommand("show", "(not available yet)");
    sub->allow_extras();
    sub->callback([] { throw InputError("show", "this command is not available in this build yet"); });
}

}  // namespace projsurf::cli
