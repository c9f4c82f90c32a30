#include "orthoray/pieces.hpp"

#include "induction/octagonal_induction.hpp"
#include "lattice/lattice_scene.hpp"
#include "shoot/piece_table.hpp"

namespace orthoray {

PieceTableSummary write_piece_tables(const Scene& scene, std::ostream& out) {
    PieceTableSummary summary;
    if (scene.has_diagonal()) {
        // Octagonal: the first-return map on the eight-sheeted cover
        // (docs/induction.md, section 6), on the orbit's class.
        if (const auto pieces = induction::write_octagonal_pieces(scene, out)) {
            summary.available = true;
            summary.mirrors = scene.elements.size();
            summary.pieces = *pieces;
        }
        return summary;
    }
    const lattice::LatticeScene ls = lattice::make_lattice(scene);
    if (scene.dim != 2 || ls.dim != 2) return summary;
    // GMP integers: a dump is for reading, not for speed.
    const shoot::UniformGrid<Integer, 2> grid(ls);
    const auto table = shoot::PieceTable<Integer>::build(ls, grid, ~std::size_t{0});
    summary.available = true;
    summary.mirrors = ls.elements.size();
    summary.pieces = table->size();
    out << "# piece tables: " << summary.pieces << " pieces on " << summary.mirrors
        << " elements (absorbers have none)\n"
        << "# lattice scale: x * " << ls.scale[0] << ", y * " << ls.scale[1]
        << "; the ray moves diagonally; a position u is y on a vertical mirror, x on a "
           "horizontal one\n"
        << "# element k is the k-th element of the scene the ray can meet\n";
    for (std::size_t k = 0; k < ls.elements.size(); ++k) {
        const lattice::LatticeElement& e = ls.elements[k];
        const int t = 1 - e.axis;
        out << "# element " << k << ": " << (e.absorber ? "absorber " : "mirror ")
            << axis_name(e.axis) << " = " << e.lo[e.axis] << ", " << axis_name(t) << " in ["
            << e.lo[t] << ", " << e.hi[t] << "]\n";
    }
    table->dump(out);
    return summary;
}

} // namespace orthoray
