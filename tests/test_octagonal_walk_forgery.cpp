// Forged walk certificates (docs/induction-certificates.md, "The walk"):
// every search below is a genuine induction, its steps exactly what the
// engine would write for it, but the walk they make breaks one rule the
// verifier enforces, and would prove a false answer if that rule were not
// checked. The honest certificate of the same scene verifies.
#include "support/certificate_outcome.hpp"

#include "induction/rho_walk.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

using namespace orthoray;

namespace {

// The scene of the fuzz seed: a ray sliding along the '/' into the floor.
// Its walk: from x (0) the first special state is the cut state 25, after
// 6 steps; by hand to its join 41; back at 41 after 6 more: tail 7, period
// 6, 13 reflections.
const char* const scene_text = "dim 2\n"
                               "mirror / 3 0 4 1\n"
                               "mirror x 0 y 0 7\n"
                               "mirror x 11 y 0 7\n"
                               "mirror y 0 x 0 11\n"
                               "mirror y 7 x 0 11\n"
                               "ray 5 2 1 1\n"
                               "target 22 0\n";

// Writes an induction's steps as certificates do.
class StepPrinter : public InductionObserver {
public:
    explicit StepPrinter(std::string& out) : out_(out) {}
    void top(std::size_t d, std::size_t r) override { line("top", d, std::to_string(r)); }
    void bottom(std::size_t r, std::size_t d) override { line("bottom", r, std::to_string(d)); }
    void equal(std::size_t r, std::size_t d) override { line("equal", r, std::to_string(d)); }
    void invariant(std::size_t d) override { out_ += "step invariant " + std::to_string(d) + "\n"; }
    void top_cycle(std::size_t d, const Integer& n) override { line("top-cycle", d, n.get_str()); }
    void bottom_cycle(std::size_t r, const Integer& n) override {
        line("bottom-cycle", r, n.get_str());
    }

private:
    void line(const char* kind, std::size_t a, const std::string& b) {
        out_ += std::string("step ") + kind + " " + std::to_string(a) + " " + b + "\n";
    }
    std::string& out_;
};

struct Listing {
    std::string head; // everything before the first walk-search
    induction::ExchangeOn<Integer> exchange;
};

Listing listing_of(const std::string& certificate) {
    Listing l;
    std::istringstream in(certificate);
    Integer n = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("walk-search", 0) == 0) break;
        l.head += line + "\n";
        if (line.rfind("piece ", 0) != 0) continue;
        std::istringstream words(line.substr(6));
        std::string start, length, kind, image;
        words >> start >> length >> kind >> image;
        induction::RawPieceOn<Integer> p;
        p.start = Integer(start);
        p.length = Integer(length);
        p.image = Integer(image);
        p.kind = kind == "reflect"  ? PieceKind::reflect
                 : kind == "escape" ? PieceKind::escape
                                    : PieceKind::absorbed; // absorbed, or cut: a dead end in E
        p.hit = line.find(" hit") != std::string::npos;
        n += p.length;
        l.exchange.pieces.push_back(p);
    }
    l.exchange.size = n;
    return l;
}

// `walk-search FROM only MARK` and its genuine steps.
std::string only_search(const Listing& l, const Integer& from, const Integer& mark) {
    std::string text = "walk-search " + from.get_str() + " only " + mark.get_str() + "\n";
    StepPrinter printer(text);
    induce(induction::to_public(induction::reroot(l.exchange, from, {mark}, false)), &printer);
    return text;
}

// The state `back` steps of E before x (E is a bijection of a few hundred
// states here: walked one state at a time).
Integer before_x(const Listing& l, int back) {
    Integer at = 0;
    for (int k = 0; k < back; ++k)
        for (const auto& p : l.exchange.pieces)
            if (p.image <= at && at < p.image + p.length) {
                at = p.start + (at - p.image);
                break;
            }
    return at;
}

test::Outcome check(const Scene& scene, const std::string& text) {
    return test::verify(scene, text);
}

} // namespace

TEST_CASE("forged walk certificates are refused", "[octagonal][induction-certificate]") {
    const Scene scene = read_scene(scene_text);
    std::stringstream out;
    CertificateWriter writer(out, scene, CertificateFormat::text);
    SolveOptions o;
    o.engine = Engine::induction;
    writer.attach(o);
    const Answer answer = solve(scene, o);
    writer.finish(answer);
    const std::string honest = out.str();
    REQUIRE(answer.reflections == 13);
    REQUIRE(answer.tail == 7);
    REQUIRE(honest.find("walk-search 0 only 25") != std::string::npos);
    CHECK(check(scene, honest).valid);

    const Listing l = listing_of(honest);
    const std::string all_from_x =
        honest.substr(honest.find("walk-search 0 all"),
                      honest.find("walk-search 0 only") - honest.find("walk-search 0 all"));
    const std::string false_cycle = "answer no\nreason cycle\nreflections 6\nperiod 6\nend\n";

    SECTION("the named state must be where the search with every mark stopped") {
        // After 6 steps the walk meets 25; an `only` search naming x itself
        // stops at once (offset 0). Taken at its word, the walk would be back
        // at x after 6 steps: a cycle of 6 with no tail.
        const std::string forged = l.head + all_from_x + only_search(l, 0, 0) + false_cycle;
        const test::Outcome v = check(scene, forged);
        CHECK_FALSE(v.valid);
        CHECK(v.message.find("does not meet it 6 steps on") != std::string::npos);
    }
    SECTION("a search must start where the walk stands") {
        // The state 6 steps of E before x, with only x marked, meets x after
        // exactly 6 steps, as the search with every mark from x met 25: from
        // the wrong start, it would put the walk back at x after 6 steps.
        const Integer p = before_x(l, 6);
        const std::string forged = l.head + all_from_x + only_search(l, p, 0) + false_cycle;
        const test::Outcome v = check(scene, forged);
        CHECK_FALSE(v.valid);
        CHECK(v.message.find("the walk is at state 0") != std::string::npos);
    }
}
