// Certificates of the intensity question (docs/certificates.md, "The
// intensity question"): the exact file of a small scene, certificates of
// random scenes with random reflectances verified in both formats and with
// both steppers, each of them tampered with in ways the checker must
// notice, and the byte budget counting the digits of huge intensities.
#include "engine/intensity_search.hpp"
#include "engine/reference_step.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "support/case_count.hpp"
#include "support/certificate_lines.hpp"
#include "support/portable_random.hpp"
#include "support/random_optics.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <queue>
#include <sstream>
#include <string>
#include <vector>

using namespace orthoray;

namespace {

using orthoray::test::join;
using orthoray::test::split_lines;

using Status = TargetAnswer::Status;

struct Certified {
    Answer answer;
    std::string text;
};

Certified certify(const Scene& scene, const Integer& eps, CertificateFormat format,
                  const engine::EventStepper* stepper = nullptr) {
    std::ostringstream out;
    CertificateWriter writer(out, scene, format);
    SolveOptions options;
    options.min_intensity = eps;
    writer.attach(options);
    Certified c;
    c.answer = stepper ? engine::solve_intensity(scene, options, *stepper)
                       : engine::solve_intensity(scene, options);
    writer.finish(c.answer);
    c.text = out.str();
    return c;
}

Verdict check(const Scene& scene, const std::string& text) {
    std::istringstream in(text);
    return verify_certificate(scene, in);
}

// The last word of a line, and the line with it replaced.
std::string last_word(const std::string& line) {
    return line.substr(line.rfind(' ') + 1);
}
std::string with_last_word(const std::string& line, const std::string& word) {
    return line.substr(0, line.rfind(' ') + 1) + word;
}

using State = std::pair<Vector, Vector>;

// The greatest intensity with which any branch reaches each state: Dijkstra
// over every state, the most intense first, each event's factor applied
// and floored as docs/intensity.md says (states reached with 0 end there).
std::map<State, Integer> greatest_intensities(const Scene& scene) {
    std::priority_queue<std::pair<Integer, State>> queue;
    for (const Ray& r : scene.rays) queue.push({*r.intensity, {r.start, r.direction}});
    std::map<State, Integer> greatest;
    while (!queue.empty()) {
        const auto [intensity, s] = queue.top();
        queue.pop();
        if (!greatest.emplace(s, intensity).second || intensity == 0) continue;
        const engine::ReferenceEvent e = engine::reference_step(scene, s.first, s.second);
        for (const engine::Outgoing& o : e.outgoing) {
            const Rational f = engine::outgoing_factor(e.acting, s.second, o.direction);
            Integer next = intensity * f.get_num();
            mpz_fdiv_q(next.get_mpz_t(), next.get_mpz_t(), f.get_den().get_mpz_t());
            if (!greatest.count({e.point, o.direction})) queue.push({next, {e.point, o.direction}});
        }
    }
    return greatest;
}

// A branch line's state and intensity: "branch <point> <direction> intensity I".
std::pair<State, Integer> branch_line(const std::string& line, int dim) {
    std::istringstream in(line);
    std::string word;
    in >> word;
    State s;
    for (Vector* v : {&s.first, &s.second})
        for (int j = 0; j < dim; ++j) {
            in >> word;
            const NumberToken token = read_number(word);
            REQUIRE(token.status == NumberToken::Status::ok);
            (*v)[j] = token.value;
        }
    in >> word >> word;
    return {s, Integer(word)};
}

} // namespace

TEST_CASE("an intensity certificate lists expanded states, lit witnesses and the threshold",
          "[intensity][certificate]") {
    const Scene scene = read_scene("dim 2\n"
                                   "mirror x 4 y -1 1 reflectance 2/3\n"
                                   "mirror x -4 y -1 1 reflectance 2/3\n"
                                   "splitter x 2 y -1 1 reflectance 1/2 transmittance 1/3\n"
                                   "ray 0 0 1 0 intensity 1000\n"
                                   "target 3 0\n"
                                   "target -2 0\n"
                                   "target 0 5\n",
                                   "corridor.scene");
    const Certified c = certify(scene, 10, CertificateFormat::text);
    // Through the splitter 1000 -> 333, back from x = 4: floor(333 * 2/3) =
    // 222; reflected at the splitter straight back: 500, the brighter.
    CHECK(c.text == "orthoray-certificate 1\n"
                    "dim 2\n"
                    "illumination\n"
                    "min-intensity 10\n"
                    "branch 0 0 1 0 intensity 1000\n"
                    "branch 2 0 1 0 intensity 333\n"
                    "branch 2 0 -1 0 intensity 500\n"
                    "lit 1 reflections 0 ray 1 intensity 333\n"
                    "step 0 0 1 0\n"
                    "step 2 0 1 0\n"
                    "lit 2 reflections 1 ray 1 intensity 500\n"
                    "step 0 0 1 0\n"
                    "step 2 0 -1 0\n"
                    "unlit 3\n"
                    "answer no\n"
                    "reason unlit\n"
                    "reflections 1\n"
                    "states 3\n"
                    "end\n");
    const Verdict v = check(scene, c.text);
    CHECK(v.valid);
    CHECK(v.message == "valid: unlit above intensity 10, 1 reflections, 3 states");
    // Target 1 claimed with 222, by a true witness (back from x = 4): a lit
    // target's intensity is the greatest that reaches it, here 333.
    const std::string dimmer = test::replaced(
        c.text, "lit 1 reflections 0 ray 1 intensity 333\nstep 0 0 1 0\nstep 2 0 1 0\n",
        "lit 1 reflections 1 ray 1 intensity 222\nstep 0 0 1 0\nstep 2 0 1 0\nstep 4 0 -1 0\n");
    const Verdict forged = check(scene, dimmer);
    CHECK_FALSE(forged.valid);
    CHECK(forged.message.find("invalid: target 1 (line 8) is claimed lit with intensity 222, "
                              "but the stretch of the branch on line 6 passes it with 333") == 0);
    // The same claims with the splitter's factors swapped are false, and
    // the checker's own rule says so.
    Scene swapped = scene;
    std::swap(swapped.elements[2].reflectance, swapped.elements[2].transmittance);
    CHECK_FALSE(check(swapped, c.text).valid);
}

