// Streams the certificate of docs/certificates.md: points as they come, the
// verdict at the end. Only the first reflection state and the last direction
// are kept, so memory does not grow with the path. The JSON Lines variant
// holds the same statements: the header, one line a point, one verdict line
// and an end line; numbers are strings, so nothing is rounded.
#include "orthoray/certificate.hpp"

#include "certify/illumination_certificate_section.hpp"
#include "orthoray/exchange.hpp"

#include <cstring>
#include <functional>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace orthoray {

// The induction part of a certificate: one statement a line, in text or as
// a JSON object {"keyword": [operands]}.
class CertificateWriter::InductionSection : public InductionObserver {
public:
    InductionSection(CertificateWriter& writer) : writer_(writer) {}

    // The listing of the exchange goes to memory first and out only when
    // whole: a stop during it (10^6-digit numbers take seconds to write in
    // decimal) leaves the certificate a path prefix, which verify reads as a
    // partial path certificate, where an exchange cut short would be invalid.
    bool begin(const IntervalExchange& exchange, const std::function<bool()>& stopped) override {
        std::ostringstream listing;
        sink_ = &listing;
        stopped_ = &stopped;
        asked_at_ = 0;
        cut_ = false;
        const bool octagonal = !exchange.lifted.empty();
        try {
            if (octagonal)
                octagonal_exchange(exchange);
            else
                axis_exchange(exchange);
        } catch (...) { // the sink must not outlive `listing`
            sink_ = &writer_.out_;
            stopped_ = nullptr;
            throw;
        }
        sink_ = &writer_.out_;
        stopped_ = nullptr;
        if (cut_) return false;
        writer_.induced_ = true;
        statement("method", {octagonal ? "octagonal-induction" : "induction"}, false);
        std::ostream& out = writer_.out_;
        const bool json = writer_.format_ == CertificateFormat::jsonl;
        out << (json ? "{\"direction\": " : "direction");
        writer_.write_vector(writer_.first_reflection_direction_);
        out << (json ? "}\n" : "\n");
        out << listing.view();
        return true;
    }
    void walk_search(const Integer& from, const std::optional<Integer>& only) override {
        if (only)
            statement("walk-search", {from.get_str(), "only", only->get_str()});
        else
            statement("walk-search", {from.get_str(), "all"});
    }
    void twin_search() override {
        writer_.out_ << (writer_.format_ == CertificateFormat::text ? "twin-search\n"
                                                                    : "{\"twin-search\": true}\n");
    }
    void top(std::size_t d, std::size_t r) override { step("top", d, std::to_string(r)); }
    void bottom(std::size_t r, std::size_t d) override { step("bottom", r, std::to_string(d)); }
    void equal(std::size_t r, std::size_t d) override { step("equal", r, std::to_string(d)); }
    void invariant(std::size_t d) override { statement("step", {"invariant", std::to_string(d)}); }
    void top_cycle(std::size_t d, const Integer& rounds) override {
        step("top-cycle", d, rounds.get_str());
    }
    void bottom_cycle(std::size_t r, const Integer& rounds) override {
        step("bottom-cycle", r, rounds.get_str());
    }

private:
    void axis_exchange(const IntervalExchange& exchange) {
        statement("scale", {exchange.scale[0].get_str(), exchange.scale[1].get_str()});
        statement("modulus", {exchange.modulus.get_str()}, false);
        for (const Transversal& t : exchange.transversals) {
            if (cut_) return;
            statement("transversal",
                      {std::to_string(t.axis), t.offset.get_str(), t.lo.get_str(), t.hi.get_str(),
                       (t.negative & 1u) ? "-1" : "1", (t.negative & 2u) ? "-1" : "1"});
        }
        statement("first",
                  {std::to_string(exchange.first_transversal), exchange.first_index.get_str()});
        write_pieces(exchange);
    }
    // docs/induction-certificates.md, "Octagonal scenes": one scale, the
    // lifted transversals as lattice points, x and its twin.
    void octagonal_exchange(const IntervalExchange& exchange) {
        statement("scale", {exchange.scale[0].get_str()}, false);
        for (const LiftedTransversal& t : exchange.lifted) {
            if (cut_) return;
            statement("lifted",
                      {t.x0.get_str(), t.y0.get_str(), t.step_x.get_str(), t.step_y.get_str(),
                       t.count.get_str(), t.dx.get_str(), t.dy.get_str()});
        }
        statement("first",
                  {std::to_string(exchange.first_transversal), exchange.first_index.get_str()});
        if (exchange.twin_transversal)
            statement("twin",
                      {std::to_string(*exchange.twin_transversal), exchange.twin_index.get_str()});
        write_pieces(exchange);
    }
    // A cut state's piece (a dead end of one state in the exchange) says
    // `cut IMAGE JOIN`: the ray steps to JOIN.
    void write_pieces(const IntervalExchange& exchange) {
        auto cut = exchange.cuts.begin();
        for (const ExchangePiece& p : exchange.pieces) {
            if (cut_) return;
            while (cut != exchange.cuts.end() && cut->first < p.start) ++cut;
            const bool is_cut = cut != exchange.cuts.end() && cut->first == p.start;
            const char* kind = is_cut                         ? "cut"
                               : p.kind == PieceKind::reflect ? "reflect"
                               : p.kind == PieceKind::escape  ? "escape"
                                                              : "absorbed";
            std::vector<std::string> operands{p.start.get_str(), p.length.get_str(), kind,
                                              p.image.get_str()};
            if (is_cut) operands.push_back(cut->second.get_str());
            if (p.hit) operands.push_back("hit");
            statement("piece", operands);
        }
    }
    void step(const char* kind, std::size_t a, const std::string& b) {
        statement("step", {kind, std::to_string(a), b});
    }
    // `keyword operands...`; in JSON a single operand is a scalar unless
    // `array` asks for a list.
    void statement(const char* keyword, std::initializer_list<std::string> operands,
                   bool array = true) {
        statement(keyword, std::vector<std::string>(operands), array);
    }
    void statement(const char* keyword, const std::vector<std::string>& operands,
                   bool array = true) {
        std::ostream& out = *sink_;
        if (cut_) return;
        if (stopped_) {
            // During the listing: asked every 64 KiB written, a millisecond
            // or so, and at every statement of 10^5-digit numbers.
            const std::streamoff at = out.tellp();
            if (at - asked_at_ >= (std::streamoff{1} << 16)) {
                asked_at_ = at;
                if ((*stopped_)()) {
                    cut_ = true;
                    return;
                }
            }
        }
        if (writer_.format_ == CertificateFormat::text) {
            out << keyword;
            for (const std::string& x : operands) out << ' ' << x;
            out << '\n';
            return;
        }
        out << "{\"" << keyword << "\": " << (array ? "[" : "");
        bool first = true;
        for (const std::string& x : operands) {
            out << (first ? "\"" : ", \"") << x << '"';
            first = false;
        }
        out << (array ? "]}\n" : "}\n");
    }

