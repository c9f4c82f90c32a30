// The interactive viewer's page (SceneRenderer::write_html, `render --html`):
// it is self-contained (no address outside the file but the SVG namespace,
// no external script or style sheet), its embedded data carries the exact
// coordinates of every point as text and the segments the answer implies,
// text cannot break out of the data's <script>, the recording stops at its
// cap, and the command line writes it through the checked output. What
// the page does in a browser is tests/browser/test_viewer.py's to check.
#include "orthoray/parse.hpp"
#include "orthoray/render.hpp"
#include "orthoray/solve.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

using nlohmann::json;
using orthoray::RenderOptions;
using orthoray::Scene;
using orthoray::SceneRenderer;
using orthoray::test::quote;
using orthoray::test::run_cli;
using orthoray::test::slurp;
using orthoray::test::TempDir;

namespace {

std::string page_of(const Scene& scene, std::size_t viewer_segments, std::uint64_t steps = 1000,
                    const std::string& extra_caption = "") {
    RenderOptions options;
    options.viewer_segments = viewer_segments;
    SceneRenderer renderer(scene, options);
    orthoray::SolveOptions solve_options;
    solve_options.max_steps = steps;
    solve_options.path = &renderer;
    const orthoray::Answer answer = orthoray::solve(scene, solve_options);
    renderer.add_caption(std::string("answer ") + orthoray::answer_word(answer));
    if (!extra_caption.empty()) renderer.add_caption(extra_caption);
    renderer.finish({answer.reason, {}});
    std::ostringstream out;
    renderer.write_html(out, "a test page");
    return out.str();
}

// The JSON between the data script's tags.
json embedded_data(const std::string& page) {
    const std::string open = "<script type=\"application/json\" id=\"viewer-data\">";
    const std::size_t begin = page.find(open);
    REQUIRE(begin != std::string::npos);
    const std::size_t end = page.find("</script>", begin);
    REQUIRE(end != std::string::npos);
    return json::parse(page.substr(begin + open.size(), end - begin - open.size()));
}

std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

} // namespace

TEST_CASE("the viewer page refers to nothing outside itself", "[render][viewer]") {
    const std::string page =
        page_of(orthoray::load_scene(orthoray::test::instance("2d/box-corner-3x5.scene")), 100);
    CHECK(page.starts_with("<!DOCTYPE html>"));
    CHECK(page.find("https://") == std::string::npos);
    // The one address is the SVG namespace, a name the script passes to
    // createElementNS, never fetched.
    CHECK(occurrences(page, "http://") == 1);
    CHECK(occurrences(page, "\"http://www.w3.org/2000/svg\"") == 1);
    CHECK(page.find("src=") == std::string::npos);
    CHECK(page.find("<link") == std::string::npos);
    CHECK(page.find("@import") == std::string::npos);
    CHECK(page.find("url(") == std::string::npos);
    CHECK(occurrences(page, "<script") == 2); // the data and the viewer
}

TEST_CASE("the viewer's data carries every point exactly", "[render][viewer]") {
    // fractions-and-decimals.scene derives its path in its comment:
    // (1/2, 1/4), (5/2, 5/4), (2, 3/2), (-5/4, -1/8), then on to the
    // target (3/4, -9/8): a hit after 3 reflections.
    const Scene scene =
        orthoray::load_scene(orthoray::test::instance("2d/fractions-and-decimals.scene"));
    const json data = embedded_data(page_of(scene, 100));
    CHECK(data["dim"] == 2);
    CHECK(data["mode"] == "path");
    CHECK(data["answer"] == "answer yes");
    REQUIRE(data["segments"].size() == 4);
    const std::vector<std::string> expected{"(1/2, 1/4)", "(5/2, 5/4)", "(2, 3/2)", "(-5/4, -1/8)",
                                            "(3/4, -9/8)"};
    for (std::size_t i = 0; i < 4; ++i) {
        const json& s = data["segments"][i];
        CHECK(data["points"][s[0].get<std::size_t>()]["exact"] == expected[i]);
        CHECK(data["points"][s[1].get<std::size_t>()]["exact"] == expected[i + 1]);
        CHECK(s[2] == i); // reflections before the segment
    }
    CHECK(data["segments"][3][3] == "h");
    REQUIRE(data["elements"].size() == 3);
    CHECK(data["elements"][0]["exact"] == "mirror x = 5/2, y in [0, 3/2] (line 13)");
    CHECK(data["targets"][0]["exact"] == "(3/4, -9/8)");
    CHECK(data["rays"][0]["exact"] == "start (1/2, 1/4), direction (1, 1/2)");
}

