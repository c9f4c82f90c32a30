// Pictures: the SVG is well-formed XML with the expected views, elements,
// markers and caption; the drawn path has the segments the answer implies;
// long paths are thinned to a bounded file and the caption says so, and
// are drawn in bands shaded from early to late; the views of a 3D scene share
// one scale; the path from a certificate (either format) is the path from
// the solver; tick labels are exact.
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/render.hpp"
#include "orthoray/solve.hpp"
#include "render/axis_ticks.hpp"
#include "support/xml_check.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using orthoray::PathEnd;
using orthoray::Reason;
using orthoray::RenderOptions;
using orthoray::Scene;
using orthoray::SceneRenderer;
using orthoray::test::read_xml;
using orthoray::test::with_class;
using orthoray::test::XmlDocument;
using orthoray::test::XmlElement;

namespace {

Scene instance(const std::string& name) {
    return orthoray::load_scene(std::string(ORTHORAY_SOURCE_DIR) + "/instances/" + name);
}

// Records the last direction the solver streams, for the escape ray.
class LastDirection : public orthoray::PathSink {
public:
    explicit LastDirection(PathSink& next) : next_(next) {}
    void visit(const orthoray::Vector& p, const orthoray::Vector& v) override {
        direction = v;
        next_.visit(p, v);
    }
    orthoray::Vector direction;

private:
    PathSink& next_;
};

struct Picture {
    std::string svg;
    XmlDocument xml;
    orthoray::Answer answer;
};

Picture draw(const Scene& scene, std::uint64_t max_steps = 1000, RenderOptions options = {}) {
    SceneRenderer renderer(scene, options);
    LastDirection tap(renderer);
    orthoray::SolveOptions solve_options;
    solve_options.max_steps = max_steps;
    solve_options.path = &tap;
    Picture p;
    p.answer = orthoray::solve(scene, solve_options);
    renderer.add_caption(std::string("answer ") + orthoray::answer_word(p.answer));
    renderer.finish({p.answer.reason, tap.direction});
    std::ostringstream out;
    renderer.write_svg(out);
    p.svg = out.str();
    p.xml = read_xml(p.svg);
    return p;
}

std::size_t count_char(const std::string& text, char c) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), c));
}

// The path data of all trajectory bands, early to late.
std::string trajectory(const XmlDocument& doc) {
    std::string d;
    for (const XmlElement* e : with_class(doc, "path", "trajectory")) d += e->attributes.at("d");
    return d;
}

std::string caption(const XmlDocument& doc) {
    std::string all;
    for (const XmlElement* e : with_class(doc, "text", "caption")) all += e->text + "\n";
    return all;
}

} // namespace

TEST_CASE("the XML checker itself rejects broken documents", "[render]") {
    CHECK(read_xml("<a><b x=\"1\"/>t</a>").well_formed);
    CHECK_FALSE(read_xml("<a><b></a></b>").well_formed);
    CHECK_FALSE(read_xml("<a x=1/>").well_formed);
    CHECK_FALSE(read_xml("<a>&nbsp;</a>").well_formed);
    CHECK_FALSE(read_xml("<a>").well_formed);
    CHECK_FALSE(read_xml("<a/><b/>").well_formed);
    CHECK_FALSE(read_xml("t<a/>").well_formed);
    CHECK_FALSE(read_xml("<a>\x01</a>").well_formed);
    CHECK(read_xml("<?xml version=\"1.0\"?>\n<a x=\"&amp;nbsp;&#38;\">&lt;</a>\n").well_formed);
    CHECK(read_xml("<a> <b/> </a>").elements.at(0).text == "  ");
}