TEST_CASE("intensity certificates of random scenes verify, and tampered ones fail",
          "[intensity][certificate][property]") {
    std::mt19937_64 rng(2016);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 50;
    shape.one_sided_percent = 20;
    shape.max_rays = 3;
    shape.max_targets = 4;
    shape.scene.max_elements = 8;
    const int cases = test::case_count(800);
    int verified = 0, lit_tampered = 0, start_tampered = 0, threshold_tampered = 0,
        unlit_tampered = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        Scene s = test::random_optics_scene(rng, shape);
        test::add_random_attenuation(rng, s, 400);
        const Integer eps = test::pick(rng, 0, 40);
        INFO("case " << i << " eps " << eps << "\n" << write_scene(s));
        const engine::ReferenceStepper scan(s);
        const Certified c =
            certify(s, eps, i % 4 == 1 ? CertificateFormat::jsonl : CertificateFormat::text,
                    i % 4 == 2 ? &scan : nullptr);
        INFO(c.text);
        const Verdict v = check(s, c.text);
        INFO(v.message);
        REQUIRE(v.valid);
        ++verified;
        if (i % 4 == 1) continue; // the tampering below edits the text form
        const std::vector<std::string> lines = split_lines(c.text);
        // m: the least lit intensity, or the threshold when a target is unlit.
        Integer m = -1;
        for (const TargetAnswer& t : c.answer.targets) {
            const Integer bound = t.status == Status::lit ? *t.intensity : eps;
            if (m < 0 || bound < m) m = bound;
        }
        for (std::size_t k = 0; k < lines.size(); ++k) {
            if (!lines[k].starts_with("lit ")) continue;
            // A lit target's intensity one more or one less than its witness.
            for (int delta : {-1, 1}) {
                std::vector<std::string> t = lines;
                t[k] = with_last_word(t[k], Integer(Integer(last_word(t[k])) + delta).get_str());
                CHECK_FALSE(check(s, join(t)).valid);
                ++lit_tampered;
            }
            // A threshold at that intensity: the witness is not above it.
            std::vector<std::string> t = lines;
            t[3] = "min-intensity " + last_word(lines[k]);
            CHECK_FALSE(check(s, join(t)).valid);
            ++threshold_tampered;
            // The target claimed unlit (its witness removed), the verdict
            // left alone or made to agree: a stretch passes it.
            t = lines;
            t[k] = "unlit " + lines[k].substr(4, lines[k].find(' ', 4) - 4);
            std::size_t end = k + 1;
            while (end < t.size() && t[end].starts_with("step ")) ++end;
            t.erase(t.begin() + static_cast<std::ptrdiff_t>(k + 1),
                    t.begin() + static_cast<std::ptrdiff_t>(end));
            CHECK_FALSE(check(s, join(t)).valid);
            ++unlit_tampered;
            break;
        }
        // A ray's start line lowered to m while the ray is brighter than m:
        // the closure misses it.
        for (std::size_t k = 0; k < lines.size(); ++k) {
            if (!lines[k].starts_with("branch ")) continue;
            const Integer listed(last_word(lines[k]));
            bool start = false;
            for (const Ray& r : s.rays) {
                std::string head = "branch";
                for (int j = 0; j < s.dim; ++j) head += ' ' + to_string(r.start[j]);
                for (int j = 0; j < s.dim; ++j) head += ' ' + to_string(r.direction[j]);
                start = start || (lines[k].starts_with(head + " intensity ") &&
                                  *r.intensity == listed && listed > m);
            }
            if (!start) continue;
            std::vector<std::string> t = lines;
            t[k] = with_last_word(t[k], m.get_str());
            CHECK_FALSE(check(s, join(t)).valid);
            ++start_tampered;
            break;
        }
    }
    CHECK(verified == cases);
    CHECK(lit_tampered > cases / 4);
    CHECK(threshold_tampered > cases / 8);
    CHECK(unlit_tampered > cases / 8);
    CHECK(start_tampered > cases / 8);
}

