// orthoray: decide whether a ray among axis-aligned mirrors reaches a point.
#include "app.hpp"
#include "orthoray/allocator_policy.hpp"
#include "orthoray/parse.hpp"
#include "output_file.hpp"
#include "stop_at_once.hpp"

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <gmp.h>
#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace {

// GMP's own allocator aborts when memory runs out; these throw instead, so
// that running out (of --max-memory, say) is the resource limit it is.
void* gmp_allocate(std::size_t size) {
    if (void* p = std::malloc(size)) return p;
    throw std::bad_alloc();
}
void* gmp_reallocate(void* old, std::size_t, std::size_t size) {
    if (void* p = std::realloc(old, size)) return p;
    throw std::bad_alloc();
}
void gmp_free(void* p, std::size_t) {
    std::free(p);
}

// The help that fits a usage error: that of the deepest subcommand named
// on the command line ("orthoray puzzle solve --help"), else orthoray's.
std::string help_command(int argc, char** argv, const CLI::App& app) {
    std::string command = "orthoray";
    const CLI::App* at = &app;
    for (int i = 1; i < argc; ++i) {
        const auto subs =
            at->get_subcommands([&](const CLI::App* sub) { return sub->get_name() == argv[i]; });
        if (subs.empty()) break;
        at = subs.front();
        command += ' ' + at->get_name();
    }
    return command + " --help";
}

} // namespace

int main(int argc, char** argv) {
    using namespace orthoray::cli;
    // From the first line on, SIGINT and SIGTERM stop any command at once
    // (exit 3, nothing written: stop_at_once.hpp), not by the default
    // action, which would exit 130 or 143 and leave a temporary output
    // behind. Commands that report how far they got set their own handling
    // over this one (InterruptGuard), and once a result is decided the
    // signals are held back (stop_no_more), so no stop cuts it short.
    stop_at_once(std::nullopt);
    orthoray::keep_freed_memory();
    mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
    // A closed pipe or a file size limit must be a failed write, reported,
    // not a silent death by SIGPIPE or SIGXFSZ in the middle of a file.
    std::signal(SIGPIPE, SIG_IGN);
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app;
    const std::vector<Subcommand> subcommands = build_cli(app);

    // CLI11 would call an unknown command a missing one; name it instead,
    // with the commands as registered, so the list cannot drift.
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
        commands.push_back(sub->get_name());
    if (argc > 1 && argv[1][0] != '-' &&
        std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
        std::cerr << "orthoray: found the command '" << argv[1] << "', expected ";
        for (std::size_t i = 0; i < commands.size(); ++i)
            std::cerr << (i == 0 ? "" : i + 1 == commands.size() ? " or " : ", ") << commands[i];
        std::cerr << " (see 'orthoray --help')\n";
        return bad_input;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) { // --help, --version: a failed write is still one
            stop_no_more();
            const int status = app.exit(e);
            try {
                finish_standard_output();
            } catch (const WriteError& error) {
                std::cerr << "orthoray: " << error.what() << '\n';
                return write_failed;
            }
            return status;
        }
        std::cerr << "orthoray: " << e.what() << " (see '" << help_command(argc, argv, app)
                  << "')\n";
        return bad_input;
    }
    try {
        int status = internal_error;
        for (const Subcommand& sub : subcommands)
            if (sub.app->parsed()) status = sub.run();
        stop_no_more(); // decided: what is left is flushing it
        finish_standard_output();
        return status;
    } catch (const WriteError& e) {
        std::cerr << "orthoray: " << e.what() << '\n';
        return write_failed;
    } catch (const orthoray::ReadInterrupted& e) {
        std::cerr << "orthoray: " << e.what() << '\n';
        return limit;
    } catch (const orthoray::InputError& e) {
        std::cerr << e.what() << '\n';
        return bad_input;
    } catch (const orthoray::UnsupportedScene& e) {
        std::cerr << "orthoray: " << e.what() << '\n';
        return bad_input;
    } catch (const UsageError& e) {
        std::cerr << "orthoray: " << e.what() << '\n';
        return bad_input;
    } catch (const std::bad_alloc&) {
        std::cerr << "orthoray: out of memory\n";
        return limit;
    } catch (const std::exception& e) {
        std::cerr << "orthoray: internal error: " << e.what() << " (please report this)\n";
        return internal_error;
    }
}
