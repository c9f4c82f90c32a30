// Illumination certificates (docs/certificates.md, section 2 of the agreed
// format) read back structurally: the branch lines are exactly the
// reachable branch states with their least labels (computed here by a plain
// Dijkstra over every state), each lit target's steps replay with the
// reference scan and count its reflections, the verdict matches the state
// graph's answer, and the JSON Lines file says the same as the text one.
// The verifier for this format is written elsewhere; this checks the writer.
#include "engine/reference_step.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"
#include "support/case_count.hpp"
#include "support/random_optics.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <tuple>

using namespace orthoray;

namespace {

using State = std::pair<Vector, Vector>;
using Label = std::pair<std::uint64_t, std::size_t>; // (reflections, ray)

std::vector<std::vector<std::string>> words_of(const std::string& text) {
    std::vector<std::vector<std::string>> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        lines.emplace_back();
        for (std::string w; words >> w;) lines.back().push_back(w);
    }
    return lines;
}

Rational number(const std::string& text) {
    const NumberToken token = read_number(text);
    REQUIRE(token.status == NumberToken::Status::ok);
    return token.value;
}

Vector vector_at(const std::vector<std::string>& words, std::size_t from, int dim) {
    Vector x;
    for (int j = 0; j < dim; ++j) x[j] = number(words.at(from + static_cast<std::size_t>(j)));
    return x;
}

// The least label of every reachable state, by Dijkstra over all states
// (the search the branch-state engine replaced), and which of them are
// branch states: rays' starts and states leaving a junction.
struct Exhaustive {
    std::map<State, Label> label;
    std::set<State> branch;
};

// Whether some arrival at p along v with its signs changed (the scenes here
// have no diagonals) meets an event there with two or more ways out: every
// element on p is asked, acting on v or not.
bool junction(const Scene& scene, const Vector& p, const Vector& v) {
    for (unsigned signs = 0; signs < (1u << scene.dim); ++signs) {
        Vector u = v;
        for (int j = 0; j < scene.dim; ++j)
            if (signs & (1u << j)) u[j] = -u[j];
        std::vector<const Element*> acting;
        for (const Element& e : scene.elements)
            if (e.contains(p) && engine::acts_on(e, u)) acting.push_back(&e);
        if (!acting.empty() && engine::event_outcome(scene.dim, acting, u).outgoing.size() >= 2)
            return true;
    }
    return false;
}

Exhaustive exhaustive(const Scene& scene) {
    Exhaustive out;
    std::priority_queue<std::pair<Label, State>, std::vector<std::pair<Label, State>>,
                        std::greater<>>
        queue;
    for (std::size_t r = 0; r < scene.rays.size(); ++r) {
        const State s{scene.rays[r].start, scene.rays[r].direction};
        out.branch.insert(s);
        queue.push({{0, r + 1}, s});
    }
    std::set<State> settled;
    while (!queue.empty()) {
        const auto [label, s] = queue.top();
        queue.pop();
        if (!settled.insert(s).second) continue;
        out.label[s] = label;
        const engine::ReferenceEvent e = engine::reference_step(scene, s.first, s.second);
        for (const engine::Outgoing& o : e.outgoing) {
            const State next{e.point, o.direction};
            if (e.outgoing.size() >= 2 || junction(scene, e.point, s.second))
                out.branch.insert(next);
            if (!settled.count(next))
                queue.push({{label.first + o.reflection, label.second}, next});
        }
    }
    return out;
}