// The certificate lists every expanded branch state with the greatest
// intensity of any branch reaching it (docs/intensity.md), also where a
// branch has an event at a junction that does not split its own arrival
// (one-sided splitters make such points common here).
TEST_CASE("each listed branch state has the greatest intensity reaching it",
          "[intensity][certificate][property]") {
    std::mt19937_64 rng(2611);
    const int cases = test::case_count(400);
    std::size_t compared = 0;
    for (int i = 0; i < cases; ++i) {
        Scene s = test::random_optics_scene(rng, test::dense_one_sided_shape(i));
        test::add_random_attenuation(rng, s, 400);
        const Integer eps = test::pick(rng, 0, 20);
        INFO("case " << i << " eps " << eps << "\n" << write_scene(s));
        const Certified c = certify(s, eps, CertificateFormat::text);
        INFO(c.text);
        const std::map<State, Integer> greatest = greatest_intensities(s);
        for (const std::string& line : split_lines(c.text)) {
            if (!line.starts_with("branch ")) continue;
            const auto [state, listed] = branch_line(line, s.dim);
            REQUIRE(greatest.count(state) == 1);
            CHECK(listed == greatest.at(state));
            ++compared;
        }
    }
    CHECK(compared > static_cast<std::size_t>(cases));
}

TEST_CASE("a single ray with an intensity gets an intensity certificate, partial at a limit",
          "[intensity][certificate]") {
    const Scene scene = read_scene("dim 2\n"
                                   "mirror x 4 y -1 1 reflectance 1/2\n"
                                   "mirror y 3 x -1 1\n"
                                   "ray 0 0 1 0 intensity 64\n"
                                   "target 0 0\n",
                                   "one.scene");
    REQUIRE(scene.single_trajectory());
    const Certified c = certify(scene, 0, CertificateFormat::text);
    CHECK(c.answer.targets[0].status == Status::lit);
    CHECK(*c.answer.targets[0].intensity == 64);
    CHECK(check(scene, c.text).valid);
    // Cut short before any event: the target at the ray's start is lit all
    // the same (0 reflections, the ray's own intensity), and the
    // certificate says so completely.
    auto capped_certificate = [](const Scene& s, Answer& answer) {
        std::ostringstream out;
        CertificateWriter writer(out, s);
        SolveOptions options;
        options.min_intensity = Integer(0);
        options.max_steps = 0;
        writer.attach(options);
        answer = engine::solve_intensity(s, options);
        writer.finish(answer);
        return out.str();
    };
    Answer at_start;
    const std::string whole = capped_certificate(scene, at_start);
    CHECK(at_start.reason == Reason::lit);
    CHECK(at_start.targets[0].reflections == 0);
    CHECK(*at_start.targets[0].intensity == 64);
    CHECK(check(scene, whole).valid);
    // A target a step away: nothing is proven.
    Scene away = scene;
    away.targets[0] = Vector{Rational(2), Rational(0), Rational(0)};
    Answer capped;
    const Verdict partial = check(away, capped_certificate(away, capped));
    CHECK(capped.reason == Reason::limit);
    CHECK(capped.targets[0].status == Status::unknown);
    CHECK_FALSE(partial.valid);
    CHECK(partial.message.find("partial") != std::string::npos);
}

TEST_CASE("the byte budget counts the digits of huge intensities", "[intensity][limits]") {
    // Two splitters: a handful of branch states, each carrying an intensity
    // of 100,000 decimal digits (about 41 KB) twice (its record and its
    // queue entry). Under a 64 KB budget the first state does not fit; with
    // a three-digit intensity the same search ends with an answer.
    std::string text = "dim 2\n"
                       "splitter x 2 y -1 1\n"
                       "splitter y 2 x 1 3\n"
                       "ray 0 0 1 0 intensity ";
    // Built in place: GCC 12's -Wrestrict misreads "1" + std::string(...)
    // under the sanitizers' inlining and stops the build.
    std::string huge(100'001, '0');
    huge.front() = '1';
    const Scene big = read_scene(text + huge + "\ntarget 5 0\n", "big.scene");
    const Scene small = read_scene(text + "100\ntarget 5 0\n", "small.scene");
    SolveOptions options;
    options.min_intensity = Integer(0);
    options.max_state_bytes = 64 << 10;
    const Answer starved = engine::solve_intensity(big, options);
    CHECK(starved.reason == Reason::limit);
    CHECK(starved.limit == Limit::memory);
    const Answer fits = engine::solve_intensity(small, options);
    CHECK(fits.reason == Reason::lit);
    options.max_state_bytes.reset();
    CHECK(engine::solve_intensity(big, options).reason == Reason::lit);
}
