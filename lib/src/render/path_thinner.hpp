// Turns a stream of segments in page coordinates into one SVG path, keeping
// the output bounded: coordinates are snapped to half pixels, a segment
// whose snapped ends equal a segment already drawn (either way round) is
// merged into it, and drawing stops at a vertex cap. A periodic path of 10^7
// reflections thus costs what its distinct pixels cost, not what its length
// costs.
//
// The path is also cut by order into at most max_bands bands of equal
// numbers of segments, so the picture can shade it from early to late.
// Since the length is not known in advance (the path streams), the band
// size starts at one segment and doubles, merging neighbouring bands, each
// time the bands would overflow: between max_bands / 2 and max_bands bands
// at the end, in constant memory.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace orthoray::render {

class PathThinner {
public:
    static constexpr std::size_t max_bands = 16;

    explicit PathThinner(std::size_t max_vertices) : max_vertices_(max_vertices) {}

    // A segment of a path, banded by its place in the path.
    void add(double x0, double y0, double x1, double y1) { add_ranked(segments_, x0, y0, x1, y1); }

    // A segment banded by `rank` instead (the reflections before a branch's
    // segment): ranks must not decrease from one call to the next.
    void add_ranked(std::uint64_t rank, double x0, double y0, double x1, double y1) {
        const Snapped a = snap(x0, y0), b = snap(x1, y1);
        if (a.x == b.x && a.y == b.y) return; // shorter than a pixel: nothing to see
        select_band(rank);
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

    // SVG path data of each band, early to late (a band may be empty when
    // all its segments were merged into earlier ones).
    const std::vector<std::string>& bands() const { return bands_; }
    // Segments a full band stands for.
    std::uint64_t band_size() const { return band_size_; }
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
    // Makes the band of segment `ordinal` (or rank) current; a new band starts a new
    // sub-path, so bands concatenate into valid path data.
    void select_band(std::uint64_t ordinal) {
        // A rank may skip bands (none of its segments was a pixel long), so
        // the bands are padded before neighbours merge.
        while (ordinal / band_size_ >= max_bands) {
            bands_.resize(max_bands);
            for (std::size_t i = 0; i < max_bands / 2; ++i)
                bands_[i] = bands_[2 * i] + bands_[2 * i + 1];
            bands_.resize(max_bands / 2);
            band_size_ *= 2;
            current_ = max_bands; // no band: the next one starts a sub-path
        }
        const auto band = static_cast<std::size_t>(ordinal / band_size_);
        if (band >= bands_.size()) bands_.resize(band + 1);
        if (band != current_) pen_.reset();
        current_ = band;
    }
    void append(char command, const Snapped& p) {
        char buffer[48];
        std::snprintf(buffer, sizeof buffer, "%c%g %g", command, p.x / 2.0, p.y / 2.0);
        bands_[current_] += buffer;
    }
    void move_to(const Snapped& p) { append('M', p); }
    void line_to(const Snapped& p) { append('L', p); }

    std::size_t max_vertices_;
    std::size_t vertices_ = 0;
    std::uint64_t segments_ = 0, merged_ = 0;
    bool cut_ = false;
    std::optional<Snapped> pen_;
    std::unordered_set<std::uint64_t> seen_;
    std::vector<std::string> bands_;
    std::size_t current_ = 0;
    std::uint64_t band_size_ = 1;
};

} // namespace orthoray::render
