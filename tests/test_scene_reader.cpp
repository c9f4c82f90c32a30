// The .scene reader on valid files: they become the expected Scene, and
// write_scene round-trips them. Malformed files are
// test_scene_reader_errors.cpp's.
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

using orthoray::Element;
using orthoray::ElementKind;
using orthoray::Integer;
using orthoray::Rational;
using orthoray::read_scene;
using orthoray::Scene;
using orthoray::Vector;

namespace {

Rational q(long num, long den = 1) {
    Rational r(num, den);
    r.canonicalize();
    return r;
}

Vector vec(const Rational& x, const Rational& y, const Rational& z = 0) {
    return Vector{x, y, z};
}

// Every field the reader fills in, element by element.
void require_same_scene(const Scene& a, const Scene& b, bool compare_lines = true) {
    REQUIRE(a.dim == b.dim);
    REQUIRE(a.elements.size() == b.elements.size());
    for (std::size_t i = 0; i < a.elements.size(); ++i) {
        INFO("element " << i);
        const Element &x = a.elements[i], &y = b.elements[i];
        CHECK(x.kind == y.kind);
        CHECK(x.axis == y.axis);
        CHECK(x.lo == y.lo);
        CHECK(x.hi == y.hi);
        CHECK(x.side == y.side);
        if (compare_lines) CHECK(x.line == y.line);
    }
    REQUIRE(a.rays.size() == b.rays.size());
    for (std::size_t i = 0; i < a.rays.size(); ++i) {
        CHECK(a.rays[i].start == b.rays[i].start);
        CHECK(a.rays[i].direction == b.rays[i].direction);
    }
    CHECK(a.targets == b.targets);
}

} // namespace

// ---------------------------------------------------------------- valid files

TEST_CASE("the spec's 2D example parses to the expected fields", "[reader]") {
    const std::string text = "dim 2\n"
                             "mirror x 3 y 0 5          # normal axis x, at x = 3, spanning y\n"
                             "mirror y 5/2 x -1 4       # normal axis y, at y = 5/2\n"
                             "absorber x 10 y 0 10\n"
                             "ray 0 0 3 1               # start, then direction\n"
                             "target 7/2 1\n";
    const Scene s = read_scene(text, "example.scene");
    CHECK(s.dim == 2);
    REQUIRE(s.elements.size() == 3);

    const Element& m0 = s.elements[0];
    CHECK(m0.kind == ElementKind::mirror);
    CHECK(m0.axis == 0);
    CHECK(m0.offset() == 3);
    CHECK(m0.lo == vec(3, 0));
    CHECK(m0.hi == vec(3, 5));
    CHECK(m0.line == 2);

    const Element& m1 = s.elements[1];
    CHECK(m1.kind == ElementKind::mirror);
    CHECK(m1.axis == 1);
    CHECK(m1.offset() == q(5, 2));
    CHECK(m1.lo == vec(-1, q(5, 2)));
    CHECK(m1.hi == vec(4, q(5, 2)));
    CHECK(m1.line == 3);

    const Element& a = s.elements[2];
    CHECK(a.kind == ElementKind::absorber);
    CHECK(a.axis == 0);
    CHECK(a.lo == vec(10, 0));
    CHECK(a.hi == vec(10, 10));
    CHECK(a.line == 4);

    CHECK(s.ray().start == vec(0, 0));
    CHECK(s.ray().direction == vec(3, 1));
    CHECK(s.target() == vec(q(7, 2), 1));
}

TEST_CASE("3D scenes name the other two axes in order", "[reader]") {
    const std::string text = "dim 3\n"
                             "mirror z 0 x 0 4 y 0 4\n"
                             "mirror x -1/2 y 0 1 z -2 2\n"
                             "mirror y 7 x 1 2 z 3 4\n"
                             "absorber z 9 x -9 9 y -9 9\n"
                             "ray 1 2 3 -1 0 1/3\n"
                             "target 1 1 1\n";
    const Scene s = read_scene(text);
    CHECK(s.dim == 3);
    REQUIRE(s.elements.size() == 4);
    CHECK(s.elements[0].axis == 2);
    CHECK(s.elements[0].lo == vec(0, 0, 0));
    CHECK(s.elements[0].hi == vec(4, 4, 0));
    CHECK(s.elements[1].axis == 0);
    CHECK(s.elements[1].lo == vec(q(-1, 2), 0, -2));
    CHECK(s.elements[1].hi == vec(q(-1, 2), 1, 2));
    CHECK(s.elements[2].axis == 1);
    CHECK(s.elements[2].lo == vec(1, 7, 3));
    CHECK(s.elements[2].hi == vec(2, 7, 4));
    CHECK(s.elements[3].kind == ElementKind::absorber);
    CHECK(s.elements[3].lo == vec(-9, -9, 9));
    CHECK(s.elements[3].hi == vec(9, 9, 9));
    CHECK(s.ray().start == vec(1, 2, 3));
    CHECK(s.ray().direction == vec(-1, 0, q(1, 3)));
    CHECK(s.target() == vec(1, 1, 1));
}

