// Realistic scenes (docs/realistic-scenes.md): the reader's checks, the
// pair dynamic program against brute force on thousands of random models
// (greedy per-object choices included), and certificates, tampered ones
// rejected.
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include "orthoray/parse.hpp"
#include "orthoray/realistic.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

using namespace orthoray;
using namespace orthoray::test;

namespace {

// The most intensity any path from the source brings to the receiver, by
// trying every path whose (previous, current) pairs do not repeat: a repeated
// pair cannot help, since transfers are monotone and never raise intensity
// (the path without the loop delivers at least as much).
Integer brute_force(const RealisticModel& m) {
    std::map<std::pair<std::size_t, std::size_t>, std::vector<const Triple*>> out;
    for (const Triple& t : m.triples) out[{t.from, t.via}].push_back(&t);
    Integer best = -1;
    std::set<std::pair<std::size_t, std::size_t>> on_path;
    std::function<void(std::size_t, std::size_t, const Integer&)> walk =
        [&](std::size_t previous, std::size_t current, const Integer& in) {
            if (current == m.receiver) best = std::max(best, in);
            for (const Triple* t : out[{previous, current}]) {
                if (!on_path.insert({t->via, t->to}).second) continue;
                walk(t->via, t->to, t->transfer(in));
                on_path.erase({t->via, t->to});
            }
        };
    for (const std::size_t leg : m.first_legs) {
        on_path.insert({m.source, leg});
        walk(m.source, leg, m.emitted);
        on_path.erase({m.source, leg});
    }
    return best;
}

Transfer random_transfer(std::mt19937_64& rng) {
    Transfer t;
    if (chance(rng, 50)) {
        t.q = pick(rng, 1, 6);
        t.p = pick(rng, 0, static_cast<int>(t.q.get_si()));
        return t;
    }
    t.kind = Transfer::Kind::table;
    Integer threshold = pick(rng, 0, 20), value = 0;
    for (int k = pick(rng, 1, 4); k > 0; --k) {
        value = std::min<Integer>(threshold, value + pick(rng, 0, 30));
        t.thresholds.push_back(threshold);
        t.values.push_back(value);
        threshold += pick(rng, 1, 40);
    }
    return t;
}

RealisticModel random_model(std::mt19937_64& rng) {
    RealisticModel m;
    const int n = pick(rng, 2, 5);
    for (int k = 0; k < n; ++k) {
        // Appended, not concatenated: GCC 12 warns falsely (-Wrestrict) on "O" + string.
        std::string name = "O";
        name += std::to_string(k);
        m.objects.push_back(name);
    }
    m.source = 0;
    m.receiver = static_cast<std::size_t>(pick(rng, 1, n - 1));
    m.emitted = pick(rng, 0, 200);
    m.eps = pick(rng, 0, 100);
    for (int x = 1; x < n; ++x)
        if (chance(rng, 60)) m.first_legs.push_back(static_cast<std::size_t>(x));
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
            for (int c = 0; c < n; ++c)
                if (a != b && b != c && chance(rng, 25))
                    m.triples.push_back({static_cast<std::size_t>(a), static_cast<std::size_t>(b),
                                         static_cast<std::size_t>(c), random_transfer(rng)});
    return m;
}

RealisticVerdict check(const RealisticModel& m, const std::string& certificate) {
    std::istringstream in(certificate);
    return verify_realistic_certificate(m, in);
}

std::string certificate_of(const RealisticModel& m) {
    std::ostringstream out;
    write_realistic_certificate(out, m, solve_realistic(m));
    return out.str();
}

const char* const greedy_fails = R"(realistic 1
object S A B C R
source S 100
receiver R
eps 10
pair S A
pair S C
triple S A B scale 4/5
triple S C B scale 2/5
triple C B R scale 1/2
)";

} // namespace

TEST_CASE("transfers: floor of a share, and a step table", "[realistic]") {
    Transfer half;
    half.p = 1;
    half.q = 2;
    CHECK(half(Integer(7)) == 3);
    CHECK(half(Integer(0)) == 0);
    Transfer table;
    table.kind = Transfer::Kind::table;
    table.thresholds = {Integer(5), Integer(10)};
    table.values = {Integer(2), Integer(9)};
    CHECK(table(Integer(4)) == 0);
    CHECK(table(Integer(5)) == 2);
    CHECK(table(Integer(9)) == 2);
    CHECK(table(Integer(10)) == 9);
    CHECK(table(Integer(1000)) == 9);
}

