#include "bash_completion.hpp"

#include <string>
#include <vector>

namespace orthoray::cli {
namespace {

// "TEXT:{auto,scene,json}" -> "auto scene json"; "" when the option takes
// free text (then files are offered).
std::string choices_of(const CLI::Option& option) {
    const std::string type = option.get_type_name();
    const std::size_t open = type.find('{'), close = type.rfind('}');
    if (open == std::string::npos || close == std::string::npos || close < open) return "";
    std::string words = type.substr(open + 1, close - open - 1);
    for (char& c : words)
        if (c == ',') c = ' ';
    return words;
}

// One `case` branch a command: its path ("puzzle solve"), its options and
// subcommands, and for each option taking a value its choices (or files).
void write_command(const CLI::App& app, const std::string& path, std::ostream& out) {
    std::string words;
    std::string values; // option) choices ;; lines
    for (const CLI::Option* option : app.get_options()) {
        if (option->get_positional()) continue;
        std::string names;
        for (const std::string& s : option->get_snames()) names += " -" + s;
        for (const std::string& l : option->get_lnames()) names += " --" + l;
        words += names;
        if (option->get_type_name().empty()) continue; // a flag
        std::string pattern;
        for (std::size_t at = 1; at < names.size();) {
            const std::size_t next = names.find(' ', at);
            pattern += (pattern.empty() ? "" : "|") + names.substr(at, next - at);
            at = next == std::string::npos ? names.size() : next + 1;
        }
        // A fixed set of words is offered; a number, nothing; text, files.
        const std::string choices = choices_of(*option);
        const std::string type = option->get_type_name();
        const bool number = type.starts_with("UINT") || type.starts_with("INT") ||
                            type.starts_with("FLOAT") || type.starts_with("NUMBER");
        values += "            " + pattern + ") " +
                  (!choices.empty() ? "COMPREPLY=($(compgen -W '" + choices + "' -- \"$cur\"))"
                   : number         ? std::string("COMPREPLY=()")
                                    : std::string("_orthoray_files")) +
                  "; return ;;\n";
    }
    std::string subs;
    for (const CLI::App* sub : app.get_subcommands({})) subs += ' ' + sub->get_name();
    out << "    \"" << path << "\")\n";
    if (!values.empty()) out << "        case \"$prev\" in\n" << values << "        esac\n";
    out << "        opts=\"" << words.substr(words.empty() ? 0 : 1) << "\" subs=\""
        << subs.substr(subs.empty() ? 0 : 1) << "\" ;;\n";
    for (const CLI::App* sub : app.get_subcommands({}))
        write_command(*sub, path.empty() ? sub->get_name() : path + ' ' + sub->get_name(), out);
}

// The subcommands of each command path, for walking the command line: a
// word is the next subcommand only where the path so far has one so named.
void write_subcommands(const CLI::App& app, const std::string& path, std::ostream& out) {
    const std::vector<const CLI::App*> subs = app.get_subcommands({});
    if (subs.empty()) return;
    out << "    \"" << path << "\") echo";
    for (const CLI::App* sub : subs) out << ' ' << sub->get_name();
    out << " ;;\n";
    for (const CLI::App* sub : subs)
        write_subcommands(*sub, path.empty() ? sub->get_name() : path + ' ' + sub->get_name(), out);
}

} // namespace

void write_bash_completion(const CLI::App& app, std::ostream& out) {
    out << "# bash completion for orthoray, generated from its command line definitions\n"
           "# (cli/bash_completion.cpp); do not edit.\n"
           "_orthoray_files() {\n"
           "    COMPREPLY=($(compgen -f -- \"$cur\"))\n"
           "}\n"
           "_orthoray_subcommands() {\n"
           "    case \"$1\" in\n";
    write_subcommands(app, "", out);
    out << "    esac\n"
           "}\n"
           "_orthoray() {\n"
           "    local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
           "    local path=\"\" opts=\"\" subs=\"\" i\n"
           "    # The subcommands named so far, in order: \"puzzle solve\".\n"
           "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
           "        if [[ \" $(_orthoray_subcommands \"$path\") \" == *\" ${COMP_WORDS[i]} \"* ]]; "
           "then\n"
           "            path=\"${path:+$path }${COMP_WORDS[i]}\"\n"
           "        fi\n"
           "    done\n"
           "    case \"$path\" in\n";
    write_command(app, "", out);
    out << "    esac\n"
           "    if [[ \"$cur\" == -* ]]; then\n"
           "        COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\"))\n"
           "        return\n"
           "    fi\n"
           "    COMPREPLY=($(compgen -W \"$subs\" -- \"$cur\"))\n"
           "    [[ ${#COMPREPLY[@]} -gt 0 ]] || _orthoray_files\n"
           "}\n"
           "complete -o filenames -F _orthoray orthoray\n";
}

} // namespace orthoray::cli
