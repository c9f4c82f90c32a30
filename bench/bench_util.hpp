// Helpers shared by the bench executables: wall-clock timing, medians, and
// the markdown table and CSV writers their reports are made of. Bench-local:
// nothing here belongs in the library.
#pragma once

#include "orthoray/number.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace orthoray::bench {

// A scene coordinate as the float baselines take it: mpq_get_d's value
// (rounded toward zero), without its division when the rational is an
// integer, as the benchmark's scenes' are. The baselines' setup times start
// from the scene in memory, so their conversion is written to be fast too.
inline double to_double(const Rational& x) {
    return is_integer(x) ? x.get_num().get_d() : x.get_d();
}

inline double seconds_since(std::chrono::steady_clock::time_point begin) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// A markdown table, printed on stdout.
class Table {
public:
    explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}
    void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
    void print() const {
        auto line = [](const std::vector<std::string>& cells) {
            std::string s = "|";
            for (const std::string& c : cells) s += " " + c + " |";
            std::printf("%s\n", s.c_str());
        };
        line(header_);
        std::vector<std::string> rule(header_.size(), "---");
        line(rule);
        for (const auto& r : rows_) line(r);
        std::printf("\n");
    }

private:
    std::vector<std::string> header_;
    std::vector<std::vector<std::string>> rows_;
};

// A CSV file written row by row and flushed after each, so that an
// interrupted run keeps what it measured. An empty path writes nothing.
class Csv {
public:
    explicit Csv(const std::string& path) {
        if (path.empty()) return;
        out_.open(path);
        if (!out_) throw std::runtime_error("cannot write " + path);
    }
    void row(const std::vector<std::string>& cells) {
        if (!out_.is_open()) return;
        for (std::size_t i = 0; i < cells.size(); ++i) out_ << (i ? "," : "") << cells[i];
        out_ << '\n';
        out_.flush();
    }

private:
    std::ofstream out_;
};

} // namespace orthoray::bench