TEST_CASE("a 2D scene leaves the third slot at zero", "[reader]") {
    const Scene s = read_scene("dim 2\nmirror y 1 x 2 3\nray 5 6 7 8\ntarget 9 10\n");
    CHECK(s.elements[0].lo[2] == 0);
    CHECK(s.elements[0].hi[2] == 0);
    CHECK(s.ray().start[2] == 0);
    CHECK(s.ray().direction[2] == 0);
    CHECK(s.target()[2] == 0);
}

TEST_CASE("zero elements are allowed, in any order after dim", "[reader]") {
    const Scene a = read_scene("dim 2\nray 0 0 1 0\ntarget 5 0\n");
    CHECK(a.elements.empty());
    CHECK(a.ray().direction == vec(1, 0));
    CHECK(a.target() == vec(5, 0));

    // target before ray, elements after both.
    const Scene b = read_scene("dim 3\ntarget 1 2 3\nray 0 0 0 0 0 -1\nabsorber y 1 x 0 1 z 0 1\n");
    CHECK(b.target() == vec(1, 2, 3));
    CHECK(b.ray().direction == vec(0, 0, -1));
    REQUIRE(b.elements.size() == 1);
    CHECK(b.elements[0].kind == ElementKind::absorber);
    CHECK(b.elements[0].line == 4);
}

TEST_CASE("a UTF-8 byte order mark before the first line is layout only", "[reader]") {
    const std::string plain = "dim 2\nmirror x 3 y 0 5\nray 0 0 1 0\ntarget 7/2 1\n";
    const Scene s = read_scene("\xEF\xBB\xBF" + plain);
    require_same_scene(s, read_scene(plain), false);
    CHECK(s.elements[0].line == 2);
    // Also before a first line that is a comment, or the whole file.
    require_same_scene(read_scene("\xEF\xBB\xBF# made on Windows\r\n" + plain), s, false);
    CHECK_THROWS_WITH(read_scene("\xEF\xBB\xBF", "f.scene"),
                      Catch::Contains("f.scene:1:4: found end of file"));
}

TEST_CASE("comments, blank lines, CRLF and tabs are layout only", "[reader]") {
    const std::string plain = "dim 2\n"
                              "mirror x 3 y 0 5\n"
                              "absorber y -1 x 0 3\n"
                              "ray 1/2 0.25 3 1\n"
                              "target 7/2 1\n";
    const Scene expected = read_scene(plain);

    const std::string decorated =
        "# a comment before dim\r\n"
        "\r\n"
        "   \t  \r\n"
        "\tdim\t2\t# trailing comment\r\n"
        "# mirror x 0 y 0 1   (commented out)\r\n"
        "mirror  x\t3 y 0\t\t5#no space before the hash\r\n"
        "\r\n"
        "absorber y -1 x 0 3 # caf\xC3\xA9: UTF-8 is fine in a comment\r\n"
        "ray\t1/2  0.25  3  1   \r\n"
        "   target 7/2 1\r\n"
        "# the end\r\n";
    const Scene s = read_scene(decorated);
    require_same_scene(s, expected, false);
    CHECK(s.elements[0].line == 6);
    CHECK(s.elements[1].line == 8);

    // No newline at the end of the file, and a lone CR before end of file.
    require_same_scene(read_scene(plain.substr(0, plain.size() - 1)), expected);
    require_same_scene(read_scene(plain.substr(0, plain.size() - 1) + "\r"), expected);
}

TEST_CASE("decimals, signs and fractions in every position", "[reader]") {
    const Scene s = read_scene("dim 2\n"
                               "mirror x -0.5 y -2. .75\n"
                               "mirror y +6/4 x -1/3 1.0\n"
                               "ray -.25 +0 0.0 -12.5\n"
                               "target 10/4 -0.125\n");
    CHECK(s.elements[0].lo == vec(q(-1, 2), -2));
    CHECK(s.elements[0].hi == vec(q(-1, 2), q(3, 4)));
    CHECK(s.elements[1].lo == vec(q(-1, 3), q(3, 2)));
    CHECK(s.elements[1].hi == vec(1, q(3, 2)));
    CHECK(s.ray().start == vec(q(-1, 4), 0));
    CHECK(s.ray().direction == vec(0, q(-25, 2)));
    CHECK(s.target() == vec(q(5, 2), q(-1, 8)));
}