    CertificateWriter& writer_;
    std::ostream* sink_ = &writer_.out_;             // where statements go
    const std::function<bool()>* stopped_ = nullptr; // set during begin()
    std::streamoff asked_at_ = 0;                    // the sink's size when last asked
    bool cut_ = false;                               // begin() was stopped
};

CertificateWriter::CertificateWriter(std::ostream& out, const Scene& scene,
                                     CertificateFormat format)
    : out_(out), scene_(scene), format_(format) {
    if (format_ == CertificateFormat::jsonl)
        out_ << "{\"orthoray-certificate\": 1, \"dim\": " << scene_.dim << "}\n";
    else
        out_ << "orthoray-certificate 1\ndim " << scene_.dim << '\n';
}

// Text: " 1 7/2"; JSON: ["1", "7/2"].
void CertificateWriter::write_vector(const Vector& x) {
    const bool json = format_ == CertificateFormat::jsonl;
    if (json) out_ << '[';
    for (int j = 0; j < scene_.dim; ++j) {
        out_ << (json ? (j ? ", \"" : "\"") : " ");
        write_number(x[j]);
        if (json) out_ << '"';
    }
    if (json) out_ << ']';
}

// As to_string writes it, through a buffer kept across calls: a path writes
// dim numbers a reflection, and a string each would be an allocation each.
void CertificateWriter::write_number(const Rational& x) {
    const mpq_srcptr q = x.get_mpq_t();
    // mpq_get_str's bound: both parts' digits, a sign, the '/' and the NUL.
    const std::size_t bound =
        mpz_sizeinbase(mpq_numref(q), 10) + mpz_sizeinbase(mpq_denref(q), 10) + 3;
    if (digits_.size() < bound) digits_.resize(bound);
    mpq_get_str(digits_.data(), 10, q);
    out_.write(digits_.data(), static_cast<std::streamsize>(std::strlen(digits_.data())));
}

CertificateWriter::~CertificateWriter() = default;

