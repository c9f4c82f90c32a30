// Writes a realistic model in the text format of docs/realistic-scenes.md,
// so that a model derived from a scene can be read back, decided again and
// its certificate verified: read_realistic(write_realistic(m)) holds the
// same objects, legs, triples and transfers.
#include "orthoray/realistic.hpp"

#include <sstream>

namespace orthoray {

std::string write_realistic(const RealisticModel& model) {
    std::ostringstream out;
    const auto& name = model.objects;
    out << "realistic 1\nobject";
    for (const std::string& object : name) out << ' ' << object;
    out << "\nsource " << name[model.source] << ' ' << model.emitted.get_str() << "\nreceiver "
        << name[model.receiver] << "\neps " << model.eps.get_str() << '\n';
    for (const std::size_t leg : model.first_legs)
        out << "pair " << name[model.source] << ' ' << name[leg] << '\n';
    for (const Triple& t : model.triples) {
        out << "triple " << name[t.from] << ' ' << name[t.via] << ' ' << name[t.to];
        if (t.transfer.kind == Transfer::Kind::scale) {
            Rational share(t.transfer.p, t.transfer.q);
            share.canonicalize();
            out << " scale " << to_string(share);
        } else {
            out << " table";
            for (std::size_t k = 0; k < t.transfer.thresholds.size(); ++k)
                out << ' ' << t.transfer.thresholds[k].get_str() << ':'
                    << t.transfer.values[k].get_str();
        }
        out << '\n';
    }
    return out.str();
}

} // namespace orthoray
