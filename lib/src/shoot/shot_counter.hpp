// What a shot costs, counted: the cells whose member lists it reads and the
// members it looks at. The grid shooters take a counting policy as a class
// template parameter. The engines use the default, NoCounting: an empty
// member (no space) whose calls are empty, so that their shots compile to
// the code without counting. Only the average-case measurement
// (bench/grid_average.cpp, docs/average-case.md) and its test instantiate
// Counting.
#pragma once

#include <cstdint>

namespace orthoray::shoot {

struct ShotCounts {
    // Member lists read: the cells walked by the uniform grid; 1 for the
    // cross-section grid's one cell (0 when the line misses every shadow).
    std::uint64_t cells = 0;
    // Members looked at, each an element test: every member of every walked
    // cell (uniform grid), every member scanned after those skipped as
    // behind the point (cross-section grid).
    std::uint64_t members = 0;
    // Members whose box the point on their plane was tested against
    // (ElementBox::holds): the others were rejected by their plane's t alone.
    std::uint64_t box_tests = 0;
};

struct NoCounting {
    void cell() const {}
    void member() const {}
    void box_test() const {}
};

// Adds up what the shots of one structure do, until taken. The shots are
// const, so the counts are mutable: one measuring thread only.
class Counting {
public:
    void cell() const { ++counts_.cells; }
    void member() const { ++counts_.members; }
    void box_test() const { ++counts_.box_tests; }
    // The counts since the last take, which starts them again from zero.
    ShotCounts take() const {
        const ShotCounts counts = counts_;
        counts_ = {};
        return counts;
    }

private:
    mutable ShotCounts counts_;
};

} // namespace orthoray::shoot