TEST_CASE("the dynamic program keeps pairs apart where the best per object fails", "[realistic]") {
    const RealisticModel m = read_realistic(greedy_fails);
    const RealisticAnswer a = solve_realistic(m);
    // B is reached best from A (80), but A B R is no triple; keeping only
    // B's best would miss S C B R, which delivers 40 / 2 = 20 > 10.
    CHECK(a.yes);
    CHECK(a.best == 20);
    CHECK(a.path == std::vector<std::size_t>{0, 3, 2, 4});
    CHECK(a.intensities == std::vector<Integer>{100, 40, 20});
    CHECK(check(m, certificate_of(m)).valid);
}

TEST_CASE("the dynamic program agrees with every path tried, on random models",
          "[realistic][slow]") {
    std::mt19937_64 rng(1994);
    int yes = 0, none = 0;
    const int cases = case_count(4000);
    for (int round = 0; round < cases; ++round) {
        const RealisticModel m = random_model(rng);
        const RealisticAnswer a = solve_realistic(m);
        CAPTURE(round);
        REQUIRE(a.best == brute_force(m));
        CHECK(a.yes == (a.best > m.eps));
        yes += a.yes;
        none += a.best < 0;
        const std::string certificate = certificate_of(m);
        REQUIRE(check(m, certificate).valid);
    }
    // The sample holds both answers and models where nothing arrives (each
    // more than a tenth, in the full run and in the sanitizers' quarter).
    CHECK(yes > cases / 10);
    CHECK(none > cases / 10);
}

TEST_CASE("tampered realistic certificates are rejected for the reason changed", "[realistic]") {
    const RealisticModel m = read_realistic(greedy_fails);
    const std::string good = certificate_of(m);
    auto tampered = [&](const std::string& from, const std::string& to) {
        std::string text = good;
        const std::size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        return check(m, text.replace(at, from.size(), to)).message;
    };
    CHECK(tampered("answer yes", "answer no") ==
          "invalid: the answer does not follow from best and eps");
    CHECK(tampered("best 20", "best 21") == "invalid: the path delivers 20, not best");
    CHECK(tampered("arrivals 100 40 20", "arrivals 100 41 20") ==
          "invalid: arrival 2 is 41, the transfers give 40");
    CHECK(tampered("path S C B R\narrivals 100 40 20", "path S A B R\narrivals 100 80 40") ==
          "invalid: the path's step 3 is not a triple of the model");
    CHECK(tampered("bound C B 40", "bound C B 39") ==
          "invalid: the triple S C B passes on 40, more than the bound of its next pair");
    CHECK(tampered("bound S A 100\n", "") == "invalid: the first leg to A has no bound of 100");
    CHECK(tampered("bound B R 20", "bound B R 19") ==
          "invalid: the triple C B R passes on 20, more than the bound of its next pair");
    CHECK_THROWS_AS(check(m, good.substr(0, good.size() - 4)), InputError);
    // A statement said twice says two things; the file is malformed, not
    // judged by its last word.
    for (const std::string line :
         {"answer yes\n", "best 20\n", "path S C B R\n", "arrivals 100 40 20\n"}) {
        INFO(line);
        std::string text = good;
        const std::size_t at = text.find(line);
        REQUIRE(at != std::string::npos);
        text.insert(at, line);
        try {
            check(m, text);
            FAIL("accepted");
        } catch (const InputError& e) {
            const std::string keyword = line.substr(0, line.find(' '));
            CHECK(std::string(e.what()).find("expected one '" + keyword + "' line") !=
                  std::string::npos);
        }
    }
}

