// write_exchange (orthoray/exchange.hpp): the exchange in the two-row form
// other interval-exchange software takes (a permutation given by the labels
// in domain order and in image order, and a length per label), with
// orthoray's own data beside it (what happens at each piece, the first
// state, the lattice scale) for readers who want to map states back.
#include "orthoray/exchange.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <numeric>

namespace orthoray {
namespace {

const char* kind_name(PieceKind kind) {
    switch (kind) {
    case PieceKind::reflect:
        return "reflect";
    case PieceKind::escape:
        return "escape";
    case PieceKind::absorbed:
        break;
    }
    return "absorbed";
}

// Exact integers as JSON numbers when they fit 64 bits, else decimal strings.
nlohmann::json exact(const Integer& x) {
    if (x.fits_slong_p()) return static_cast<long long>(x.get_si());
    return x.get_str();
}

// Labels (piece numbers) in the order of the pieces' images.
std::vector<std::size_t> image_order(const IntervalExchange& e) {
    std::vector<std::size_t> order(e.pieces.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return e.pieces[a].image < e.pieces[b].image; });
    return order;
}

void write_text(const IntervalExchange& e, std::ostream& out) {
    out << "orthoray-exchange 1\n"
        << "# a bijection of [0, size) translating each piece [start, start + length) to\n"
        << "# [image, image + length); top: labels by start, bottom: labels by image\n"
        << "size " << e.size << '\n'
        << "modulus " << e.modulus << '\n';
    if (!e.transversals.empty()) out << "scale " << e.scale[0] << ' ' << e.scale[1] << '\n';
    out << "# label start length image kind hit\n";
    for (std::size_t k = 0; k < e.pieces.size(); ++k) {
        const ExchangePiece& p = e.pieces[k];
        out << "piece " << k << ' ' << p.start << ' ' << p.length << ' ' << p.image << ' '
            << kind_name(p.kind) << ' ' << (p.hit ? 1 : 0) << '\n';
    }
    out << "top";
    for (std::size_t k = 0; k < e.pieces.size(); ++k) out << ' ' << k;
    out << "\nbottom";
    for (std::size_t k : image_order(e)) out << ' ' << k;
    out << "\nend\n";
}

void write_json(const IntervalExchange& e, std::ostream& out) {
    nlohmann::json doc = {{"format", "orthoray-exchange"},
                          {"version", 1},
                          {"size", exact(e.size)},
                          {"modulus", exact(e.modulus)}};
    if (!e.transversals.empty()) doc["scale"] = {exact(e.scale[0]), exact(e.scale[1])};
    doc["pieces"] = nlohmann::json::array();
    doc["top"] = nlohmann::json::array();
    doc["lengths"] = nlohmann::json::array();
    for (std::size_t k = 0; k < e.pieces.size(); ++k) {
        const ExchangePiece& p = e.pieces[k];
        doc["pieces"].push_back({{"label", k},
                                 {"start", exact(p.start)},
                                 {"length", exact(p.length)},
                                 {"image", exact(p.image)},
                                 {"kind", kind_name(p.kind)},
                                 {"hit", p.hit}});
        doc["top"].push_back(k);
        doc["lengths"].push_back(exact(p.length));
    }
    doc["bottom"] = image_order(e);
    out << doc.dump() << '\n';
}

} // namespace

void write_exchange(const IntervalExchange& exchange, std::ostream& out, ExchangeFormat format) {
    if (format == ExchangeFormat::json)
        write_json(exchange, out);
    else
        write_text(exchange, out);
}

} // namespace orthoray
