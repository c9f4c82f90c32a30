// `pieces --json` (orthoray/pieces.hpp, PieceTableFormat::json) read back as
// a program would: on random 2D scenes, the exported rows replay the lattice
// engine's path reflection by reflection (where the ray leaves a mirror, the
// row for that mirror, direction and position names the next point, the
// mirror there and the axes flipped), and the text form lists the same rows.
#include "support/case_count.hpp"
#include "support/random_scene.hpp"

#include "orthoray/pieces.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sstream>
#include <vector>

using namespace orthoray;

namespace {

struct Recorded : PathSink {
    std::vector<std::pair<Vector, Vector>> states;
    void visit(const Vector& point, const Vector& direction) override {
        states.emplace_back(point, direction);
    }
};

Integer integer_of(const nlohmann::json& x) {
    return x.is_string() ? Integer(x.get<std::string>()) : Integer(x.get<long>());
}

// The direction's name as the tables spell it.
std::string direction_name(const Vector& v) {
    return std::string(v[0] > 0 ? "+x" : "-x") + (v[1] > 0 ? "+y" : "-y");
}

} // namespace

TEST_CASE("pieces --json replays the lattice engine's path", "[pieces]") {
    std::mt19937_64 rng(24'11);
    test::RandomSceneShape shape;
    shape.box_percent = 70;
    const int cases = test::case_count(300);
    std::uint64_t replayed = 0, escapes = 0;
    for (int i = 0; i < cases; ++i) {
        const Scene scene = test::random_scene(rng, shape);
        INFO("scene:\n" << write_scene(scene));
        std::ostringstream json, text;
        if (!write_piece_tables(scene, json, PieceTableFormat::json).available) continue;
        REQUIRE(write_piece_tables(scene, text).available);
        const nlohmann::json doc = nlohmann::json::parse(json.str());
        // The text form: the same rows, one line each, after the header.
        const std::string lines = text.str();
        REQUIRE(std::count(lines.begin(), lines.end(), '\n') ==
                static_cast<long>(3 + doc["elements"].size() + doc["pieces"].size()));
        const Integer scale[2] = {integer_of(doc["scale"][0]), integer_of(doc["scale"][1])};

        Recorded path;
        SolveOptions o;
        o.engine = Engine::lattice;
        o.max_steps = 200;
        o.path = &path;
        solve(scene, o);
        for (std::size_t s = 1; s < path.states.size(); ++s) {
            const auto& [p, v] = path.states[s];
            Integer at[2];
            for (int j = 0; j < 2; ++j) {
                const Rational x = p[j] * scale[j];
                REQUIRE(x.get_den() == 1); // on the lattice
                at[j] = x.get_num();
            }
            // The mirror the ray leaves; a corner (two mirrors) is skipped.
            std::vector<std::size_t> on;
            for (std::size_t e = 0; e < doc["elements"].size(); ++e) {
                const nlohmann::json& el = doc["elements"][e];
                const int axis = el["axis"] == "x" ? 0 : 1;
                if (el["kind"] == "mirror" && at[axis] == integer_of(el["offset"]) &&
                    integer_of(el["lo"]) <= at[1 - axis] && at[1 - axis] <= integer_of(el["hi"]))
                    on.push_back(e);
            }
            if (on.size() != 1) continue;
            const nlohmann::json& el = doc["elements"][on[0]];
            const int axis = el["axis"] == "x" ? 0 : 1;
            const Integer u = at[1 - axis];
            const nlohmann::json* row = nullptr;
            for (const nlohmann::json& r : doc["pieces"])
                if (r["element"] == on[0] && r["direction"] == direction_name(v) &&
                    integer_of(r["from"]) <= u)
                    row = &r; // rows come sorted by from: the last one holds u
            REQUIRE(row != nullptr);
            // An escape leaves no point to compare: its state is the path's
            // final one. Any other row has a next point, unless the path
            // ended there for another reason (a hit, a cycle, the step cap).
            const bool final_state = s + 1 == path.states.size();
            if ((*row)["kind"] == "escape") {
                CHECK(final_state);
                ++escapes;
                continue;
            }
            if (final_state) continue;
            const bool last = s + 2 == path.states.size();
            if ((*row)["kind"] == "absorbed") CHECK(last);
            const Integer t = integer_of((*row)["t0"]) +
                              (*row)["slope"].get<int>() * (u - integer_of((*row)["from"]));
            const auto& [q, w] = path.states[s + 1];
            for (int j = 0; j < 2; ++j)
                CHECK(q[j] * scale[j] == Rational(at[j] + (v[j] > 0 ? t : Integer(-t))));
            if (last) continue;
            const std::string flip = (*row)["flip"].get<std::string>();
            CHECK((w[0] != v[0]) == (flip.find('x') != std::string::npos));
            CHECK((w[1] != v[1]) == (flip.find('y') != std::string::npos));
            ++replayed;
        }
    }
    CHECK(replayed > 5u * static_cast<unsigned>(cases)); // 2,664 at full size
    // Seeded: 17 escapes at full size, 4 in the sanitizers' quarter.
    CHECK(escapes > 0);
}