TEST_CASE("numbers of any size are exact", "[reader]") {
    const std::string big = std::string("1").append(199, '7');           // 200 digits
    const std::string big_den = std::string("3").append(198, '1') + "9"; // 200 digits
    const std::string tiny = std::string("0.").append(150, '0') + "1";   // 10^-151
    const std::string text = "dim 2\n"
                             "mirror x " +
                             big + "/" + big_den + " y -" + big + " " + big +
                             "\n"
                             "ray " +
                             tiny + " 0 " + big + " 1\n" + "target " + big + " " + tiny + "\n";
    const Scene s = read_scene(text);
    Rational offset{Integer(big), Integer(big_den)};
    offset.canonicalize();
    const Rational b{Integer(big)};
    Integer ten_151;
    mpz_ui_pow_ui(ten_151.get_mpz_t(), 10, 151);
    const Rational t(Integer(1), ten_151);
    CHECK(s.elements[0].offset() == offset);
    CHECK(s.elements[0].lo[1] == -b);
    CHECK(s.elements[0].hi[1] == b);
    CHECK(s.ray().start == vec(t, 0));
    CHECK(s.ray().direction == vec(b, 1));
    CHECK(s.target() == vec(b, t));
    // And they survive a trip through write_scene.
    require_same_scene(read_scene(orthoray::write_scene(s)), s);
}

// ------------------------------------------------------------ write_scene

TEST_CASE("write_scene round-trips hand-made scenes", "[reader]") {
    Scene a;
    a.dim = 2;
    a.add_mirror(0, q(3), {{q(0), q(5)}});
    a.add_mirror(1, q(-7, 2), {{q(-1, 3), q(4)}});
    a.add_absorber(0, q(10), {{q(0), q(10)}});
    a.ray().start = vec(0, q(1, 8));
    a.ray().direction = vec(3, -1);
    a.target() = vec(q(7, 2), 1);

    Scene b;
    b.dim = 3;
    b.add_mirror(2, q(0), {{q(0), q(4)}, {q(0), q(4)}});
    b.add_absorber(1, q(-5, 3), {{q(-1), q(1)}, {q(1, 2), q(2)}});
    b.add_mirror(0, q(9), {{q(-9), q(9)}, {q(-9), q(9)}});
    b.ray().start = vec(1, 2, 3);
    b.ray().direction = vec(0, 0, q(-1, 7));
    b.target() = vec(q(1, 2), q(1, 3), q(1, 4));

    Scene empty; // no elements at all
    empty.dim = 3;
    empty.ray().start = vec(0, 0, 0);
    empty.ray().direction = vec(1, 1, 1);
    empty.target() = vec(5, 5, 5);

    for (const Scene* s : {&a, &b, &empty}) {
        const std::string text = orthoray::write_scene(*s);
        INFO(text);
        const Scene back = read_scene(text);
        require_same_scene(back, *s, false);
        // Writing again gives the same text: the format is canonical.
        CHECK(orthoray::write_scene(back) == text);
    }
}

TEST_CASE("write_scene round-trips seeded random scenes", "[reader]") {
    std::mt19937_64 rng(20240611);
    auto number = [&] {
        std::int64_t num = static_cast<std::int64_t>(rng() % 2001) - 1000;
        std::int64_t den = static_cast<std::int64_t>(rng() % 12) + 1;
        Rational r(Integer(std::to_string(num)), Integer(std::to_string(den)));
        r.canonicalize();
        if (rng() % 10 == 0) r *= Rational(Integer(std::string("1").append(60, '0'))); // huge
        return r;
    };
    for (int round = 0; round < 50; ++round) {
        Scene s;
        s.dim = 2 + static_cast<int>(rng() % 2);
        int n = static_cast<int>(rng() % 8);
        for (int i = 0; i < n; ++i) {
            int axis = static_cast<int>(rng() % static_cast<unsigned>(s.dim));
            std::vector<std::pair<Rational, Rational>> extent;
            for (int j = 0; j < s.dim - 1; ++j) {
                Rational lo = number();
                extent.emplace_back(lo, lo + abs(number()) + q(1, 3));
            }
            s.add(rng() % 3 == 0 ? ElementKind::absorber : ElementKind::mirror, axis, number(),
                  extent);
        }
        for (int j = 0; j < s.dim; ++j) {
            s.ray().start[j] = number();
            s.ray().direction[j] = number();
            s.target()[j] = number();
        }
        if (s.ray().direction[0] == 0) s.ray().direction[0] = 1;
        const std::string text = orthoray::write_scene(s);
        INFO("round " << round << "\n" << text);
        require_same_scene(read_scene(text), s, false);
    }
}