// The JSON Lines certificate as the text lines it should match.
std::vector<std::vector<std::string>> jsonl_as_words(const std::string& text, int dim) {
    std::vector<std::vector<std::string>> lines;
    std::istringstream in(text);
    auto vec = [&](std::vector<std::string>& line, const nlohmann::json& v) {
        REQUIRE(v.size() == static_cast<std::size_t>(dim));
        for (const auto& x : v) line.push_back(x.get<std::string>());
    };
    for (std::string l; std::getline(in, l);) {
        const nlohmann::json j = nlohmann::json::parse(l);
        std::vector<std::string> line;
        if (j.contains("orthoray-certificate")) {
            lines.push_back({"orthoray-certificate", "1"});
            line = {"dim", std::to_string(j["dim"].get<int>())};
        } else if (j.contains("illumination")) {
            line = {"illumination"};
        } else if (j.contains("branch")) {
            const nlohmann::json& b = j["branch"];
            line = {"branch"};
            vec(line, b["point"]);
            vec(line, b["direction"]);
            line.insert(line.end(), {"ray", b["ray"], "reflections", b["reflections"]});
        } else if (j.contains("lit")) {
            const nlohmann::json& t = j["lit"];
            line = {"lit", t["target"], "reflections", t["reflections"], "ray", t["ray"]};
        } else if (j.contains("step")) {
            line = {"step"};
            vec(line, j["step"]["point"]);
            vec(line, j["step"]["direction"]);
        } else if (j.contains("unlit") || j.contains("unknown")) {
            const char* word = j.contains("unlit") ? "unlit" : "unknown";
            line = {word, j[word]};
        } else if (j.contains("answer")) {
            for (const char* key : {"answer", "reason", "reflections"})
                lines.push_back({key, j[key]});
            line = {"states", j["states"]};
            if (j.value("partial", false)) {
                lines.push_back(line);
                line = {"partial"};
            }
        } else {
            REQUIRE(j == nlohmann::json::parse(R"({"end": true})"));
            line = {"end"};
        }
        lines.push_back(line);
    }
    return lines;
}

// Reads the certificate of `answer` for `scene` and checks it; `complete`:
// the search explored everything (no limit).
void check_certificate(const Scene& scene, const Answer& answer, const std::string& text,
                       const Exhaustive* all) {
    const auto lines = words_of(text);
    std::size_t at = 0;
    auto next = [&]() -> const std::vector<std::string>& {
        REQUIRE(at < lines.size());
        return lines[at++];
    };
    CHECK(next() == std::vector<std::string>{"orthoray-certificate", "1"});
    CHECK(next() == std::vector<std::string>{"dim", std::to_string(scene.dim)});
    CHECK(next() == std::vector<std::string>{"illumination"});
    const std::size_t words = 1 + 2 * static_cast<std::size_t>(scene.dim) + 4;
    std::map<State, Label> branches;
    while (at < lines.size() && lines[at].at(0) == "branch") {
        const auto& b = next();
        REQUIRE(b.size() == words);
        CHECK(b[words - 4] == "ray");
        CHECK(b[words - 2] == "reflections");
        const State s{vector_at(b, 1, scene.dim), vector_at(b, 1 + scene.dim, scene.dim)};
        const Label label{std::stoull(b[words - 1]), std::stoull(b[words - 3])};
        CHECK(branches.emplace(s, label).second); // no state twice
    }
    if (all) { // exactly the reachable branch states, with their least labels
        CHECK(branches.size() == all->branch.size());
        for (const auto& [s, label] : branches) {
            CHECK(all->branch.count(s) == 1);
            CHECK(all->label.at(s) == label);
        }
    }
    for (std::size_t t = 0; t < scene.targets.size(); ++t) {
        const auto& line = next();
        const TargetAnswer& expected = answer.targets[t];
        REQUIRE(line.size() >= 2);
        CHECK(line[1] == std::to_string(t + 1));
        if (expected.status != TargetAnswer::Status::lit) {
            CHECK(line[0] ==
                  (expected.status == TargetAnswer::Status::unlit ? "unlit" : "unknown"));
            continue;
        }
        REQUIRE(line.size() == 6);
        CHECK(line[0] == "lit");
        CHECK(line[3] == expected.reflections.get_str());
        CHECK(line[5] == std::to_string(expected.ray));
        // The witness: the ray's start, then each first acting event with a
        // direction the rules allow; its direction changes number K.
        std::vector<State> steps;
        while (at < lines.size() && lines[at].at(0) == "step") {
            const auto& s = next();
            REQUIRE(s.size() == 1 + 2 * static_cast<std::size_t>(scene.dim));
            steps.emplace_back(vector_at(s, 1, scene.dim), vector_at(s, 1 + scene.dim, scene.dim));
        }
        REQUIRE(!steps.empty());
        const Ray& ray = scene.rays.at(expected.ray - 1);
        CHECK(steps.front() == State(ray.start, ray.direction));
        std::uint64_t turns = 0;
        for (std::size_t i = 1; i < steps.size(); ++i) {
            const engine::ReferenceEvent e =
                engine::reference_step(scene, steps[i - 1].first, steps[i - 1].second);
            REQUIRE_FALSE(e.escape);
            CHECK(e.point == steps[i].first);
            bool allowed = false;
            for (const engine::Outgoing& o : e.outgoing) allowed |= o.direction == steps[i].second;
            CHECK(allowed);
            turns += steps[i].second != steps[i - 1].second;
        }
        CHECK(expected.reflections == static_cast<unsigned long>(turns));
        const engine::ReferenceEvent last =
            engine::reference_step(scene, steps.back().first, steps.back().second);
        CHECK(engine::reference_passes(scene, scene.targets[t], steps.back().first,
                                       steps.back().second, last));
    }
    CHECK(next() == std::vector<std::string>{"answer", answer_word(answer)});
    CHECK(next() == std::vector<std::string>{"reason", to_string(answer.reason)});
    CHECK(next() == std::vector<std::string>{"reflections", answer.reflections.get_str()});
    CHECK(next() == std::vector<std::string>{"states", std::to_string(branches.size())});
    // The answer counts the states explored: after a full search every
    // reachable one, of which the certificate lists the branch states; at a
    // limit the branch states stored stand for them.
    if (answer.reason == Reason::limit)
        CHECK(answer.states == static_cast<unsigned long>(branches.size()));
    else if (all)
        CHECK(answer.states == static_cast<unsigned long>(all->label.size()));
    if (answer.reason == Reason::limit) CHECK(next() == std::vector<std::string>{"partial"});
    CHECK(next() == std::vector<std::string>{"end"});
    CHECK(at == lines.size());
}

