#include "render/viewer_record.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace orthoray::render {
namespace {

using Json = nlohmann::json;

// Element shapes kept for the viewer; a larger maze is cut and the page
// says how many were kept (a browser draws 10^4 shapes smoothly, not 10^6).
constexpr std::size_t max_elements = 20'000;

Json floats(const Point3& p, int dim) {
    Json a = Json::array();
    for (int j = 0; j < dim; ++j) a.push_back(std::isfinite(p[j]) ? p[j] : 0.0);
    return a;
}

const char* status_name(TargetAnswer::Status status) {
    switch (status) {
    case TargetAnswer::Status::lit:
        return "lit";
    case TargetAnswer::Status::unlit:
        return "unlit";
    case TargetAnswer::Status::unknown:
        break;
    }
    return "unknown";
}

// "mirror x = 3, y in [0, 5]": the element's plane and extent, exactly.
std::string element_text(const Element& e, int dim) {
    std::string text = to_string(e.kind);
    if (e.is_diagonal()) {
        text += std::string(" ") + diagonal_sign(e.diagonal) + " from " +
                exact_point_text(e.from(), dim) + " to " + exact_point_text(e.to(), dim);
    } else {
        text +=
            std::string(" ") + axis_name(e.axis) + side_sign(e.side) + " = " + e.offset().get_str();
        for (int j = 0; j < dim; ++j)
            if (j != e.axis)
                text += std::string(", ") + axis_name(j) + " in [" + e.lo[j].get_str() + ", " +
                        e.hi[j].get_str() + "]";
    }
    if (e.line > 0) text += " (line " + std::to_string(e.line) + ")";
    return text;
}

} // namespace

std::string exact_point_text(const Vector& p, int dim) {
    std::string text = "(";
    for (int j = 0; j < dim; ++j) text += (j ? ", " : "") + p[j].get_str();
    return text + ")";
}

ViewerRecord::ViewerRecord(const Scene& scene, const Frame& frame, std::size_t max_segments)
    : scene_(scene), frame_(frame), max_segments_(max_segments) {}

std::size_t ViewerRecord::point(const Vector& p) {
    std::string exact = exact_point_text(p, scene_.dim);
    const auto [it, added] = index_.emplace(exact, points_.size());
    if (added) points_.push_back({std::move(exact), frame_.normalised(p)});
    return it->second;
}

std::size_t ViewerRecord::exit_point(const Point3& at) {
    points_.push_back({std::string(), at});
    return points_.size() - 1;
}

bool ViewerRecord::room() {
    ++received_;
    return segments_.size() < max_segments_;
}

void ViewerRecord::visit(const Vector& p) {
    if (max_segments_ == 0) return;
    // The start point, then one segment a point, while there is room.
    if (path_points_++ > 0 && !room()) return;
    const std::size_t here = point(p);
    if (last_) segments_.push_back({*last_, here, path_points_ - 2, 'n'});
    last_ = here;
}

void ViewerRecord::finish(const PathEnd& end, const std::optional<Point3>& exit) {
    if (!last_ || received_ > segments_.size()) return; // cut: the end is not the path's
    if (end.reason == Reason::hit && room())
        segments_.push_back({*last_, point(scene_.target()), path_points_ - 1, 'h'});
    else if (end.reason == Reason::escape && exit && room())
        segments_.push_back({*last_, exit_point(*exit), path_points_ - 1, 'e'});
    else if (end.reason == Reason::absorbed && !segments_.empty())
        segments_.back().end = 'a';
}

void ViewerRecord::segment(const BranchSegment& s, const std::optional<Point3>& exit) {
    branches_ = true;
    if (!room()) return;
    const std::size_t from = point(s.from);
    if (s.escape && !exit) return; // does not move in the picture
    const std::size_t to = s.escape ? exit_point(*exit) : point(s.to);
    segments_.push_back({from, to, s.reflections, s.escape ? 'e' : s.absorbed ? 'a' : 'n'});
}

std::string ViewerRecord::to_json(const std::vector<std::string>& caption) const {
    const int dim = scene_.dim;
    Json data;
    data["dim"] = dim;
    data["extent"] = floats(Point3{frame_.extent[0], frame_.extent[1], frame_.extent[2]}, dim);
    data["mode"] = branches_ ? "branches" : "path";
    data["caption"] = caption;
    // The answer line the command put in the caption, for its own element.
    std::string answer;
    for (const std::string& line : caption)
        if (line.starts_with("answer")) {
            answer = line;
            break;
        }
    data["answer"] = answer;

    Json elements = Json::array();
    for (std::size_t i = 0; i < std::min(scene_.elements.size(), max_elements); ++i) {
        const Element& e = scene_.elements[i];
        elements.push_back(
            {{"kind", to_string(e.kind)},
             {"axis", e.is_diagonal() ? -1 : e.axis},
             {"one_sided", e.one_sided()},
             {"a", floats(frame_.normalised(e.is_diagonal() ? e.from() : e.lo), dim)},
             {"b", floats(frame_.normalised(e.is_diagonal() ? e.to() : e.hi), dim)},
             {"exact", element_text(e, dim)}});
    }
    data["elements"] = std::move(elements);
    data["elements_total"] = scene_.elements.size();

    Json rays = Json::array();
    for (const Ray& ray : scene_.rays) {
        // The direction scaled so its largest part is 1 in normalised units
        // (the scene's numbers may be far beyond what a double divides).
        Point3 d{0, 0, 0};
        double largest = 0;
        for (int j = 0; j < dim; ++j) {
            d[j] = frame_.normalised_component(ray.direction[j], j);
            largest = std::max(largest, std::abs(d[j]));
        }
        if (largest > 0 && std::isfinite(largest))
            for (int j = 0; j < dim; ++j) d[j] /= largest;
        rays.push_back({{"at", floats(frame_.normalised(ray.start), dim)},
                        {"direction", floats(d, dim)},
                        {"exact", "start " + exact_point_text(ray.start, dim) + ", direction " +
                                      exact_point_text(ray.direction, dim)}});
    }
    data["rays"] = std::move(rays);

    Json targets = Json::array();
    for (std::size_t t = 0; t < scene_.targets.size(); ++t)
        targets.push_back(
            {{"at", floats(frame_.normalised(scene_.targets[t]), dim)},
             {"exact", exact_point_text(scene_.targets[t], dim)},
             {"status", t < targets_.size() ? status_name(targets_[t].status) : "plain"}});
    data["targets"] = std::move(targets);

    Json points = Json::array();
    for (const Point& p : points_)
        points.push_back({{"at", floats(p.at, dim)}, {"exact", p.exact}});
    data["points"] = std::move(points);
    Json segments = Json::array();
    for (const Segment& s : segments_)
        segments.push_back({s.from, s.to, s.reflections, std::string(1, s.end)});
    data["segments"] = std::move(segments);
    data["segments_received"] = received_;

    Json grid = Json::array();
    for (const auto& [a, b] : grid_)
        grid.push_back({floats(frame_.normalised(a), dim), floats(frame_.normalised(b), dim)});
    data["grid"] = std::move(grid);
    return data.dump();
}

} // namespace orthoray::render
