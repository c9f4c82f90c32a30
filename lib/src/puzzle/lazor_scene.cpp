// A level as a scene (docs/puzzles.md, "The model"): y is flipped so the
// scene's y grows upward, every block becomes four one-sided elements facing
// outward, and every laser starts half a step behind its file position so
// that the block it enters at its start acts on it.
#include "puzzle/block_edges.hpp"

namespace orthoray {

namespace puzzle {

ElementKind element_kind(LazorCell block) {
    switch (block) {
    case LazorCell::opaque:
        return ElementKind::absorber;
    case LazorCell::refract:
        return ElementKind::splitter;
    default:
        return ElementKind::mirror;
    }
}

std::array<Element, 4> block_edges(LazorCell block, int column, int row, int height) {
    // The block covers file x in [2c, 2c + 2], y in [2r, 2r + 2]; in the
    // scene y' = 2h - y, so it covers y' in [2h - 2r - 2, 2h - 2r].
    const Rational left(2 * column), right(2 * column + 2);
    const Rational bottom(2 * height - 2 * row - 2), top(2 * height - 2 * row);
    const ElementKind kind = element_kind(block);
    std::array<Element, 4> edges;
    // Each edge acts only on rays arriving from outside the block: the left
    // edge on rays moving toward +x (side minus), the right edge on rays
    // moving toward -x (plus), the bottom on rays moving up, the top on rays
    // moving down.
    const struct {
        int axis;
        const Rational& at;
        Side side;
    } sides[4] = {{0, left, Side::minus},
                  {0, right, Side::plus},
                  {1, bottom, Side::minus},
                  {1, top, Side::plus}};
    for (int i = 0; i < 4; ++i) {
        Element& e = edges[i];
        e.kind = kind;
        e.axis = sides[i].axis;
        e.side = sides[i].side;
        const int other = 1 - e.axis;
        e.lo[e.axis] = e.hi[e.axis] = sides[i].at;
        e.lo[other] = other == 0 ? left : bottom;
        e.hi[other] = other == 0 ? right : top;
    }
    return edges;
}

Vector scene_point(int x, int y, int height) {
    return Vector{Rational(x), Rational(2 * height - y), Rational(0)};
}

Vector scene_direction(int dx, int dy) {
    return Vector{Rational(dx), Rational(-dy), Rational(0)};
}

int cell_behind(const LazorLevel& level, const LazorLaser& laser) {
    const bool vertical = laser.x % 2 == 0;
    const int column =
        vertical ? (laser.dx > 0 ? laser.x / 2 - 1 : laser.x / 2) : (laser.x - 1) / 2;
    const int row = vertical ? (laser.y - 1) / 2 : (laser.dy > 0 ? laser.y / 2 - 1 : laser.y / 2);
    if (column < 0 || column >= level.width || row < 0 || row >= level.height) return -1;
    return row * level.width + column;
}

bool stops_branches_back(LazorCell behind) {
    return behind == LazorCell::reflect || behind == LazorCell::opaque;
}

Element start_guard(const LazorLaser& laser, int height) {
    // The block ahead can only send a branch back by negating the component
    // across the start edge; the guard lies across that edge's axis, a
    // quarter step into the cell behind, half a step either side of the
    // start along the edge, and acts only on rays moving into that cell.
    const int axis = laser.x % 2 == 0 ? 0 : 1;
    const Vector start = scene_point(laser.x, laser.y, height);
    const Vector v = scene_direction(laser.dx, laser.dy);
    Element guard;
    guard.kind = ElementKind::absorber;
    guard.axis = axis;
    guard.side = sgn(v[axis]) > 0 ? Side::plus : Side::minus; // the way back is -v[axis]
    guard.lo[axis] = guard.hi[axis] = start[axis] - v[axis] / 4;
    const int other = 1 - axis;
    guard.lo[other] = start[other] - Rational(1, 2);
    guard.hi[other] = start[other] + Rational(1, 2);
    return guard;
}

} // namespace puzzle

Scene lazor_scene(const LazorLevel& level) {
    Scene scene;
    scene.dim = 2;
    scene.rays.clear();
    scene.targets.clear();
    for (int row = 0; row < level.height; ++row)
        for (int column = 0; column < level.width; ++column) {
            const LazorCell cell = level.at(column, row);
            if (cell == LazorCell::open || cell == LazorCell::blocked) continue;
            for (Element& e : puzzle::block_edges(cell, column, row, level.height))
                scene.elements.push_back(std::move(e));
        }
    for (const LazorLaser& laser : level.lasers) {
        const int behind = puzzle::cell_behind(level, laser);
        if (behind >= 0 && puzzle::stops_branches_back(level.cells[behind]))
            scene.elements.push_back(puzzle::start_guard(laser, level.height));
        Ray ray;
        ray.line = laser.line;
        ray.direction = puzzle::scene_direction(laser.dx, laser.dy);
        // Half a step back: the open segment from there to the file position
        // crosses no grid line, so the first event is at the file position
        // itself, where the block the laser enters acts (docs/puzzles.md).
        ray.start = puzzle::scene_point(laser.x, laser.y, level.height);
        for (int j = 0; j < 2; ++j) ray.start[j] -= ray.direction[j] / 2;
        scene.rays.push_back(std::move(ray));
    }
    for (const LazorPoint& point : level.points)
        scene.targets.push_back(puzzle::scene_point(point.x, point.y, level.height));
    return scene;
}

} // namespace orthoray
