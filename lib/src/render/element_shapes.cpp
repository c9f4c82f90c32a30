// Elements as path data: a segment where a view sees the element edge-on, a
// quadrilateral where it sees its face, ticks on a one-sided element's
// acting side.
#include "render/element_shapes.hpp"

#include "render/markers.hpp"
#include "render/svg_writer.hpp"

#include <algorithm>
#include <string>
#include <unordered_set>

namespace orthoray::render {
namespace {

// Ticks on the side a one-sided element acts on (markers.hpp): toward
// where a step off the element to that side lands on the page.
void side_ticks(const View& v, const Element& e, const Point3& corner,
                const std::vector<Pixel>& shape, std::string& d) {
    Point3 off = corner;
    off[static_cast<std::size_t>(e.axis)] += e.side == Side::plus ? 0.01 : -0.01;
    d += render::side_ticks(shape, v.map(corner), v.map(off));
}

} // namespace

// Shapes that snap to the same half pixels as one already drawn in the view
// are skipped, so dense scenes stay small.
std::size_t draw_elements(const Scene& scene, const Frame& frame, std::vector<View>& views,
                          std::size_t max_shapes) {
    const std::size_t cap = max_shapes / views.size();
    for (View& v : views) {
        std::unordered_set<std::string> seen;
        for (const Element& e : scene.elements) {
            if (v.shapes >= cap) break;
            // A diagonal (2D) runs between its ends, not its box's corners.
            Point3 c0 = frame.normalised(e.is_diagonal() ? e.from() : e.lo),
                   c1 = frame.normalised(e.is_diagonal() ? e.to() : e.hi);
            std::vector<Pixel> corners;
            bool face = false;
            if (scene.dim == 2 || (!v.oblique && (e.axis == v.a || e.axis == v.b))) {
                corners = {v.map(c0), v.map(c1)};
            } else {
                face = true;
                // The rectangle's corners: the two non-normal axes vary.
                int p = -1, q = -1;
                for (int j = 0; j < 3; ++j)
                    if (j != e.axis) (p < 0 ? p : q) = j;
                Point3 k = c0;
                for (int corner : {0, 1, 3, 2}) {
                    k[p] = corner & 1 ? c1[p] : c0[p];
                    k[q] = corner & 2 ? c1[q] : c0[q];
                    corners.push_back(v.map(k));
                }
            }
            std::string d;
            for (std::size_t i = 0; i < corners.size(); ++i) {
                d += i ? 'L' : 'M';
                d += number_text(corners[i].x);
                d += ' ';
                d += number_text(corners[i].y);
            }
            if (face) d += "Z";
            const auto kind = static_cast<std::size_t>(e.kind);
            if (!seen.insert(d + kind_class[kind]).second) continue;
            ++v.shapes;
            (face ? v.faces : v.edges)[kind] += d;
            if (e.one_sided()) side_ticks(v, e, c0, corners, v.ticks[kind]);
        }
    }
    std::size_t drawn = scene.elements.size();
    for (const View& v : views)
        if (v.shapes >= cap) drawn = std::min(drawn, v.shapes);
    return drawn;
}

} // namespace orthoray::render