TEST_CASE("a 2D picture has the mirrors, markers, caption and the whole path", "[render]") {
    const Picture p = draw(instance("2d/box-corner-3x5.scene"));
    INFO(p.xml.error);
    REQUIRE(p.xml.well_formed);
    CHECK(p.xml.elements.front().name == "svg");
    CHECK(with_class(p.xml, "g", "view").size() == 1);
    const auto mirrors = with_class(p.xml, "path", "mirror");
    REQUIRE(mirrors.size() == 1);
    CHECK(count_char(mirrors[0]->attributes.at("d"), 'M') == 4); // four mirrors
    CHECK(with_class(p.xml, "path", "absorber").empty());
    // 6 reflections: 6 segments between the 7 points, then on to the target;
    // so short a path gets a band, and a shade, for each segment.
    const auto bands = with_class(p.xml, "path", "trajectory");
    CHECK(bands.size() == 7);
    CHECK(count_char(trajectory(p.xml), 'L') == 7);
    CHECK(count_char(trajectory(p.xml), 'M') == 7);
    CHECK(with_class(p.xml, "circle", "start").size() == 1);
    CHECK(with_class(p.xml, "path", "start-arrow").size() == 1);
    CHECK(with_class(p.xml, "path", "target").size() == 1);
    CHECK(caption(p.xml) == "answer yes\n");
    // Tick labels in scene coordinates: 0..3 across, 0..5 up.
    std::vector<std::string> ticks;
    for (const XmlElement* e : with_class(p.xml, "text", "tick")) ticks.push_back(e->text);
    CHECK(ticks == std::vector<std::string>{"0", "1", "2", "3", "0", "1", "2", "3", "4", "5"});
}

TEST_CASE("an escape is drawn out to the frame and an absorption is marked", "[render]") {
    const Picture escape = draw(instance("2d/escape-after-three-reflections.scene"));
    REQUIRE(escape.xml.well_formed);
    REQUIRE(escape.answer.reason == Reason::escape);
    CHECK(count_char(trajectory(escape.xml), 'L') == 4); // 3 segments + the final ray

    const Picture absorbed = draw(instance("2d/absorbed-after-three-reflections.scene"));
    REQUIRE(absorbed.xml.well_formed);
    CHECK(with_class(absorbed.xml, "path", "absorber").size() == 1);
    CHECK(with_class(absorbed.xml, "rect", "absorbed").size() == 1);
}

TEST_CASE("a 3D picture has three projections and an oblique view", "[render]") {
    const Picture p = draw(instance("3d/corner-cube-retroreflector.scene"));
    INFO(p.xml.error);
    REQUIRE(p.xml.well_formed);
    std::vector<std::string> names;
    for (const XmlElement* e : with_class(p.xml, "g", "view"))
        names.push_back(e->attributes.at("data-name"));
    CHECK(names == std::vector<std::string>{"xy (top)", "xz (front)", "yz (side)", "oblique"});
    // Each mirror is seen face-on in one projection and in the oblique view.
    const auto faces = with_class(p.xml, "path", "face-mirror");
    std::size_t face_count = 0;
    for (const XmlElement* f : faces) face_count += count_char(f->attributes.at("d"), 'Z');
    CHECK(face_count == 3 + 3);
    CHECK(with_class(p.xml, "path", "trajectory").size() >= 4);
    CHECK(with_class(p.xml, "path", "target").size() == 4);
}

