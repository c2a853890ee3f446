#include "cli/commands.hpp"
#include "projsurf/io/errors.hpp"

namespace projsurf::cli {

void addDetectCommand(CLI::App &app) {
    auto *sub = app.add_subcommand("detect", "(not available yet)");
    sub->allow_extras();
    sub->callback([] { throw InputError("detect", "not available yet"); });
}

}  // namespace projsurf::cli