// Solves with a certificate in both formats; the answers must not differ.
std::pair<Answer, std::string> certified(const Scene& scene, SolveOptions options,
                                         std::string* jsonl = nullptr) {
    std::ostringstream text, json;
    Answer answer;
    {
        CertificateWriter writer(text, scene);
        writer.attach(options);
        answer = solve(scene, options);
        writer.finish(answer);
    }
    if (jsonl) {
        CertificateWriter writer(json, scene, CertificateFormat::jsonl);
        writer.attach(options);
        writer.finish(solve(scene, options));
        *jsonl = json.str();
    }
    return {answer, text.str()};
}

} // namespace

TEST_CASE("illumination certificates list the branch states and replayable witnesses",
          "[illumination][certificate][property]") {
    std::mt19937_64 rng(1218);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 40;
    shape.max_rays = 3;
    shape.max_targets = 3;
    shape.scene.max_elements = 8;
    const int cases = test::case_count(400);
    int checked = 0, lit = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        const Scene s = test::random_optics_scene(rng, shape);
        REQUIRE_FALSE(s.has_diagonal()); // junction() above tries sign changes only
        if (s.single_trajectory()) continue;
        const Answer graph = explore_illumination_graph(s, 20000);
        if (!graph.decided()) continue;
        ++checked;
        INFO("case " << i << "\n" << write_scene(s));
        std::string jsonl;
        const auto [answer, text] = certified(s, {}, &jsonl);
        CHECK(answer.reason == graph.reason);
        for (std::size_t t = 0; t < s.targets.size(); ++t) {
            CHECK(answer.targets[t].status == graph.targets[t].status);
            CHECK(answer.targets[t].reflections == graph.targets[t].reflections);
            lit += answer.targets[t].status == TargetAnswer::Status::lit;
        }
        const Exhaustive all = exhaustive(s);
        check_certificate(s, answer, text, &all);
        CHECK(jsonl_as_words(jsonl, s.dim) == words_of(text));
    }
    CHECK(checked > cases / 2);
    CHECK(lit > 0);
}