TEST_CASE("a long periodic path is thinned to a small file and the caption says so", "[render]") {
    // A 997 x 1000 box: the 45-degree ray covers it in ~2000 reflections a period.
    Scene scene = orthoray::read_scene("dim 2\nmirror x 0 y 0 1000\nmirror x 997 y 0 1000\n"
                                       "mirror y 0 x 0 997\nmirror y 1000 x 0 997\n"
                                       "ray 0 0 1 1\ntarget 500 -1\n");
    const Picture p = draw(scene, 200'000);
    REQUIRE(p.xml.well_formed);
    REQUIRE(p.answer.reason == Reason::cycle);
    CHECK(caption(p.xml).find("thinned: ") != std::string::npos);
    CHECK(p.svg.size() < 200'000);

    RenderOptions tiny;
    tiny.max_path_vertices = 100;
    const Picture cut = draw(scene, 200'000, tiny);
    REQUIRE(cut.xml.well_formed);
    CHECK(caption(cut.xml).find("cut at the 100-vertex cap") != std::string::npos);
    const std::string d = trajectory(cut.xml);
    CHECK(count_char(d, 'L') + count_char(d, 'M') <= 100);
}

TEST_CASE("a certificate's path draws like the solver's, in both formats", "[render]") {
    for (const char* name : {"2d/box-corner-3x5.scene", "3d/box-corner-2x3x5.scene",
                             "2d/escape-after-three-reflections.scene"}) {
        INFO(name);
        const Scene scene = instance(name);
        const Picture solved = draw(scene);
        for (auto format :
             {orthoray::CertificateFormat::text, orthoray::CertificateFormat::jsonl}) {
            std::stringstream cert;
            orthoray::CertificateWriter writer(cert, scene, format);
            orthoray::SolveOptions options;
            writer.attach(options);
            writer.finish(orthoray::solve(scene, options));

            SceneRenderer renderer(scene);
            const orthoray::CertificateClaim claim =
                orthoray::read_certificate_path(scene, cert, "c", renderer);
            CHECK(claim.complete);
            CHECK(claim.reason == solved.answer.reason);
            CHECK(claim.reflections == solved.answer.reflections);
            renderer.add_caption("answer " + claim.answer);
            renderer.finish({claim.reason, claim.direction});
            std::ostringstream out;
            renderer.write_svg(out);
            CHECK(out.str() == solved.svg);
        }
    }
}

TEST_CASE("tick values are exact round numbers", "[render]") {
    using orthoray::Rational;
    auto labels = [](const Rational& lo, const Rational& hi, int count) {
        std::vector<std::string> result;
        for (const auto& t : orthoray::render::axis_ticks(lo, hi, count).ticks)
            result.push_back(t.label);
        return result;
    };
    CHECK(labels(0, 5, 5) == std::vector<std::string>{"0", "1", "2", "3", "4", "5"});
    CHECK(labels(Rational(-1, 3), Rational(1, 3), 4) ==
          std::vector<std::string>{"-0.2", "0", "0.2"});
    CHECK(labels(Rational(1, 1000), Rational(3, 1000), 2) ==
          std::vector<std::string>{"0.001", "0.002", "0.003"});
    CHECK(labels(Rational(1'000'000), Rational(1'000'003), 3) ==
          std::vector<std::string>{"1000000", "1000001", "1000002", "1000003"});
    const auto ticks = orthoray::render::axis_ticks(Rational(-7, 2), Rational(7, 2), 4).ticks;
    REQUIRE_FALSE(ticks.empty());
    CHECK(ticks.front().label == "-2");
    CHECK(ticks.front().fraction == Approx(1.5 / 7));
    // A span no double can hold still gets round, exact ticks.
    // Appended, as GCC 12 at -O3 warns falsely on `+` (-Warray-bounds).
    const orthoray::Rational huge(orthoray::Integer(std::string("1").append(400, '0')));
    const auto far = orthoray::render::axis_ticks(0, huge, 4).ticks;
    REQUIRE(far.size() >= 3);
    CHECK(far[1].fraction == Approx(far.back().fraction / static_cast<double>(far.size() - 1)));
    CHECK(far[1].label == "5e399");
    // Ticks 1 apart at 10^40 would all read 1e40: they count from an exact
    // round offset instead, which the axis names, and a negative one too.
    const Rational base(orthoray::Integer(std::string("1").append(40, '0')));
    const auto offset = orthoray::render::axis_ticks(base, base + 3, 3);
    CHECK(offset.offset == "1e40");
    CHECK_FALSE(offset.offset_negative);
    std::vector<std::string> counted;
    for (const auto& t : offset.ticks) counted.push_back(t.label);
    CHECK(counted == std::vector<std::string>{"0", "1", "2", "3"});
    const Rational odd(orthoray::Integer("123456789012345678901234567890123456789"));
    const auto negative = orthoray::render::axis_ticks(-odd - 2, -odd, 2);
    CHECK(negative.offset_negative);
    CHECK(negative.offset == "1.2345678901234567890123456789012346e38");
    REQUIRE(negative.ticks.size() == 3);
    CHECK(negative.ticks.front().label == "3209"); // x + 1.23...46e38
    CHECK(negative.ticks.back().label == "3211");
    // Near the origin nothing changes.
    CHECK(orthoray::render::axis_ticks(0, 5, 5).offset.empty());
}

TEST_CASE("the views of a 3D scene share one scale", "[render]") {
    // The 2 x 3 x 5 box: each side appears in two projections, at one length
    // in pixels in both; before, each view had a scale of its own, and the
    // short sides were stretched.
    const Picture p = draw(instance("3d/box-corner-2x3x5.scene"));
    REQUIRE(p.xml.well_formed);
    std::vector<double> width, height;
    for (const XmlElement* e : with_class(p.xml, "rect", "frame")) {
        width.push_back(std::stod(e->attributes.at("width")));
        height.push_back(std::stod(e->attributes.at("height")));
    }
    REQUIRE(width.size() == 4);                        // xy, xz, yz, oblique
    CHECK(width[0] == Approx(width[1]).margin(0.1));   // x in xy and xz
    CHECK(height[0] == Approx(width[2]).margin(0.1));  // y in xy and yz
    CHECK(height[1] == Approx(height[2]).margin(0.1)); // z in xz and yz
    // And the scale is the frame's: x : z as 2 : 5 up to the frame's padding
    // (4% of the longest side on each end).
    CHECK(width[1] / height[1] == Approx((2 + 0.4) / (5 + 0.4)).epsilon(0.01));
    // The oblique view's axis key stays left of its plot area, clear of the
    // start marker at the frame's corner.
    const auto frames = with_class(p.xml, "rect", "frame");
    const double oblique_left = std::stod(frames[3]->attributes.at("x"));
    const auto labels = with_class(p.xml, "text", "axis");
    REQUIRE(labels.size() == 6 + 3);
    for (std::size_t i = 6; i < labels.size(); ++i)
        CHECK(std::stod(labels[i]->attributes.at("x")) < oblique_left);
}

TEST_CASE("a long path is shaded from early to late in a bounded number of bands", "[render]") {
    // 997 x 1000 box, 45 degrees: about 2000 distinct segments a period.
    Scene scene = orthoray::read_scene("dim 2\nmirror x 0 y 0 1000\nmirror x 997 y 0 1000\n"
                                       "mirror y 0 x 0 997\nmirror y 1000 x 0 997\n"
                                       "ray 0 0 1 1\ntarget 500 -1\n");
    const Picture p = draw(scene, 1500);
    REQUIRE(p.xml.well_formed);
    const auto bands = with_class(p.xml, "path", "trajectory");
    // The band size doubles as the path grows: 8 to 16 bands at the end.
    CHECK(bands.size() >= 8);
    CHECK(bands.size() <= 16);
    // Every band has its own colour, the first one the ramp's start (amber)
    // and the last its end (purple).
    std::vector<std::string> colours;
    for (const XmlElement* b : bands) colours.push_back(b->attributes.at("stroke"));
    CHECK(colours.front() == "#f0a30a");
    CHECK(colours.back() == "#5c1878");
    std::vector<std::string> distinct = colours;
    std::sort(distinct.begin(), distinct.end());
    CHECK(std::unique(distinct.begin(), distinct.end()) == distinct.end());
    // The first band starts where the ray does: the bands are in path order.
    const std::string& first = bands.front()->attributes.at("d");
    const auto start = with_class(p.xml, "circle", "start");
    REQUIRE(start.size() == 1);
    double x = 0, y = 0;
    REQUIRE(std::sscanf(first.c_str(), "M%lf %lf", &x, &y) == 2);
    CHECK(x == Approx(std::stod(start[0]->attributes.at("cx"))).margin(0.5));
    CHECK(y == Approx(std::stod(start[0]->attributes.at("cy"))).margin(0.5));
    // A key to the shading is drawn.
    CHECK(with_class(p.xml, "rect", "legend").size() == 8);
}

namespace {

// A scene drawn from walk_branches, its targets marked from solve().
struct BranchPicture {
    std::string svg;
    XmlDocument xml;
    orthoray::BranchWalk walk;
    orthoray::Answer answer;
};

BranchPicture draw_branches(const Scene& scene, std::uint64_t max_states = 1000) {
    SceneRenderer renderer(scene);
    BranchPicture p;
    p.walk = orthoray::walk_branches(scene, renderer, max_states);
    p.answer = orthoray::solve(scene);
    renderer.mark_targets(p.answer.targets);
    std::ostringstream out;
    renderer.write_svg(out);
    p.svg = out.str();
    p.xml = read_xml(p.svg);
    return p;
}

// Records what walk_branches hands on.
struct SegmentRecorder : orthoray::BranchSink {
    std::vector<orthoray::BranchSegment> segments;
    void segment(const orthoray::BranchSegment& s) override { segments.push_back(s); }
};

// By hand: from (1, 1) along (1, 1) the ray meets the splitter x = 2 at
// (2, 2) (0 reflections). Through it, it goes on to the mirror y = 3 at
// (3, 3) (0 reflections), reflects to (1, -1) and escapes (1 reflection).
// Reflected by the splitter it goes along (-1, 1) to the absorber x = 0 at
// (0, 4) (1 reflection). Four states, four segments, in two shades; target
// (1, 3) is on the absorbed branch, (3, 3) at the mirror, (4, 4) on none.
const char* splitter_scene = "dim 2\n"
                             "splitter x 2 y 0 4\n"
                             "absorber x 0 y 0 4\n"
                             "mirror y 3 x 2 4\n"
                             "ray 1 1 1 1\n"
                             "target 1 3\n"
                             "target 3 3\n"
                             "target 4 4\n";

} // namespace

TEST_CASE("walk_branches walks every state once, fewest reflections first", "[render][optics]") {
    const Scene scene = orthoray::read_scene(splitter_scene, "split.scene");
    SegmentRecorder r;
    const orthoray::BranchWalk walk = orthoray::walk_branches(scene, r, 1000);
    CHECK(walk.complete);
    CHECK(walk.states == 4);
    REQUIRE(r.segments.size() == 4);
    std::vector<std::uint64_t> reflections;
    for (const auto& s : r.segments) reflections.push_back(s.reflections);
    CHECK(reflections == std::vector<std::uint64_t>{0, 0, 1, 1});
    CHECK(r.segments[0].to == orthoray::Vector{2, 2, 0});
    CHECK(r.segments[1].to == orthoray::Vector{3, 3, 0});
    CHECK(std::count_if(r.segments.begin(), r.segments.end(),
                        [](const auto& s) { return s.escape; }) == 1);
    CHECK(std::count_if(r.segments.begin(), r.segments.end(),
                        [](const auto& s) { return s.absorbed; }) == 1);

    SegmentRecorder capped;
    const orthoray::BranchWalk cut = orthoray::walk_branches(scene, capped, 3);
    CHECK_FALSE(cut.complete);
    CHECK(cut.limit == orthoray::Limit::steps);
    CHECK(capped.segments.size() == 3);

    struct Stop : orthoray::RunMonitor {
        std::optional<orthoray::Limit> poll(std::uint64_t) override {
            return orthoray::Limit::interrupt;
        }
    } stop;
    SegmentRecorder stopped;
    const orthoray::BranchWalk interrupted = orthoray::walk_branches(scene, stopped, 1000, &stop);
    CHECK_FALSE(interrupted.complete);
    CHECK(interrupted.limit == orthoray::Limit::interrupt);
    CHECK(stopped.segments.empty());
}

TEST_CASE("a splitter scene draws every branch, splitters dashed, targets lit or unlit",
          "[render][optics]") {
    const BranchPicture p = draw_branches(orthoray::read_scene(splitter_scene, "split.scene"));
    INFO(p.xml.error);
    REQUIRE(p.xml.well_formed);
    // One L a segment: the four branches' segments, none merged.
    CHECK(count_char(trajectory(p.xml), 'L') == 4);
    CHECK(with_class(p.xml, "path", "trajectory").size() == 2); // 0 and 1 reflections
    CHECK(with_class(p.xml, "path", "splitter").size() == 1);
    CHECK(with_class(p.xml, "path", "mirror").size() == 1);
    CHECK(with_class(p.xml, "path", "absorber").size() == 1);
    CHECK(with_class(p.xml, "circle", "target-lit").size() == 2);
    CHECK(with_class(p.xml, "circle", "target-unlit").size() == 1);
    CHECK(with_class(p.xml, "circle", "target").empty());
    CHECK(with_class(p.xml, "rect", "absorbed").size() == 1);
    CHECK(with_class(p.xml, "text", "marker-label").size() == 3); // "target 1" .. "target 3"
    CHECK(p.svg.find("reflections so far: 0") != std::string::npos);
}

TEST_CASE("one-sided elements get ticks on the side that acts, in 2D and 3D", "[render][optics]") {
    // A one-way mirror facing +x: ticks to its right (larger page x).
    const BranchPicture flat = draw_branches(orthoray::read_scene(
        "dim 2\nmirror x+ 2 y 0 4\nmirror x 0 y 0 4\nray 3 1 -1 0\ntarget 1 1\n", "one.scene"));
    REQUIRE(flat.xml.well_formed);
    const auto ticks = with_class(flat.xml, "path", "side-mirror");
    REQUIRE(ticks.size() == 1);
    const std::string& d = ticks[0]->attributes.at("d");
    CHECK(count_char(d, 'M') >= 5);
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    REQUIRE(std::sscanf(d.c_str(), "M%lf %lfL%lf %lf", &x0, &y0, &x1, &y1) == 4);
    CHECK(x1 > x0);
    CHECK(y1 == y0);
    // 3D: the projections that see the element edge-on and the oblique view
    // have ticks, the one looking along its normal does not.
    const BranchPicture deep = draw_branches(orthoray::read_scene(
        "dim 3\nsplitter z- 2 x 0 4 y 0 4\nray 1 1 0 0 0 1\ntarget 1 1 5\ntarget 2 2 2\n",
        "deep.scene"));
    REQUIRE(deep.xml.well_formed);
    CHECK(with_class(deep.xml, "path", "side-splitter").size() == 3);
    CHECK(with_class(deep.xml, "path", "face-splitter").size() == 2); // xy and oblique
    CHECK(with_class(deep.xml, "circle", "target-lit").size() == 4);  // one target, four views
    CHECK(with_class(deep.xml, "circle", "target-unlit").size() == 4);
}

TEST_CASE("diagonals are drawn between their ends, and their branches walked",
          "[render][octagonal]") {
    // '\' from (0, 2) down to (2, 0), '/' from (3, 0) up to (5, 2); the ray
    // meets '\' at (1, 1) and leaves downward.
    const BranchPicture p = draw_branches(orthoray::read_scene(
        "dim 2\nmirror \\ 0 2 2 0\nmirror / 3 0 5 2\nray -1 1 1 0\ntarget 1 1\ntarget 9 9\n"));
    INFO(p.xml.error);
    REQUIRE(p.xml.well_formed);
    const auto mirrors = with_class(p.xml, "path", "mirror");
    REQUIRE(mirrors.size() == 1);
    std::string d = mirrors[0]->attributes.at("d");
    for (char& c : d)
        if (c == 'M' || c == 'L') c = ' ';
    std::istringstream numbers(d);
    double x[4], y[4];
    for (int i = 0; i < 4; ++i) REQUIRE(numbers >> x[i] >> y[i]);
    // The page's y grows downward: '\' falls to the right on the page's
    // terms, so its second end is lower (greater y); '/' rises.
    CHECK(x[1] > x[0]);
    CHECK(y[1] > y[0]);
    CHECK(x[3] > x[2]);
    CHECK(y[3] < y[2]);
    CHECK(p.walk.states == 2); // the start and the state leaving (1, 1)
    CHECK(with_class(p.xml, "circle", "target-lit").size() == 1);
    CHECK(with_class(p.xml, "circle", "target-unlit").size() == 1);
}
