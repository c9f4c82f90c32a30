// write_piece_tables (orthoray/pieces.hpp): the tables as text for reading,
// or as JSON for programs, both from PieceTable::for_each_row.
#include "orthoray/pieces.hpp"

#include "induction/octagonal_induction.hpp"
#include "lattice/lattice_scene.hpp"
#include "shoot/piece_table.hpp"

#include <nlohmann/json.hpp>

namespace orthoray {
namespace {

using Table = shoot::PieceTable<Integer>;

const char* direction_name(unsigned negative) {
    static const char* const names[] = {"+x+y", "-x+y", "+x-y", "-x-y"};
    return names[negative];
}

std::string flip_name(unsigned flip) {
    return std::string((flip & 1u) ? "x" : "") + ((flip & 2u) ? "y" : "");
}

void write_text(const lattice::LatticeScene& ls, const Table& table, std::ostream& out) {
    out << "# piece tables: " << table.size() << " pieces on " << ls.elements.size()
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
    table.for_each_row([&](const Table::Row& row) {
        out << "element " << row.element << ' ' << direction_name(row.negative) << " from "
            << row.from << ": ";
        if (row.kind == Table::Kind::escape) {
            out << "escape\n";
            return;
        }
        out << (row.kind == Table::Kind::absorb ? "absorbed"
                                                : "element " + std::to_string(row.next))
            << " at t = " << row.t0;
        if (row.slope != 0) out << (row.slope > 0 ? " + (u - from)" : " - (u - from)");
        if (row.kind == Table::Kind::reflect) out << ", flip " << flip_name(row.flip);
        out << '\n';
    });
}

// Exact integers as JSON numbers when they fit 64 bits, as decimal strings
// otherwise, as orthoray's other JSON outputs write them.
nlohmann::json exact(const Integer& x) {
    if (x.fits_slong_p()) return static_cast<long long>(x.get_si());
    return x.get_str();
}

void write_json(const lattice::LatticeScene& ls, const Table& table, std::ostream& out) {
    nlohmann::json doc;
    doc["scale"] = {exact(ls.scale[0]), exact(ls.scale[1])};
    doc["elements"] = nlohmann::json::array();
    for (const lattice::LatticeElement& e : ls.elements) {
        const int t = 1 - e.axis;
        doc["elements"].push_back({{"kind", e.absorber ? "absorber" : "mirror"},
                                   {"axis", std::string(1, axis_name(e.axis))},
                                   {"offset", exact(e.lo[e.axis])},
                                   {"lo", exact(e.lo[t])},
                                   {"hi", exact(e.hi[t])},
                                   {"scene_element", e.source}});
    }
    doc["pieces"] = nlohmann::json::array();
    table.for_each_row([&](const Table::Row& row) {
        nlohmann::json piece = {{"element", row.element},
                                {"direction", direction_name(row.negative)},
                                {"from", exact(row.from)}};
        switch (row.kind) {
        case Table::Kind::escape:
            piece["kind"] = "escape";
            break;
        case Table::Kind::absorb:
            piece["kind"] = "absorbed";
            break;
        case Table::Kind::reflect:
            piece["kind"] = "reflect";
            piece["next"] = row.next;
            piece["flip"] = flip_name(row.flip);
            break;
        }
        if (row.kind != Table::Kind::escape) {
            piece["t0"] = exact(row.t0);
            piece["slope"] = row.slope;
        }
        doc["pieces"].push_back(std::move(piece));
    });
    out << doc.dump() << '\n';
}

} // namespace

PieceTableSummary write_piece_tables(const Scene& scene, std::ostream& out,
                                     PieceTableFormat format) {
    PieceTableSummary summary;
    if (scene.has_diagonal()) {
        if (format == PieceTableFormat::json) return summary;
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
    const auto table = Table::build(grid, ~std::size_t{0});
    summary.available = true;
    summary.mirrors = ls.elements.size();
    summary.pieces = table->size();
    if (format == PieceTableFormat::json)
        write_json(ls, *table, out);
    else
        write_text(ls, *table, out);
    return summary;
}

} // namespace orthoray
