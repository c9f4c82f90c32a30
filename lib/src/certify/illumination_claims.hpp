// What an illumination certificate states (docs/certificates.md), as read
// by illumination_parse.cpp: its branch lines, one line a target, and the
// verdict. Witness steps are not kept (a witness may be long); they are
// checked as they are read (witness_check.hpp).
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace orthoray::certify {

// (reflections, ray), compared lexicographically: the order in which the
// least label of a target is defined (spec optics.md: fewest reflections,
// then the least-numbered ray).
struct Label {
    Integer reflections;
    Integer ray;
};

inline bool operator<(const Label& a, const Label& b) {
    if (a.reflections != b.reflections) return a.reflections < b.reflections;
    return a.ray < b.ray;
}

inline std::string show(const Label& label) {
    std::string text = "(";
    text.append(label.reflections.get_str()).append(" reflections, ray ");
    return text.append(label.ray.get_str()).append(")");
}

// Is n one of 1 .. count (a ray or target number of the scene)?
inline bool numbers_one_of(const Integer& n, std::size_t count) {
    return n >= 1 && n <= Integer(std::to_string(count));
}

struct BranchLine {
    Vector point, direction;
    Label label;        // the illumination question
    Integer intensity;  // the intensity question: an upper bound at this state
    long long line = 0; // in the certificate file
};

struct TargetLine {
    enum class Claim { lit, unlit, unknown };
    Claim claim = Claim::unknown;
    Integer target;    // as written, numbered from 1
    Label label;       // lit only
    Integer intensity; // lit, in an intensity certificate
    long long line = 0;
};

struct IlluminationClaims {
    // Set: a certificate for the intensity question (docs/intensity.md),
    // whose branch and lit lines carry intensities.
    std::optional<Integer> min_intensity;
    std::vector<BranchLine> branches;
    std::vector<TargetLine> targets;
    std::string answer;
    Reason reason = Reason::limit;
    Integer reflections, states;
    bool partial = false;
};

} // namespace orthoray::certify
