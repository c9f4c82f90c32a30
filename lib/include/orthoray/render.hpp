// Pictures of a scene and a trajectory as SVG (docs/render.md). Exact
// coordinates become floats here only, and only to place them on the page;
// nothing drawn feeds back into a decision.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"
#include "orthoray/solve.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace orthoray {

struct RenderOptions {
    int view_size = 640; // the longer side of one view's plot area, in pixels
    // Caps that keep the file small whatever the scene and path (together
    // under about 8 MB): path vertices over all views, and element shapes
    // over all views. Beyond them the picture is cut and the caption says so.
    std::size_t max_path_vertices = 200'000;
    std::size_t max_element_shapes = 100'000;
};

// How the drawn path ends, so the last piece can be drawn: on to the target
// (hit), out of the picture along `direction` (escape), or not at all.
struct PathEnd {
    Reason reason = Reason::limit;
    Vector direction; // escape: the final ray's direction
};

// Draws one scene: 2D as one view, 3D as the xy, xz and yz projections and
// an oblique view. The trajectory streams in as a PathSink (from solve() or
// from a certificate); segments that fall on pixels already drawn are merged,
// so memory and output stay bounded for 10^7 segments.
class SceneRenderer : public PathSink {
public:
    explicit SceneRenderer(const Scene& scene, const RenderOptions& options = {});
    ~SceneRenderer() override;
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    // The trajectory's points in order: the start point, then every
    // reflection point (and an absorption point). `direction` is not used.
    void visit(const Vector& point, const Vector& direction) override;
    // Called once after the last point.
    void finish(const PathEnd& end);

    // A line of the caption, above the views. The renderer adds its own
    // line when it thinned or cut the path.
    void add_caption(const std::string& line);

    // Segments received, and how many were drawn (the rest were merged
    // into pixels already drawn, or fell after a cap).
    std::uint64_t segments() const;
    bool thinned() const;

    void write_svg(std::ostream& out) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace orthoray
