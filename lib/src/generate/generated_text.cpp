// Generated scenes as .scene text, with their expected answer as a comment.
#include "orthoray/generate.hpp"

#include <sstream>

namespace orthoray {
namespace {

const char* expect_prefix = "# expect: ";

} // namespace

std::string write_generated(const GeneratedScene& generated,
                            const std::vector<std::string>& header) {
    std::ostringstream out;
    for (const std::string& line : header) out << "# " << line << '\n';
    for (const std::string& note : generated.notes) out << "# " << note << '\n';
    if (generated.expect) {
        const Expectation& e = *generated.expect;
        out << expect_prefix << (e.reason == Reason::hit ? "yes " : "no ") << to_string(e.reason)
            << ' ' << e.reflections.get_str() << '\n';
    }
    out << write_scene(generated.scene);
    return out.str();
}

std::optional<Expectation> read_expectation(std::string_view text) {
    std::istringstream in{std::string(text)};
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(expect_prefix, 0) != 0) continue;
        std::istringstream words(line.substr(std::string_view(expect_prefix).size()));
        std::string answer, reason, count;
        if (!(words >> answer >> reason >> count)) return std::nullopt;
        Expectation e;
        bool known = false;
        for (Reason r : {Reason::hit, Reason::escape, Reason::absorbed, Reason::cycle})
            if (reason == to_string(r)) {
                e.reason = r;
                known = true;
            }
        if (!known || answer != (e.reason == Reason::hit ? "yes" : "no") ||
            e.reflections.set_str(count, 10) != 0)
            return std::nullopt;
        return e;
    }
    return std::nullopt;
}

} // namespace orthoray