// Dense scenes with many one-sided splitters, where branches often have an
// event at a junction that does not split their own arrival: the branch
// lines must still be exactly the reachable branch states (those leaving a
// junction included) with their least labels.
TEST_CASE("illumination certificates of dense one-sided scenes list least labels",
          "[illumination][certificate][property]") {
    std::mt19937_64 rng(2811);
    const int cases = test::case_count(400);
    int checked = 0;
    for (int i = 0; i < cases; ++i) {
        const Scene s = test::random_optics_scene(rng, test::dense_one_sided_shape(i));
        if (s.single_trajectory()) continue;
        INFO("case " << i << "\n" << write_scene(s));
        const auto [answer, text] = certified(s, {});
        const Exhaustive all = exhaustive(s);
        check_certificate(s, answer, text, &all);
        ++checked;
    }
    CHECK(checked > cases / 2);
}

// Ray 2 crosses the one-sided splitter y+ 3 from its passive side where the
// mirror x -1 crosses it: one way out for that arrival, but an arrival from
// above splits there, so (-1, 3) is a junction. Ray 2 reaches (-1, 3) along
// (-1, 1/2) with 15 reflections, a split elsewhere only with 16; a search
// whose stretches ran on through that point wrote 16 (found by a clang build,
// whose random scenes differed).
TEST_CASE("a branch state passed where the arrival does not split gets its least label",
          "[illumination][certificate]") {
    const Scene s = read_scene("dim 2\n"
                               "mirror x+ -7 y -7 7\n"
                               "splitter x 7 y -7 7\n"
                               "mirror y -7 x -7 7\n"
                               "mirror y 7 x -7 7\n"
                               "splitter y -4 x -4 5\n"
                               "splitter y+ 3 x -3 2\n"
                               "splitter x -3 y -6 -5\n"
                               "splitter x 2 y -4 1\n"
                               "splitter y+ 6 x -5 -2\n"
                               "mirror x- -4 y -2 -1\n"
                               "mirror x -1 y 1 6\n"
                               "mirror y 1 x 0 3\n"
                               "ray -3 0 0 1\n"
                               "ray 3 4 -1 1/2\n"
                               "ray 1 -2 3/2 0\n"
                               "target 10 -2\n",
                               "passed.scene");
    const Exhaustive all = exhaustive(s);
    const State passed{{Rational(-1), Rational(3), Rational(0)},
                       {Rational(-1), Rational(1, 2), Rational(0)}};
    REQUIRE(all.branch.count(passed) == 1);
    CHECK(all.label.at(passed) == Label{15, 2});
    const auto [answer, text] = certified(s, {});
    CHECK(text.find("branch -1 3 -1 1/2 ray 2 reflections 15\n") != std::string::npos);
    check_certificate(s, answer, text, &all);
}

TEST_CASE("a limit writes a partial illumination certificate", "[illumination][certificate]") {
    const Scene s = read_scene("dim 2\nsplitter x 2 y -1 1\ntarget 0 0\ntarget -3 0\n"
                               "ray 0 0 1 0\n");
    SolveOptions options;
    options.max_steps = 1;
    std::string jsonl;
    const auto [answer, text] = certified(s, options, &jsonl);
    CHECK(answer.reason == Reason::limit);
    CHECK(text == "orthoray-certificate 1\ndim 2\nillumination\n"
                  "branch 0 0 1 0 ray 1 reflections 0\n"
                  "branch 2 0 1 0 ray 1 reflections 0\n"
                  "branch 2 0 -1 0 ray 1 reflections 1\n"
                  "lit 1 reflections 0 ray 1\nstep 0 0 1 0\nunknown 2\n"
                  "answer unknown\nreason limit\nreflections 0\nstates 3\npartial\nend\n");
    check_certificate(s, answer, text, nullptr);
    CHECK(jsonl_as_words(jsonl, s.dim) == words_of(text));
    // Without any limit, both targets are lit.
    const auto [full, full_text] = certified(s, {});
    CHECK(full.reason == Reason::lit);
    check_certificate(s, full, full_text, nullptr);
}