TEST_CASE("a bad operand of a realistic certificate is located at its own column", "[realistic]") {
    const RealisticModel m = read_realistic(greedy_fails);
    const std::string good = certificate_of(m);
    auto message = [&](const std::string& from, const std::string& to) {
        std::string text = good;
        const std::size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
        std::istringstream in(text);
        try {
            verify_realistic_certificate(m, in, "c.cert");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK(message("best 20", "best  x") == "c.cert:3:7: found 'x', expected a natural number");
    CHECK(message("path S C B R", "path S C\tQ R") ==
          "c.cert:4:10: found 'Q', expected an object of the model");
    CHECK(message("arrivals 100 40 20", "arrivals 100 4x 20") ==
          "c.cert:5:14: found '4x', expected a natural number");
    CHECK(message("bound C B 40", "bound C B -40") ==
          "c.cert:" +
              std::to_string(
                  1 + std::count(good.begin(), good.begin() + good.find("bound C B"), '\n')) +
              ":11: found '-40', expected a natural number");
}

TEST_CASE("realistic models: every malformed line is one located message", "[realistic]") {
    auto message = [](const std::string& text) {
        try {
            read_realistic(text, "m.realistic");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    const std::string head = "realistic 1\nobject S A R\nsource S 10\nreceiver R\neps 1\n";
    CHECK(message("realistic 2\n") == "m.realistic:1:11: found '2', expected the format version 1");
    CHECK(message(head + "triple S A R scale 3/2\n") ==
          "m.realistic:6:20: found '3/2', expected a share P/Q from 0 to 1");
    CHECK(message(head + "triple S A R table 0:0 5:6\n") ==
          "m.realistic:6:24: found '5:6', expected a value at most its threshold (intensity "
          "never grows)");
    CHECK(message(head + "triple S A R table 0:0 5:3 8:2\n") ==
          "m.realistic:6:28: found '8:2', expected values that do not decrease (a monotone "
          "transfer)");
    CHECK(message(head + "triple S A R table 5:1 5:2\n") ==
          "m.realistic:6:24: found '5:2', expected thresholds in increasing order");
    // A bad threshold or value is pointed at itself, not at its step.
    CHECK(message(head + "triple S A R table 0:0 x:2\n") ==
          "m.realistic:6:24: found 'x', expected a natural number");
    CHECK(message(head + "triple S A R table 0:0 10:x\n") ==
          "m.realistic:6:27: found 'x', expected a natural number");
    CHECK(message(head + "triple S Q R scale 1\n") ==
          "m.realistic:6:10: found 'Q', expected an object declared by 'object'");
    CHECK(message(head + "pair A R\n") == "m.realistic:6:6: found 'A', expected the source object");
    CHECK(message("realistic 1\nobject S R\nsource S 10\nreceiver R\n") ==
          "m.realistic:5:1: found the end of the file, expected an 'eps' statement");
    CHECK(message(head + "lamp S\n") == "m.realistic:6:1: found 'lamp', expected realistic, "
                                        "object, source, receiver, eps, pair or triple");
    CHECK(message(head + "eps 3\n") ==
          "m.realistic:6:1: found 'eps', expected one 'eps' statement");
}

TEST_CASE("orthoray realistic answers, writes a certificate verify accepts, and exits as solve",
          "[realistic][cli]") {
    const TempDir dir;
    const std::string model = source_path("instances/realistic/greedy-fails.realistic");
    const std::string cert = dir.path("r.cert");
    const CliResult run =
        run_cli("realistic --json " + quote(model) + " --certificate " + quote(cert));
    CHECK(run.status == 0);
    CHECK(
        run.out.substr(0, run.out.find(",\"seconds\"")) ==
        R"({"answer":"yes","best":20,"eps":10,"path":["S","C","B","R"],"arrivals":[100,40,20],"pairs":6)");
    const CliResult valid = run_cli("verify " + quote(model) + ' ' + quote(cert));
    CHECK(valid.status == 0);
    CHECK(valid.out == "valid: yes, best 20\n");
    // Raise eps past the best: the answer is no, exit 1.
    std::string text = slurp(model);
    text.replace(text.find("eps 10"), 6, "eps 20");
    const std::string strict = dir.write("strict.realistic", text);
    CHECK(run_cli("realistic " + quote(strict)).status == 1);
    // The first certificate claims yes, which eps 20 no longer allows.
    const CliResult stale = run_cli("verify " + quote(strict) + ' ' + quote(cert));
    CHECK(stale.status == 1);
    CHECK(stale.out == "invalid: the answer does not follow from best and eps\n");
    const CliResult bad = run_cli(
        "realistic " + quote(dir.write("bad.realistic", "realistic 1\nobject S\nsource T 1\n")));
    CHECK(bad.status == 2);
    CHECK(bad.err.find("bad.realistic:3:8: found 'T', expected an object declared by 'object'") !=
          std::string::npos);
}
