// orthoray: decide whether a ray among axis-aligned mirrors reaches a point.
#include "commands.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/version.hpp"
#include "output_file.hpp"

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

} // namespace

int main(int argc, char** argv) {
    using namespace orthoray::cli;
    mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
    // A closed pipe or a file size limit must be a failed write, reported,
    // not a silent death by SIGPIPE or SIGXFSZ in the middle of a file.
    std::signal(SIGPIPE, SIG_IGN);
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{
        "orthoray: decides exactly whether a light ray among axis-aligned mirrors\n"
        "reaches a target point, and proves the answer with a certificate.\n\n"
        "Example:\n"
        "  orthoray solve instances/2d/box-corner-3x5.scene --certificate path.cert\n"
        "  orthoray verify instances/2d/box-corner-3x5.scene path.cert\n"
        "  orthoray generate box --sides 3 5 -o box.scene\n"
        "  orthoray bounds box.scene\n"
        "  orthoray batch instances/ -o results.jsonl\n\n"
        "Exit status: 0 yes (or valid), 1 no (or invalid), 2 bad input or usage,\n"
        "3 a resource limit (steps, time, memory) or SIGINT/SIGTERM stopped the run first,\n"
        "4 an internal error, 5 an output could not be written (full disk, closed pipe).\n"
        "Scene formats and rules: docs/scene-format.md, docs/scene-json.md,\n"
        "docs/semantics.md. Pictures: docs/render.md."};
    app.name("orthoray");
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("orthoray ") + orthoray::version);
    Command solve = add_solve(app);
    Command verify = add_verify(app);
    Command pieces = add_pieces(app);
    Command generate = add_generate(app);
    Command bounds = add_bounds(app);
    Command render = add_render(app);
    Command convert = add_convert(app);
    Command puzzle = add_puzzle(app);
    Command realistic = add_realistic(app);
    Command batch = add_batch(app);

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
        if (e.get_exit_code() == 0) return app.exit(e); // --help, --version
        std::cerr << "orthoray: " << e.what() << " (see 'orthoray --help')\n";
        return bad_input;
    }
    try {
        const int status = app.got_subcommand("solve")       ? solve()
                           : app.got_subcommand("verify")    ? verify()
                           : app.got_subcommand("generate")  ? generate()
                           : app.got_subcommand("bounds")    ? bounds()
                           : app.got_subcommand("render")    ? render()
                           : app.got_subcommand("convert")   ? convert()
                           : app.got_subcommand("puzzle")    ? puzzle()
                           : app.got_subcommand("realistic") ? realistic()
                           : app.got_subcommand("batch")     ? batch()
                                                             : pieces();
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
