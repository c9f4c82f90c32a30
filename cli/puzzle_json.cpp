#include "puzzle_json.hpp"

#include <nlohmann/json.hpp>

namespace orthoray::cli {

const char* lazor_answer_word(LazorSolution::Status status) {
    switch (status) {
    case LazorSolution::Status::solved:
        return "solved";
    case LazorSolution::Status::unsolvable:
        return "unsolvable";
    case LazorSolution::Status::limit:
        break;
    }
    return "unknown";
}

std::string lazor_json_members(const LazorSolution& s, const std::string& limit, unsigned jobs,
                               double seconds) {
    std::string out = "\"answer\":" + nlohmann::json(lazor_answer_word(s.status)).dump();
    if (s.status == LazorSolution::Status::limit)
        out += ",\"limit\":" + nlohmann::json(limit).dump();
    if (s.placed) {
        nlohmann::json grid = nlohmann::json::array();
        for (int row = 0; row < s.placed->height; ++row) {
            std::string text;
            for (int column = 0; column < s.placed->width; ++column)
                text += std::string(column ? " " : "") + lazor_letter(s.placed->at(column, row));
            grid.push_back(text);
        }
        out += ",\"grid\":" + grid.dump();
    }
    if (!s.points.empty()) {
        nlohmann::ordered_json points = nlohmann::ordered_json::array();
        for (std::size_t i = 0; i < s.points.size(); ++i)
            points.push_back({{"point", i + 1},
                              {"x", s.placed->points[i].x},
                              {"y", s.placed->points[i].y},
                              {"laser", s.points[i].ray},
                              {"reflections", s.points[i].reflections.get_ui()}});
        out += ",\"points\":" + points.dump();
    }
    // An exact integer, printed in full.
    if (!s.solutions.empty()) out += ",\"solutions\":" + s.solutions;
    out += ",\"nodes\":" + std::to_string(s.nodes) + ",\"jobs\":" + std::to_string(jobs) +
           ",\"seconds\":" + nlohmann::json(seconds).dump();
    return out;
}

} // namespace orthoray::cli
