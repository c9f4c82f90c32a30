#include "man_page.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace orthoray::cli {
namespace {

// Text made safe for roff: a backslash is written \e, a hyphen \- (so that
// options copy and paste as ASCII), and a line may not start with a control
// character ('.' or '\'').
std::string roff(const std::string& text) {
    std::string out;
    bool line_start = true;
    for (const char c : text) {
        if (line_start && (c == '.' || c == '\'')) out += "\\&";
        if (c == '\\')
            out += "\\e";
        else if (c == '-')
            out += "\\-";
        else
            out += c;
        line_start = c == '\n';
    }
    return out;
}

// "orthoray puzzle solve" for a nested subcommand.
std::string command_path(const CLI::App& app) {
    return app.get_parent() ? command_path(*app.get_parent()) + ' ' + app.get_name()
                            : app.get_name();
}

std::string page_name(const CLI::App& app) {
    std::string name = command_path(app);
    for (char& c : name)
        if (c == ' ') c = '-';
    return name;
}

// A description's prose lines become paragraphs; its "Example:" block and
// other indented lines stay as they are (no filling).
void write_description(std::ostream& out, const std::string& text) {
    std::istringstream lines(text);
    std::string line;
    bool literal = false;
    while (std::getline(lines, line)) {
        const bool indented = line.starts_with("  ");
        if (indented && !literal) out << ".nf\n";
        if (!indented && literal) out << ".fi\n";
        literal = indented;
        out << (line.empty() ? std::string(".PP") : roff(line)) << '\n';
    }
    if (literal) out << ".fi\n";
}

void write_option(std::ostream& out, const CLI::Option& option) {
    std::string names;
    for (const std::string& s : option.get_snames()) names += (names.empty() ? "-" : ", -") + s;
    for (const std::string& l : option.get_lnames()) names += (names.empty() ? "--" : ", --") + l;
    if (option.get_positional()) names = option.get_name(true);
    out << ".TP\n\\fB" << roff(names) << "\\fR";
    if (!option.get_type_name().empty()) out << " \\fI" << roff(option.get_type_name()) << "\\fR";
    out << '\n' << roff(option.get_description());
    if (option.get_required()) out << " (required)";
    out << '\n';
}

void write_page(const CLI::App& app, const std::filesystem::path& dir, const std::string& version,
                std::vector<std::filesystem::path>& written) {
    const std::string name = page_name(app);
    const std::filesystem::path file = dir / (name + ".1");
    std::ofstream out(file);
    out << ".TH " <<
        [&] {
            std::string upper;
            for (const char c : name) upper += static_cast<char>(std::toupper(c));
            return roff(upper);
        }()
        << " 1 \"\" \"orthoray " << version << "\" \"orthoray manual\"\n";
    out << ".SH NAME\n" << roff(name) << " \\- " << roff(summary(app.get_description())) << '\n';
    out << ".SH SYNOPSIS\n\\fB" << roff(command_path(app)) << "\\fR [OPTIONS]";
    for (const CLI::Option* option : app.get_options())
        if (option->get_positional())
            out << (option->get_required() ? " " : " [") << roff(option->get_name(true))
                << (option->get_required() ? "" : "]");
    const std::vector<const CLI::App*> subs = app.get_subcommands({});
    if (!subs.empty()) out << " COMMAND";
    out << "\n.SH DESCRIPTION\n";
    write_description(out, app.get_description());
    if (!subs.empty()) {
        out << ".SH COMMANDS\n";
        for (const CLI::App* sub : subs)
            out << ".TP\n\\fB" << roff(sub->get_name()) << "\\fR\n"
                << roff(summary(sub->get_description())) << " See \\fB" << roff(page_name(*sub))
                << "\\fR(1).\n";
    }
    out << ".SH OPTIONS\n";
    for (const CLI::Option* option : app.get_options()) write_option(out, *option);
    out << ".SH EXIT STATUS\n"
           "0 yes (or valid), 1 no (or invalid), 2 bad input or usage, 3 a resource limit "
           "(steps, time, memory) or SIGINT/SIGTERM stopped the run first, 4 an internal error, "
           "5 an output could not be written.\n"
           ".SH SEE ALSO\n";
    if (app.get_parent()) out << "\\fB" << roff(page_name(*app.get_parent())) << "\\fR(1), ";
    out << "the documentation in /usr/share/doc/orthoray and docs/ of the source.\n";
    if (!out) throw std::runtime_error("could not write " + file.string());
    written.push_back(file);
    for (const CLI::App* sub : subs) write_page(*sub, dir, version, written);
}

} // namespace

std::string summary(const std::string& text) {
    // Up to a full stop, question mark, colon or semicolon outside
    // parentheses that ends a word, or a blank line.
    std::string first;
    int depth = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        depth += c == '(' ? 1 : c == ')' ? -1 : 0;
        const bool word_end = i + 1 == text.size() || text[i + 1] == ' ' || text[i + 1] == '\n';
        if (depth == 0 && word_end && (c == '.' || c == '?' || c == ':' || c == ';')) {
            if (c == '?') first += c;
            break;
        }
        if (c == '\n' && i + 1 < text.size() && text[i + 1] == '\n') break;
        first += c == '\n' ? ' ' : c;
    }
    return first;
}

std::vector<std::filesystem::path>
write_man_pages(const CLI::App& app, const std::filesystem::path& dir, const std::string& version) {
    std::vector<std::filesystem::path> written;
    write_page(app, dir, version, written);
    return written;
}

} // namespace orthoray::cli
