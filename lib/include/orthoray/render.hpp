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
#include <utility>
#include <vector>

namespace orthoray {

struct RenderOptions {
    int view_size = 640; // the longer side of one view's plot area, in pixels
    // Caps that keep the file small whatever the scene and path (together
    // under about 8 MB): path vertices over all views, and element shapes
    // over all views. Beyond them the picture is cut and the caption says so.
    std::size_t max_path_vertices = 200'000;
    std::size_t max_element_shapes = 100'000;
    // Segments kept, with their exact points, for write_html (0: none are
    // kept, and the page shows the scene alone). Memory grows with them, so
    // the interactive viewer keeps the first few thousand only.
    std::size_t viewer_segments = 0;
};

// How the drawn path ends, so the last piece can be drawn: on to the target
// (hit), out of the picture along `direction` (escape), or not at all.
struct PathEnd {
    Reason reason = Reason::limit;
    Vector direction; // escape: the final ray's direction
};

// One segment of one branch of a ray (docs/optics.md): from a state's point
// along its direction to the next event, or to infinity (`escape`), or to an
// absorption point (`absorbed`).
struct BranchSegment {
    Vector from, to; // `to` is unset on escape
    Vector direction;
    bool escape = false, absorbed = false;
    // The least reflections, over every branch of every ray, before `from`.
    std::uint64_t reflections = 0;
};

class BranchSink {
public:
    virtual ~BranchSink() = default;
    virtual void segment(const BranchSegment& segment) = 0;
};

struct BranchWalk {
    bool complete = false;      // every reachable state was walked
    Limit limit = Limit::steps; // why not, when incomplete
    std::uint64_t states = 0;   // states walked (each one segment)
};

// Walks every branch of every ray, each state (event point, outgoing
// direction) once, with the illumination search's stepper (the rays'
// lattices where they apply, engine::fastest_stepper) and the acting rule of
// docs/optics.md, and hands each state's segment to `sink` in order of
// least reflections (a 0-1 breadth-first search: a pass-through costs 0, a
// reflection 1). At most `max_states` states; the monitor is polled every
// 10 ms and may stop the walk. Memory grows with the states walked.
BranchWalk walk_branches(const Scene& scene, BranchSink& sink, std::uint64_t max_states,
                         RunMonitor* monitor = nullptr);

// Draws one scene: 2D as one view, 3D as the xy, xz and yz projections and
// an oblique view. The trajectory streams in as a PathSink (from solve() or
// from a certificate); segments that fall on pixels already drawn are merged,
// so memory and output stay bounded for 10^7 segments.
//
// Scenes with splitters, one-sided elements or several rays and targets are
// drawn from walk_branches instead: the renderer is then a BranchSink, every
// branch's segments shaded by reflections so far, and mark_targets says
// which targets are lit.
class SceneRenderer : public PathSink, public BranchSink {
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

    // A branch's segment (instead of visit and finish), in order of
    // reflections as walk_branches gives them.
    void segment(const BranchSegment& segment) override;
    // Each target's status, in file order, for its marker (lit, unlit or
    // unknown); without it the targets are drawn plain.
    void mark_targets(const std::vector<TargetAnswer>& targets);

    // A line of the caption, above the views. The renderer adds its own
    // line when it thinned or cut the path.
    void add_caption(const std::string& line);

    // Segments received, and how many were drawn (the rest were merged
    // into pixels already drawn, or fell after a cap).
    std::uint64_t segments() const;
    bool thinned() const;

    void write_svg(std::ostream& out) const;

    // Lines drawn under everything else in the HTML viewer, in scene
    // units: a puzzle's cell grid.
    void set_grid(const std::vector<std::pair<Vector, Vector>>& lines);
    // The interactive viewer (docs/render.md): one self-contained HTML page
    // with the scene, the first RenderOptions::viewer_segments segments with
    // their exact points, the caption and a step slider, zoom, pan and, in
    // 3D, rotation. `title` is the page's heading.
    void write_html(std::ostream& out, const std::string& title) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace orthoray
