// The command line's own documentation: the one-line subcommand list of
// --help, usage errors that point to the subcommand's help, `version
// --json`, and the man pages and bash completion generated from the parser's
// definitions (cli/man_page.cpp, cli/bash_completion.cpp): each page and the
// completion script must know every option the program's --help shows.
#include "support/run_cli.hpp"

#include <boost/version.hpp>
#include <catch2/catch.hpp>
#include <gmp.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

using orthoray::test::CliResult;
using orthoray::test::run_cli;

namespace {

const std::filesystem::path share_dir = ORTHORAY_SHARE_DIR;

// The lines of `text` after the line `header`, up to the next blank line.
std::vector<std::string> section(const std::string& text, const std::string& header) {
    std::istringstream in(text);
    std::vector<std::string> lines;
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        if (inside && line.empty()) break;
        if (inside) lines.push_back(line);
        if (line == header) inside = true;
    }
    return lines;
}

// The commands orthoray names when given an unknown one: an enumeration
// independent of the help formatter.
std::vector<std::string> commands() {
    const CliResult r = run_cli("no-such-command");
    const std::string list = r.err.substr(r.err.find("expected ") + 9);
    std::vector<std::string> names;
    const std::regex word("[a-z]+");
    for (auto it = std::sregex_iterator(list.begin(), list.begin() + list.find(" (see"), word);
         it != std::sregex_iterator(); ++it)
        if (it->str() != "or") names.push_back(it->str());
    return names;
}

// Every long option listed in the Options: section of a --help text (the
// lines that start with an option's names; descriptions that mention other
// options do not count).
std::set<std::string> long_options(const std::string& help) {
    std::set<std::string> options;
    const std::regex entry(R"(^\s+(-[A-Za-z],)?(--[a-z][a-z0-9-]*))");
    for (const std::string& line : section(help, "Options:")) {
        std::smatch m;
        if (std::regex_search(line, m, entry)) options.insert(m[2].str());
    }
    return options;
}

std::string read(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

} // namespace

TEST_CASE("orthoray --help lists each subcommand on one line", "[cli][help]") {
    const CliResult r = run_cli("--help");
    REQUIRE(r.status == 0);
    const std::vector<std::string> lines = section(r.out, "Subcommands:");
    const std::vector<std::string> names = commands();
    REQUIRE(names.size() >= 10);
    REQUIRE(lines.size() == names.size());
    for (std::size_t i = 0; i < names.size(); ++i) {
        INFO(lines[i]);
        CHECK(lines[i].starts_with("  " + names[i] + " "));
        CHECK(lines[i].size() < 130);
    }
}

TEST_CASE("a usage error points to the subcommand's own help", "[cli][help]") {
    CliResult r = run_cli("solve --no-such-option x.scene");
    CHECK(r.status == 2);
    CHECK(r.err.find("(see 'orthoray solve --help')") != std::string::npos);
    r = run_cli("puzzle solve");
    CHECK(r.status == 2);
    CHECK(r.err.find("(see 'orthoray puzzle solve --help')") != std::string::npos);
    r = run_cli("--no-such-option");
    CHECK(r.err.find("(see 'orthoray --help')") != std::string::npos);
}

TEST_CASE("orthoray version --json names the libraries it was built with", "[cli][help]") {
    const CliResult r = run_cli("version --json");
    REQUIRE(r.status == 0);
    const nlohmann::json v = nlohmann::json::parse(r.out);
    const CliResult short_form = run_cli("--version");
    CHECK(short_form.out == "orthoray " + v["orthoray"].get<std::string>() + "\n");
    CHECK(v["gmp"] == std::string(gmp_version));
    CHECK(v["boost"] == std::to_string(BOOST_VERSION / 100000) + "." +
                            std::to_string(BOOST_VERSION / 100 % 1000) + "." +
                            std::to_string(BOOST_VERSION % 100));
    CHECK(v["compiler"].get<std::string>().size() > 4);
    // A git checkout's commit, 12 hex digits and "-dirty" when it had
    // changes, or "unknown" (cmake/write_commit.cmake; tested there).
    const std::string commit = v["commit"].get<std::string>();
    CHECK(std::regex_match(commit, std::regex("[0-9a-f]{12}(-dirty)?|unknown")));
}

TEST_CASE("every subcommand has a man page that lists every option its --help shows",
          "[cli][help]") {
    const std::vector<std::string> names = commands();
    std::vector<std::string> paths{""};
    for (const std::string& name : names) paths.push_back(name);
    for (const char* sub : {"scene", "solve", "generate"})
        paths.push_back(std::string("puzzle ") + sub);
    for (const std::string& path : paths) {
        std::string page = "orthoray" + (path.empty() ? "" : "-" + path);
        for (char& c : page)
            if (c == ' ') c = '-';
        INFO(page);
        const std::filesystem::path file = share_dir / "man1" / (page + ".1");
        REQUIRE(std::filesystem::exists(file));
        std::string text = read(file);
        // roff writes a hyphen as \-.
        text = std::regex_replace(text, std::regex(R"(\\-)"), "-");
        for (const std::string& option : long_options(run_cli(path + " --help").out)) {
            INFO(option);
            CHECK(std::regex_search(text, std::regex(R"((\\fB|, ))" + option + "([^a-z0-9-]|$)")));
        }
    }
}

TEST_CASE("the bash completion completes subcommands, options and their choices", "[cli][help]") {
    const std::filesystem::path script = share_dir / "completions" / "orthoray";
    REQUIRE(std::filesystem::exists(script));
    // COMP_WORDS as bash sets them; prints COMPREPLY, one word a line, sorted.
    auto complete = [&](const std::string& words) {
        const std::string command = "bash -c 'source \"" + script.string() + "\"; COMP_WORDS=(" +
                                    words +
                                    "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _orthoray; "
                                    "printf \"%s\\n\" \"${COMPREPLY[@]}\" | LC_ALL=C sort' 2>&1";
        std::string out;
        if (FILE* pipe = popen(command.c_str(), "r")) {
            char buffer[256];
            while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
            pclose(pipe);
        }
        return out;
    };
    CHECK(complete("orthoray so") == "solve\n");
    CHECK(complete("orthoray puzzle s") == "scene\nsolve\n");
    CHECK(complete("orthoray solve --engine \"\"") ==
          "auto\ngraph\ninduction\nlattice\nreference\n");
    CHECK(complete("orthoray puzzle solve --j") == "--jobs\n--json\n");
    CHECK(complete("orthoray batch --max-steps \"\"") == "\n");
    // Every option of solve's --help is offered after "solve --".
    const std::string offered = complete("orthoray solve --");
    for (const std::string& option : long_options(run_cli("solve --help").out)) {
        INFO(option);
        CHECK(offered.find(option + "\n") != std::string::npos);
    }
}
