#include "orthoray/answer_json.hpp"

#include <nlohmann/json.hpp>

#include <sstream>

namespace orthoray {
namespace {

std::string quoted(const char* text) {
    return nlohmann::json(text).dump();
}

// The illumination question's part: one entry per target in file order
// (docs/optics.md), then the states explored.
void write_targets(std::ostream& out, const Answer& a) {
    out << ",\"targets\":[";
    for (std::size_t t = 0; t < a.targets.size(); ++t) {
        const TargetAnswer& target = a.targets[t];
        out << (t ? "," : "") << "{\"target\":" << t + 1 << ",\"answer\":";
        switch (target.status) {
        case TargetAnswer::Status::lit:
            out << "\"yes\",\"reflections\":" << target.reflections.get_str()
                << ",\"ray\":" << target.ray;
            if (target.intensity) out << ",\"intensity\":" << target.intensity->get_str();
            // Only after a limit: the best found so far, which a branch not
            // yet walked could still beat (docs/optics.md, "Limits").
            if (!target.best_proven) out << ",\"best_proven\":false";
            out << '}';
            break;
        case TargetAnswer::Status::unlit:
            out << "\"no\"}";
            break;
        case TargetAnswer::Status::unknown:
            out << "\"unknown\"}";
            break;
        }
    }
    out << "],\"states\":" << a.states.get_str();
    if (a.states_lower_bound) out << ",\"states_lower_bound\":true";
}

} // namespace

std::string engine_name(const Answer& answer, const std::string& asked) {
    return answer.engine == EngineUsed::none ? asked : to_string(answer.engine);
}

std::string answer_json_members(const Answer& a, const std::string& engine, double seconds) {
    std::ostringstream out;
    out << "\"answer\":" << quoted(answer_word(a)) << ",\"reason\":" << quoted(to_string(a.reason));
    if (a.reason == Reason::limit) out << ",\"limit\":" << quoted(to_string(a.limit));
    out << ",\"reflections\":" << a.reflections.get_str();
    if (a.reason == Reason::cycle)
        out << ",\"tail\":" << a.tail.get_str() << ",\"period\":" << a.period().get_str();
    if (a.illumination()) write_targets(out, a);
    const Answer::Stats& stats = a.stats;
    out << ",\"engine\":" << nlohmann::json(engine).dump()
        << ",\"arithmetic\":" << quoted(to_string(a.arithmetic));
    if (a.shooter != ShooterUsed::none)
        out << ",\"shooter\":" << quoted(to_string(a.shooter))
            << ",\"setup_seconds\":" << nlohmann::json(stats.setup.seconds).dump()
            << ",\"grid_cells\":" << stats.setup.cells << ",\"pieces\":" << stats.setup.pieces
            << ",\"two_step_pieces\":" << stats.setup.two_step_pieces;
    if (a.engine == EngineUsed::induction)
        out << ",\"exchange_pieces\":" << stats.induction.pieces
            << ",\"exchange_states\":" << stats.induction.states.get_str()
            << ",\"induction_steps\":" << stats.induction.steps
            << ",\"induction_rounds\":" << stats.induction.rounds
            << ",\"induction_seconds\":" << nlohmann::json(stats.induction.seconds).dump();
    out << ",\"seconds\":" << nlohmann::json(seconds).dump();
    return out.str();
}

} // namespace orthoray
