#include "induction/collisions.hpp"

#include <algorithm>

namespace orthoray::induction {

std::optional<std::vector<Collision>> find_collisions(const std::vector<RawPiece>& pieces) {
    struct Image {
        Integer start, length, from;
    };
    std::vector<Image> images;
    for (const RawPiece& p : pieces)
        if (p.kind == PieceKind::reflect) images.push_back({p.image, p.length, p.start});
    std::sort(images.begin(), images.end(), [](const Image& a, const Image& b) {
        return a.start < b.start || (a.start == b.start && a.from < b.from);
    });
    std::vector<Collision> out;
    Integer covered; // the images so far cover up to here (exclusive)
    for (std::size_t i = 0; i < images.size(); ++i) {
        const Image& next = images[i];
        const Integer end = next.start + next.length;
        if (i > 0 && next.start < covered) {
            // They share [next.start, min(covered, end)): one state, or no
            // collision this walk can take.
            if (std::min(covered, end) != next.start + 1) return std::nullopt;
            out.push_back({next.from, next.start});
        }
        if (i == 0 || covered < end) covered = end;
    }
    return out;
}

void cut_collisions(std::vector<RawPiece>& pieces, const std::vector<Collision>& collisions) {
    for (const Collision& c : collisions) {
        RawPiece& p = pieces[isolate_state(pieces, c.state)];
        p.kind = PieceKind::absorbed;
        p.image = 0;
    }
}

} // namespace orthoray::induction
