// One measured run of an engine in a forked child (child_process.hpp), the
// verdicts the parts compare, and the number formats of the reports.
// Bench-local.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"
#include "orthoray/solve.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace orthoray::bench {

// What a child sends back: plain bytes, so it crosses the pipe as is.
struct ChildResult {
    bool ok = false;
    char error[160] = {};
    Reason reason = Reason::limit;
    std::uint64_t reflections = 0; // as in Answer
    std::uint64_t performed = 0;   // reflections actually computed
    double wall = 0;               // seconds of the solve / trace call
    double setup = 0;              // the part of it spent building grids and tables
    std::uint64_t pieces = 0, cells = 0;
    char shooter[16] = {}, arithmetic[16] = {};
};

struct Measured {
    ChildResult result;
    long max_rss_kb = 0;
};

// Runs `work` in a child; exceptions become ok = false with their message.
Measured in_child(const std::function<ChildResult()>& work);

std::uint64_t to_u64(const Integer& x);

// The exact engine (Shooter::pieces) or the float tracer, for `steps` reflections.
ChildResult run_exact(const Scene& scene, std::uint64_t steps, Engine engine);
ChildResult run_float(const Scene& scene, std::uint64_t steps);

struct Verdict {
    Reason reason = Reason::limit;
    std::uint64_t reflections = 0;
    bool operator==(const Verdict&) const = default;
};

std::string verdict_text(const Verdict& v);
Verdict exact_verdict(const Scene& scene, std::uint64_t cap, Engine engine = Engine::lattice);
Verdict float_verdict(const Scene& scene, std::uint64_t cap, double epsilon);

std::string fixed(double x, int digits);
// 3 significant digits, without exponents: 123, 12.3, 1.23, 0.0123.
std::string sig3(double x);
std::string rate_text(double per_second);
std::string mb(long kb);
// 1000000 as 10^6, 3000000 as 3*10^6.
std::string power_of_ten(std::uint64_t n);
// FILE.csv -> FILE-suffix.csv ("" stays "").
std::string sibling(const std::string& csv, const std::string& suffix);
std::string sci(double x);

} // namespace orthoray::bench
