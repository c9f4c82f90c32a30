// Turns a stream of segments in page coordinates into one SVG path, keeping
// the output bounded: coordinates are snapped to half pixels, a segment
// whose snapped ends equal a segment already drawn (either way round) is
// merged into it, and drawing stops at a vertex cap. A periodic path of 10^7
// reflections thus costs what its distinct pixels cost, not what its length
// costs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <unordered_set>

namespace orthoray::render {

class PathThinner {
public:
    explicit PathThinner(std::size_t max_vertices) : max_vertices_(max_vertices) {}

    void add(double x0, double y0, double x1, double y1) {
        const Snapped a = snap(x0, y0), b = snap(x1, y1);
        if (a.x == b.x && a.y == b.y) return; // shorter than a pixel: nothing to see
        ++segments_;
        const std::uint64_t ka = a.key(), kb = b.key();
        const std::uint64_t key = ka < kb ? (ka << 32 | kb) : (kb << 32 | ka);
        if (seen_.size() < max_remembered) {
            if (!seen_.insert(key).second) return merged();
        } else if (seen_.count(key) != 0) {
            return merged();
        }
        const bool continues = pen_ && pen_->x == a.x && pen_->y == a.y;
        if (vertices_ + (continues ? 1 : 2) > max_vertices_) {
            cut_ = true;
            return merged();
        }
        if (!continues) {
            move_to(a);
            ++vertices_;
        }
        line_to(b);
        ++vertices_;
        pen_ = b;
    }

    const std::string& path_data() const { return d_; }
    std::uint64_t segments() const { return segments_; }
    std::uint64_t drawn() const { return segments_ - merged_; }
    bool cut() const { return cut_; }

private:
    struct Snapped {
        long x = 0, y = 0; // half pixels
        // 16 bits a coordinate for the merge key. Points far off the page
        // share keys at the clamp; they are clipped away anyway.
        std::uint64_t key() const {
            auto part = [](long v) {
                return static_cast<std::uint64_t>(std::clamp(v + 16384, 0L, 65535L));
            };
            return part(x) << 16 | part(y);
        }
    };

    // Enough memory for every segment between the pixels of a large view.
    static constexpr std::size_t max_remembered = 1'000'000;

    static Snapped snap(double x, double y) {
        auto half = [](double v) {
            return std::isfinite(v) ? std::lround(std::clamp(v, -1e7, 1e7) * 2) : 0L;
        };
        return {half(x), half(y)};
    }

    void merged() {
        ++merged_;
        pen_.reset(); // the next drawn segment starts a new sub-path
    }
    void append(char command, const Snapped& p) {
        char buffer[48];
        std::snprintf(buffer, sizeof buffer, "%c%g %g", command, p.x / 2.0, p.y / 2.0);
        d_ += buffer;
    }
    void move_to(const Snapped& p) { append('M', p); }
    void line_to(const Snapped& p) { append('L', p); }

    std::size_t max_vertices_;
    std::size_t vertices_ = 0;
    std::uint64_t segments_ = 0, merged_ = 0;
    bool cut_ = false;
    std::optional<Snapped> pen_;
    std::unordered_set<std::uint64_t> seen_;
    std::string d_;
};

} // namespace orthoray::render
