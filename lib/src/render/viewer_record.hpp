// What the interactive viewer (docs/render.md, "Interactive viewer") shows,
// recorded as the path or the branches stream in: every point with its exact
// coordinates as text (for the hover read-out) and its place in the frame's
// normalised units (for drawing only), the segments in the order they were
// travelled or walked, and the targets' statuses. The recording stops at a
// cap, so memory stays bounded however long the path.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/render.hpp"
#include "render/frame.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace orthoray::render {

// "(482917/1001, 7)": the exact point, in the scene's dimension.
std::string exact_point_text(const Vector& p, int dim);

class ViewerRecord {
public:
    // Keeps at most `max_segments` segments (0: records nothing).
    ViewerRecord(const Scene& scene, const Frame& frame, std::size_t max_segments);

    // A single trajectory's points in order, then how it ends.
    void visit(const Vector& point);
    void finish(const PathEnd& end, const std::optional<Point3>& exit);
    // A branch's segment (walk_branches); `exit` is where an escape leaves
    // the frame, in normalised units.
    void segment(const BranchSegment& segment, const std::optional<Point3>& exit);
    void mark_targets(const std::vector<TargetAnswer>& targets) { targets_ = targets; }
    // Lines of a cell grid (a puzzle's blocks), in scene units.
    void set_grid(const std::vector<std::pair<Vector, Vector>>& lines) { grid_ = lines; }

    // The viewer's data as one JSON object (viewer_html.cpp embeds it).
    std::string to_json(const std::vector<std::string>& caption) const;

private:
    struct Point {
        std::string exact; // empty: a point where an escape leaves the frame
        Point3 at;
    };
    struct Segment {
        std::size_t from, to;
        std::uint64_t reflections;
        char end; // 'n' on to the next event, 'e' escape, 'a' absorbed, 'h' hit
    };
    std::size_t point(const Vector& p);
    std::size_t exit_point(const Point3& at);
    bool room();

    const Scene& scene_;
    const Frame& frame_;
    std::size_t max_segments_;
    std::vector<Point> points_;
    std::map<std::string, std::size_t> index_; // exact text -> point
    std::vector<Segment> segments_;
    std::uint64_t received_ = 0;
    std::optional<std::size_t> last_; // the path's last point
    std::uint64_t path_points_ = 0;
    bool branches_ = false;
    std::vector<TargetAnswer> targets_;
    std::vector<std::pair<Vector, Vector>> grid_;
};

} // namespace orthoray::render