TEST_CASE("text in the viewer's data cannot end its script", "[render][viewer]") {
    const std::string hostile = "</script><script>alert(1)</script>";
    const std::string page =
        page_of(orthoray::load_scene(orthoray::test::instance("2d/box-corner-3x5.scene")), 100,
                1000, hostile);
    CHECK(page.find(hostile) == std::string::npos);
    CHECK(occurrences(page, "</script>") == 2);
    const json data = embedded_data(page);
    CHECK(data["caption"].back() == hostile); // read back whole
}

TEST_CASE("the viewer keeps the first segments only, and says how many came", "[render][viewer]") {
    // A periodic path far longer than the cap.
    const Scene scene = orthoray::read_scene("dim 2\nmirror x 0 y 0 50002\nmirror x 49999 y 0 "
                                             "50002\nmirror y 0 x 0 49999\nmirror y 50002 x 0 "
                                             "49999\nray 0 0 1 1\ntarget 1 2\n");
    const json data = embedded_data(page_of(scene, 50, 1000));
    CHECK(data["segments"].size() == 50);
    CHECK(data["segments_received"].get<std::uint64_t>() > 50);
    CHECK(data["points"].size() == 51);
    // Without a cap set, nothing is kept: the page shows the scene alone.
    CHECK(embedded_data(page_of(scene, 0, 1000))["segments"].empty());
}

TEST_CASE("the viewer draws every branch with its targets' statuses", "[render][viewer][optics]") {
    // The ray splits at (2, 1): on through (4, 1), lighting target 1, and
    // back; three states. Target 2 is never reached.
    const Scene scene =
        orthoray::read_scene("dim 2\nsplitter x 2 y 0 4\nray 0 1 1 0\ntarget 4 1\ntarget 2 3\n");
    RenderOptions options;
    options.viewer_segments = 100;
    SceneRenderer renderer(scene, options);
    const orthoray::BranchWalk walk = orthoray::walk_branches(scene, renderer, 1000);
    renderer.mark_targets(orthoray::solve(scene).targets);
    std::ostringstream out;
    renderer.write_html(out, "branches");
    const json data = embedded_data(out.str());
    CHECK(walk.states == 3);
    CHECK(data["mode"] == "branches");
    REQUIRE(data["segments"].size() == 3);
    CHECK(data["points"][data["segments"][0][1].get<std::size_t>()]["exact"] == "(2, 1)");
    CHECK(data["segments"][0][2] == 0);
    CHECK(data["targets"][0]["status"] == "lit");
    CHECK(data["targets"][1]["status"] == "unlit");
}

TEST_CASE("render --html writes the page through the checked output", "[render][viewer][cli]") {
    const TempDir dir;
    const std::string scene = quote(orthoray::test::instance("2d/box-corner-3x5.scene"));
    const auto html = run_cli("render " + scene + " --html " + quote(dir.path("a.html")));
    CHECK(html.status == 0);
    CHECK(html.out == "wrote " + dir.path("a.html") + " (7 segments)\n");
    CHECK(embedded_data(slurp(dir.path("a.html")))["segments"].size() == 7);
    // -o NAME.html is the same page; beside an SVG, both are written.
    CHECK(run_cli("render " + scene + " -o " + quote(dir.path("b.html"))).status == 0);
    CHECK(slurp(dir.path("b.html")) == slurp(dir.path("a.html")));
    const auto both = run_cli("render " + scene + " -o " + quote(dir.path("c.svg")) + " --html " +
                              quote(dir.path("c.html")));
    CHECK(both.status == 0);
    CHECK(slurp(dir.path("c.svg")).starts_with("<?xml"));
    CHECK(slurp(dir.path("c.html")).starts_with("<!DOCTYPE html>"));
    // Two pages at once is a usage error; a failed write exits 5.
    const auto two = run_cli("render " + scene + " -o " + quote(dir.path("d.html")) + " --html " +
                             quote(dir.path("e.html")));
    CHECK(two.status == 2);
    CHECK(two.err.find("expected one HTML page") != std::string::npos);
    CHECK(run_cli("render " + scene + " --html /dev/full").status == 5);
}
