#include "measurement.hpp"

#include "bench_util.hpp"
#include "child_process.hpp"
#include "float_grid_tracer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>

namespace orthoray::bench {
namespace {

// Reflections an answer says were computed: a cycle of period L is seen at
// reflection L + 1.
std::uint64_t performed(Reason reason, std::uint64_t reflections) {
    return reason == Reason::cycle ? reflections + 1 : reflections;
}

void copy(char (&out)[16], const std::string& s) {
    std::snprintf(out, sizeof out, "%s", s.c_str());
}

} // namespace

Measured in_child(const std::function<ChildResult()>& work) {
    const ChildOutput out = run_in_child([&] {
        ChildResult r;
        try {
            r = work();
            r.ok = true;
        } catch (const std::exception& e) {
            r.ok = false;
            std::snprintf(r.error, sizeof r.error, "%s", e.what());
        }
        return std::string(reinterpret_cast<const char*>(&r), sizeof r);
    });
    Measured m;
    m.max_rss_kb = out.max_rss_kb;
    if (out.bytes.size() == sizeof m.result)
        std::memcpy(&m.result, out.bytes.data(), sizeof m.result);
    else
        std::snprintf(m.result.error, sizeof m.result.error, "child died (status %d)", out.status);
    return m;
}

std::uint64_t to_u64(const Integer& x) {
    return x.get_ui();
}

ChildResult run_exact(const Scene& scene, std::uint64_t steps, Engine engine) {
    SolveOptions options;
    options.engine = engine;
    // 2D tables from the start; the cross-section grid in 3D (which refuses
    // the tables by name).
    options.shooter = scene.dim == 2 ? Shooter::pieces : Shooter::section;
    options.max_steps = steps;
    const auto begin = std::chrono::steady_clock::now();
    const Answer a = solve(scene, options);
    ChildResult r;
    r.wall = seconds_since(begin);
    r.reason = a.reason;
    r.reflections = to_u64(a.reflections);
    r.performed = performed(a.reason, r.reflections);
    r.setup = a.stats.setup.seconds;
    r.pieces = a.stats.setup.pieces;
    r.cells = a.stats.setup.cells;
    copy(r.shooter, to_string(a.shooter));
    copy(r.arithmetic, to_string(a.arithmetic));
    return r;
}

ChildResult run_float(const Scene& scene, std::uint64_t steps) {
    const auto begin = std::chrono::steady_clock::now();
    const FloatGridTracer tracer(scene);
    const FloatAnswer a = tracer.trace(steps);
    ChildResult r;
    r.wall = seconds_since(begin);
    r.reason = a.reason;
    r.reflections = a.reflections;
    r.performed = performed(a.reason, a.reflections);
    r.setup = tracer.setup_seconds();
    r.cells = tracer.cells();
    copy(r.shooter, "grid");
    copy(r.arithmetic, "double");
    return r;
}

std::string verdict_text(const Verdict& v) {
    const char* answer = v.reason == Reason::hit     ? "yes"
                         : v.reason == Reason::limit ? "unknown"
                                                     : "no";
    std::string text = std::string(answer) + ", " + to_string(v.reason) + ", ";
    if (v.reason == Reason::cycle) return text + "period " + std::to_string(v.reflections);
    return text + std::to_string(v.reflections) +
           (v.reflections == 1 ? " reflection" : " reflections");
}

Verdict exact_verdict(const Scene& scene, std::uint64_t cap, Engine engine) {
    SolveOptions options;
    options.engine = engine;
    options.max_steps = cap;
    const Answer a = solve(scene, options);
    return {a.reason, to_u64(a.reflections)};
}

Verdict float_verdict(const Scene& scene, std::uint64_t cap, double epsilon) {
    FloatOptions options;
    options.epsilon = epsilon;
    options.max_steps = cap;
    const FloatAnswer a = float_trace(scene, options);
    return {a.reason, a.reflections};
}

std::string fixed(double x, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
    return buffer;
}

// 3 significant digits, without exponents: 123, 12.3, 1.23, 0.0123.
std::string sig3(double x) {
    if (x == 0) return "0";
    const double a = std::fabs(x);
    int digits = a >= 100  ? 0
                 : a >= 10 ? 1
                 : a >= 1  ? 2
                           : 2 - static_cast<int>(std::floor(std::log10(a)));
    return fixed(x, std::min(digits, 9));
}

std::string rate_text(double per_second) {
    if (per_second >= 1e6) return sig3(per_second / 1e6) + " M";
    if (per_second >= 1e3) return sig3(per_second / 1e3) + " k";
    return sig3(per_second);
}

std::string mb(long kb) {
    return fixed(static_cast<double>(kb) / 1024.0, 1);
}

std::string power_of_ten(std::uint64_t n) {
    int e = 0;
    std::uint64_t x = n;
    while (x >= 10 && x % 10 == 0) x /= 10, ++e;
    if (x == 1 && e >= 3) return "10^" + std::to_string(e);
    if (e >= 6) return std::to_string(x) + "*10^" + std::to_string(e);
    return std::to_string(n);
}

std::string sibling(const std::string& csv, const std::string& suffix) {
    if (csv.empty()) return "";
    const std::size_t dot = csv.rfind(".csv");
    const std::string stem =
        dot != std::string::npos && dot + 4 == csv.size() ? csv.substr(0, dot) : csv;
    return stem + "-" + suffix + ".csv";
}

std::string sci(double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", x);
    return buffer;
}

} // namespace orthoray::bench
