// lancer's command line: parses options, runs the chosen subcommand, and turns every error into
// one message and an exit code (0 ok, 1 internal failure, 2 bad input or environment).
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/interrupt.hpp"
#include "cli/commands.hpp"
#include "core/cancel.hpp"
#include "core/error.hpp"
#include "core/escape.hpp"
#include "core/process_limits.hpp"
#include "core/version.hpp"
#include "gpu/vulkan/context.hpp"
#include "gpu/vulkan/pipeline.hpp"
#include "gpu/vulkan/vk_check.hpp"
#include "view/view_command.hpp"

namespace {

// One message and the exit code for an error that ended a command.
int report(std::exception_ptr error) {
    try {
        std::rethrow_exception(error);
    } catch (const lancer::UserError& e) {
        lancer::print_error(e);
        return 2;
    } catch (const lancer::gpu::VulkanError& e) {
        std::fprintf(stderr, "lancer: GPU error: %s\n", lancer::escape_control_characters(e.what()).c_str());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "lancer: error: out of memory: render a smaller image or a smaller scene\n");
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lancer: internal error: %s\n", lancer::escape_control_characters(e.what(), true).c_str());
        return 1;
    } catch (...) {
        std::fprintf(stderr, "lancer: internal error: an unknown exception\n");
        return 1;
    }
}

}  // namespace

int main(int argc, char** argv) {
    lancer::adapt_to_address_space_limit();
    // Past a file size limit (ulimit -f), a write fails with EFBIG and is reported like a full
    // disk, instead of SIGXFSZ killing the process half way through a file.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{"lancer: an exact ray tracer on Vulkan compute"};
    app.set_version_flag("--version", std::string("lancer ") + lancer::kVersion);
    app.require_subcommand(0, 1);
    bool list_devices = false;
    app.add_flag("--list-devices", list_devices, "List the Vulkan devices and exit");

    std::vector<lancer::Subcommand> commands = {
        lancer::add_render_command(app),
        lancer::add_watch_command(app),
        lancer::add_diff_command(app),
        lancer::add_combine_command(app),
        lancer::add_view_command(app),
    };
    for (const auto& command : commands) command.app->set_version_flag("--version", app.version());

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);  // --help, --version
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "lancer: error: %s (see lancer --help)\n", lancer::escape_control_characters(e.what()).c_str());
        return 2;
    }

    // SIGINT and SIGTERM stop every phase of every command cleanly, from here on (interrupt.hpp).
    lancer::Interrupts interrupts;
    // What an interrupt left undone is said where it is known (a still, a frame, a video); an
    // interrupt elsewhere (loading, or an error that a system call interrupted by it caused) is
    // reported as what it is.
    auto interrupted = [](const std::string& what_was_left) {
        std::fprintf(stderr, "lancer: %s\n",
                     lancer::escape_control_characters(
                         lancer::Interrupted(lancer::cancellation_signal(), what_was_left).what())
                         .c_str());
        return 128 + lancer::cancellation_signal();
    };
    const int code = [&]() -> int {
        try {
            if (list_devices) return lancer::list_devices();
            for (const auto& command : commands)
                if (command.app->parsed()) return command.run();
            std::fputs(app.help().c_str(), stdout);
            return 2;
        } catch (const lancer::Interrupted& e) {
            std::fprintf(stderr, "lancer: %s\n", lancer::escape_control_characters(e.what()).c_str());
            return 128 + e.signal_number();
        } catch (const lancer::Cancelled&) {
            return interrupted("nothing was written");
        } catch (...) {
            if (lancer::cancellation_requested()) return interrupted("nothing was written");
            return report(std::current_exception());
        }
    }();
    // Error paths must be as clean as successful ones: a Vulkan validation message on the way out
    // (the renderer, and so its teardown, is gone by now) is a bug. (Successful runs check this
    // themselves and exit with 1.)
    const int result = code != 0 && code != 1 ? lancer::gpu::exit_code_after_validation(code) : code;
    // An interrupted pipeline build is still inside the driver on a thread of its own (it cannot
    // be stopped): the exit handlers, which tear down the driver and LLVM under it, must not run.
    if (lancer::gpu::abandoned_pipeline_builds() > 0) {
        std::fflush(nullptr);
        std::_Exit(result);
    }
    return result;
}
