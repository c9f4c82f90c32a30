// The illumination statements, in the order the format fixes: branch lines,
// then one line a target (a lit line followed by its witness steps), then
// the verdict. See illumination_parse.hpp.
#include "certify/illumination_parse.hpp"

#include <string>
#include <string_view>

namespace orthoray::certify {
namespace {

// Token `index` must be the word `word` (the labels inside branch and lit).
void expect_word(const CertificateReader& in, std::size_t index, std::string_view word) {
    if (index >= in.size() || in.token(index) != word)
        in.fail(index, std::string("'").append(word).append("'"));
}

void expect_size(const CertificateReader& in, std::size_t size, const std::string& operand) {
    if (in.size() < size) in.fail(in.size(), operand);
    if (in.size() > size) in.fail(size, in.end_of_statement());
}

// branch X V ray R reflections K, or in an intensity certificate
// branch X V intensity I
BranchLine parse_branch(const CertificateReader& in, int dim, bool intensity) {
    const std::size_t d = static_cast<std::size_t>(dim);
    BranchLine b;
    b.line = in.line();
    if (in.size() < 2 * d + 1) in.fail(in.size(), "a number");
    b.point = in.vector(1, dim);
    b.direction = in.vector(1 + d, dim);
    if (intensity) {
        expect_word(in, 2 * d + 1, "intensity");
        expect_size(in, 2 * d + 3, "a non-negative integer");
        b.intensity = in.count(2 * d + 2);
        return b;
    }
    expect_word(in, 2 * d + 1, "ray");
    if (in.size() < 2 * d + 3) in.fail(in.size(), "a ray number");
    b.label.ray = in.count(2 * d + 2);
    expect_word(in, 2 * d + 3, "reflections");
    expect_size(in, 2 * d + 5, "a non-negative integer");
    b.label.reflections = in.count(2 * d + 4);
    return b;
}

// lit T reflections K ray R [intensity I] | unlit T | unknown T
TargetLine parse_target(const CertificateReader& in, bool intensity) {
    TargetLine t;
    t.line = in.line();
    const std::string_view word = in.keyword();
    t.claim = word == "lit"     ? TargetLine::Claim::lit
              : word == "unlit" ? TargetLine::Claim::unlit
                                : TargetLine::Claim::unknown;
    if (in.size() < 2) in.fail(1, "a target number");
    t.target = in.count(1);
    if (t.claim != TargetLine::Claim::lit) {
        expect_size(in, 2, "a target number");
        return t;
    }
    expect_word(in, 2, "reflections");
    if (in.size() < 4) in.fail(in.size(), "a non-negative integer");
    t.label.reflections = in.count(3);
    expect_word(in, 4, "ray");
    if (!intensity) {
        expect_size(in, 6, "a ray number");
        t.label.ray = in.count(5);
        return t;
    }
    if (in.size() < 6) in.fail(in.size(), "a ray number");
    t.label.ray = in.count(5);
    expect_word(in, 6, "intensity");
    expect_size(in, 8, "a non-negative integer");
    t.intensity = in.count(7);
    return t;
}

bool is_target_line(std::string_view word) {
    return word == "lit" || word == "unlit" || word == "unknown";
}

void parse_verdict(CertificateReader& in, IlluminationClaims& c) {
    in.expect("answer", 1, "yes, no or unknown");
    c.answer = std::string(in.token(1));
    if (c.answer != "yes" && c.answer != "no" && c.answer != "unknown")
        in.fail(1, "yes, no or unknown");
    in.advance();
    in.expect("reason", 1, "lit, unlit or limit");
    const std::string_view reason = in.token(1);
    if (reason == "lit")
        c.reason = Reason::lit;
    else if (reason == "unlit")
        c.reason = Reason::unlit;
    else if (reason == "limit")
        c.reason = Reason::limit;
    else
        in.fail(1, "lit, unlit or limit");
    in.advance();
    in.expect("reflections", 1, "a non-negative integer");
    c.reflections = in.count(1);
    in.advance();
    in.expect("states", 1, "a non-negative integer");
    c.states = in.count(1);
    if (c.reason == Reason::limit) {
        in.advance();
        in.expect("partial", 0, in.end_of_statement());
        c.partial = true;
    }
    in.advance();
    in.expect("end", 0, in.end_of_statement());
    if (in.next()) in.fail(0, "end of file (nothing may follow 'end')");
}

} // namespace

IlluminationClaims parse_illumination(CertificateReader& in, int dim, WitnessCheck& witnesses) {
    IlluminationClaims c;
    in.expect("illumination", 0, in.end_of_statement());
    in.advance();
    if (in.keyword() == "min-intensity") {
        in.expect("min-intensity", 1, "a non-negative integer");
        c.min_intensity = in.count(1);
        in.advance();
    }
    const bool intensity = c.min_intensity.has_value();
    while (in.keyword() == "branch") {
        c.branches.push_back(parse_branch(in, dim, intensity));
        in.advance();
    }
    const char* next = "'branch', 'lit', 'unlit', 'unknown' or 'answer'";
    while (is_target_line(in.keyword())) {
        c.targets.push_back(parse_target(in, intensity));
        const bool lit = c.targets.back().claim == TargetLine::Claim::lit;
        in.advance();
        if (lit) {
            witnesses.begin(c.targets.back(), c.min_intensity);
            while (in.keyword() == "step") {
                in.expect("step", 2 * static_cast<std::size_t>(dim), "a number");
                witnesses.step(in.vector(1, dim), in.vector(1 + dim, dim));
                in.advance();
            }
            witnesses.finish();
        }
        next = lit ? "'step', 'lit', 'unlit', 'unknown' or 'answer'"
                   : "'lit', 'unlit', 'unknown' or 'answer'";
    }
    if (in.keyword() != "answer") in.fail(0, next);
    parse_verdict(in, c);
    return c;
}

} // namespace orthoray::certify
