// What the two closure checks of an illumination certificate share
// (illumination_verifier.cpp for labels, intensity_closure.cpp for
// intensities): the map from a branch line's state to the line, and the
// failure they throw.
#pragma once

#include "orthoray/scene.hpp"

#include <cstddef>
#include <map>
#include <string>
#include <utility>

namespace orthoray::certify {

struct StateOrder {
    bool operator()(const std::pair<Vector, Vector>& a, const std::pair<Vector, Vector>& b) const {
        for (int j = 0; j < 3; ++j)
            if (int c = cmp(a.first[j], b.first[j])) return c < 0;
        for (int j = 0; j < 3; ++j)
            if (int c = cmp(a.second[j], b.second[j])) return c < 0;
        return false;
    }
};
// (point, direction) -> the index of its branch line.
using StateIndex = std::map<std::pair<Vector, Vector>, std::size_t, StateOrder>;

// A failed check, caught by verify_illumination.
struct Invalid {
    std::string message;
};

[[noreturn]] inline void invalid(const std::string& what) {
    throw Invalid{"invalid: " + what};
}

inline std::string at_line(long long line) {
    return "line " + std::to_string(line);
}

} // namespace orthoray::certify