void CertificateWriter::attach(SolveOptions& options) {
    if (options.min_intensity) {
        illumination_ = std::make_unique<IlluminationSection>(*this, options.min_intensity);
        options.intensity_observer = illumination_.get();
        return;
    }
    if (!scene_.single_trajectory()) {
        if (!illumination_)
            illumination_ = std::make_unique<IlluminationSection>(*this, std::nullopt);
        options.illumination_observer = illumination_.get();
        return;
    }
    if (!induction_) induction_ = std::make_unique<InductionSection>(*this);
    options.path = this;
    options.induction_observer = induction_.get();
}

void CertificateWriter::visit(const Vector& point, const Vector& direction) {
    out_ << (format_ == CertificateFormat::jsonl ? "{\"point\": " : "point");
    write_vector(point);
    out_ << (format_ == CertificateFormat::jsonl ? "}\n" : "\n");
    if (visits_ == 1) {
        first_reflection_point_ = point;
        first_reflection_direction_ = direction;
    }
    last_direction_ = direction;
    ++visits_;
}

void CertificateWriter::cycle_start(const Vector& point, const Vector& direction) {
    cycle_start_.emplace(point, direction);
}

void CertificateWriter::finish(const Answer& answer) {
    if (illumination_ || !scene_.single_trajectory()) {
        if (!illumination_)
            illumination_ = std::make_unique<IlluminationSection>(*this, std::nullopt);
        illumination_->finish(answer);
        return;
    }
    const bool json = format_ == CertificateFormat::jsonl;
    // A statement: `name operands` on its own line, or `"name": operands`
    // inside the one verdict object.
    auto statement = [&](const char* name) -> std::ostream& {
        return json ? out_ << ", \"" << name << "\": " : out_ << name;
    };
    auto end_statement = [&] {
        if (!json) out_ << '\n';
    };
    const std::string reflections = answer.reflections.get_str();
    if (json)
        out_ << "{\"answer\": \"" << answer_word(answer) << "\", \"reason\": \""
             << to_string(answer.reason) << "\", \"reflections\": \"" << reflections << '"';
    else
        out_ << "answer " << answer_word(answer) << "\nreason " << to_string(answer.reason)
             << "\nreflections " << reflections << '\n';
    if (induced_) {
        // The exchange already says where x is: the verdict is the answer,
        // plus the period of a cycle (reflections minus the tail, which only
        // a walk's cycle has).
        if (answer.reason == Reason::cycle) {
            const std::string period = answer.period().get_str();
            statement("period") << (json ? "\"" + period + "\"" : " " + period);
            end_statement();
        }
        if (answer.reason == Reason::limit) { // stopped while the steps were written
            statement("partial") << (json ? "true" : "");
            end_statement();
        }
        out_ << (json ? "}\n{\"end\": true}\n" : "end\n");
        out_.flush();
        return;
    }
    switch (answer.reason) {
    case Reason::hit:
        statement("target");
        write_vector(scene_.target());
        end_statement();
        break;
    case Reason::escape:
        statement("direction");
        write_vector(last_direction_);
        end_statement();
        break;
    case Reason::cycle: {
        // The cycle's first state s_(T+1) and its period; with one-sided
        // elements or diagonals also the tail T (docs/certificates.md),
        // which other certificates leave out (it is 0).
        const Vector& point = cycle_start_ ? cycle_start_->first : first_reflection_point_;
        const Vector& direction = cycle_start_ ? cycle_start_->second : first_reflection_direction_;
        const std::string period = answer.period().get_str(), tail = answer.tail.get_str();
        const bool with_tail = scene_.has_one_sided() || scene_.has_diagonal() || answer.tail != 0;
        if (json) {
            out_ << ", \"state\": {\"point\": ";
            write_vector(point);
            out_ << ", \"direction\": ";
            write_vector(direction);
            out_ << "}, \"period\": \"" << period << '"';
            if (with_tail) out_ << ", \"tail\": \"" << tail << '"';
        } else {
            out_ << "state";
            write_vector(point);
            write_vector(direction);
            out_ << "\nperiod " << period << '\n';
            if (with_tail) out_ << "tail " << tail << '\n';
        }
        break;
    }
    case Reason::limit:
        statement("partial") << (json ? "true" : "");
        end_statement();
        break;
    case Reason::absorbed:
        break;
    case Reason::lit: // the illumination section wrote these above
    case Reason::unlit:
        break;
    }
    out_ << (json ? "}\n{\"end\": true}\n" : "end\n");
    out_.flush();
}

} // namespace orthoray
