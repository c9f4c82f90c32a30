// Certificates of the realistic-scene dynamic program
// (docs/realistic-scenes.md). The writer prints what the program found; the
// checker re-evaluates the path and the closure of the bounds from the model
// alone, with its own reading of the transfers (a plain scan of the table),
// and shares nothing with the dynamic program or Boost.Graph.
#include "io/quoted_token.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/realistic.hpp"

#include <algorithm>
#include <map>
#include <ostream>
#include <utility>

namespace orthoray {

void write_realistic_certificate(std::ostream& out, const RealisticModel& model,
                                 const RealisticAnswer& answer) {
    out << "orthoray-realistic-certificate 1\n"
        << "answer " << (answer.yes ? "yes" : "no") << '\n'
        << "best " << (answer.best < 0 ? std::string("none") : answer.best.get_str()) << '\n';
    if (!answer.path.empty()) {
        out << "path";
        for (const std::size_t object : answer.path) out << ' ' << model.objects[object];
        out << "\narrivals";
        for (const Integer& i : answer.intensities) out << ' ' << i.get_str();
        out << '\n';
    }
    for (const RealisticAnswer::PairBound& b : answer.bounds)
        out << "bound " << model.objects[b.previous] << ' ' << model.objects[b.current] << ' '
            << b.intensity.get_str() << '\n';
    out << "end\n";
}

namespace {

// The checker's own reading of a transfer.
Integer passed(const Transfer& t, const Integer& in) {
    if (t.kind == Transfer::Kind::scale) {
        Integer product = in * t.p, out;
        mpz_fdiv_q(out.get_mpz_t(), product.get_mpz_t(), t.q.get_mpz_t());
        return out;
    }
    Integer out = 0;
    for (std::size_t k = 0; k < t.thresholds.size(); ++k)
        if (t.thresholds[k] <= in) out = t.values[k];
    return out;
}

class CertificateCheck {
public:
    CertificateCheck(const RealisticModel& model, std::istream& in, const std::string& name)
        : model_(model), in_(in), name_(name) {
        for (std::size_t k = 0; k < model.objects.size(); ++k) names_[model.objects[k]] = k;
        for (const Triple& t : model.triples) triples_[{t.from, t.via, t.to}] = &t.transfer;
    }

    RealisticVerdict run() {
        read();
        const std::string problem = check();
        if (!problem.empty()) return {false, "invalid: " + problem};
        return {true, "valid: " + std::string(yes_ ? "yes" : "no") + ", best " +
                          (best_ ? best_->get_str() : std::string("none"))};
    }

private:
    const RealisticModel& model_;
    std::istream& in_;
    std::string name_;
    std::map<std::string, std::size_t> names_;
    std::map<std::tuple<std::size_t, std::size_t, std::size_t>, const Transfer*> triples_;
    bool yes_ = false, ended_ = false;
    std::optional<Integer> best_;
    std::vector<std::size_t> path_;
    std::vector<Integer> arrivals_;
    std::map<std::pair<std::size_t, std::size_t>, Integer> bounds_;
    int line_ = 0;
    std::vector<int> columns_; // of the current line's words

    [[noreturn]] void fail(int column, const std::string& found, const std::string& expected) {
        throw InputError(name_, line_, column,
                         "found " + io::quoted_token(found) + ", expected " + expected);
    }

    void read() {
        std::string text;
        // Each statement but `bound` once: a repeated one would say two
        // things, and the last would win unseen.
        bool header = false, answer = false, best = false, path = false, arrivals = false;
        auto once = [&](bool& seen, const std::string& line, const std::string& keyword) {
            if (seen) fail(1, line, "one '" + keyword + "' line");
            seen = true;
        };
        while (std::getline(in_, text)) {
            ++line_;
            // Each word with its column (1-based, a byte a column, as the
            // other readers count), so a bad operand is reported where it is.
            std::vector<std::string> w;
            columns_.clear();
            for (std::size_t at = text.find_first_not_of(" \t\r\v\f"); at != std::string::npos;) {
                const std::size_t end = std::min(text.find_first_of(" \t\r\v\f", at), text.size());
                w.push_back(text.substr(at, end - at));
                columns_.push_back(static_cast<int>(at) + 1);
                at = text.find_first_not_of(" \t\r\v\f", end);
            }
            if (w.empty()) continue;
            if (ended_) fail(1, w[0], "nothing after 'end'");
            if (!header) {
                if (w.size() != 2 || w[0] != "orthoray-realistic-certificate" || w[1] != "1")
                    fail(1, text, "'orthoray-realistic-certificate 1'");
                header = true;
            } else if (w[0] == "answer" && w.size() == 2 && (w[1] == "yes" || w[1] == "no")) {
                once(answer, text, "answer");
                yes_ = w[1] == "yes";
            } else if (w[0] == "best" && w.size() == 2) {
                once(best, text, "best");
                if (w[1] != "none") best_ = natural(w, 1);
            } else if (w[0] == "path" && w.size() >= 3) {
                once(path, text, "path");
                for (std::size_t k = 1; k < w.size(); ++k) path_.push_back(object(w, k));
            } else if (w[0] == "arrivals" && w.size() >= 2) {
                once(arrivals, text, "arrivals");
                for (std::size_t k = 1; k < w.size(); ++k) arrivals_.push_back(natural(w, k));
            } else if (w[0] == "bound" && w.size() == 4) {
                const auto key = std::pair{object(w, 1), object(w, 2)};
                if (!bounds_.emplace(key, natural(w, 3)).second) fail(1, text, "one bound a pair");
            } else if (w[0] == "end" && w.size() == 1) {
                ended_ = true;
            } else {
                fail(1, text, "answer, best, path, arrivals, bound or end");
            }
        }
        if (!header || !answer || !best || !ended_)
            throw InputError(name_, line_ + 1, 1,
                             "found the end of the file, expected a complete certificate (header, "
                             "answer, best, bounds, end)");
    }

    // Word k of the current line, read as an object or a natural number.
    std::size_t object(const std::vector<std::string>& w, std::size_t k) {
        const auto it = names_.find(w[k]);
        if (it == names_.end()) fail(columns_[k], w[k], "an object of the model");
        return it->second;
    }

    Integer natural(const std::vector<std::string>& w, std::size_t k) {
        if (w[k].find_first_not_of("0123456789") != std::string::npos)
            fail(columns_[k], w[k], "a natural number");
        return Integer(w[k]);
    }

    // The first failing claim, or "" when all hold.
    std::string check() const {
        if (yes_ != (best_ && *best_ > model_.eps))
            return "the answer does not follow from best and eps";
        if (best_) {
            if (const std::string p = check_path(); !p.empty()) return p;
        } else if (!path_.empty()) {
            return "a path is given, but best says none arrives";
        }
        return check_bounds();
    }

    // The path is a ray path of the model and delivers exactly `best`.
    std::string check_path() const {
        if (path_.size() < 2 || path_.front() != model_.source || path_.back() != model_.receiver)
            return "the path does not lead from the source to the receiver";
        if (arrivals_.size() != path_.size() - 1) return "one arrival an object after the source";
        bool first_leg = false;
        for (const std::size_t leg : model_.first_legs) first_leg |= leg == path_[1];
        if (!first_leg) return "the path's first leg is not a pair of the model";
        Integer in = model_.emitted;
        for (std::size_t k = 1; k < path_.size(); ++k) {
            if (k >= 2) {
                const auto t = triples_.find({path_[k - 2], path_[k - 1], path_[k]});
                if (t == triples_.end())
                    return "the path's step " + std::to_string(k) + " is not a triple of the model";
                in = passed(*t->second, in);
            }
            if (arrivals_[k - 1] != in)
                return "arrival " + std::to_string(k) + " is " + arrivals_[k - 1].get_str() +
                       ", the transfers give " + in.get_str();
        }
        if (in != *best_) return "the path delivers " + in.get_str() + ", not best";
        return {};
    }

    // The bounds are closed: every first leg gets at most its bound, every
    // triple passes on at most the next pair's bound; so by induction along
    // any path, what reaches a pair is at most its bound, and the bounds at
    // the receiver are at most best.
    std::string check_bounds() const {
        for (const std::size_t leg : model_.first_legs) {
            const auto b = bounds_.find({model_.source, leg});
            if (b == bounds_.end() || b->second < model_.emitted)
                return "the first leg to " + model_.objects[leg] + " has no bound of " +
                       model_.emitted.get_str();
        }
        for (const Triple& t : model_.triples) {
            const auto in = bounds_.find({t.from, t.via});
            if (in == bounds_.end()) continue; // never reached
            const Integer out = passed(t.transfer, in->second);
            const auto next = bounds_.find({t.via, t.to});
            if (next == bounds_.end() || next->second < out)
                return "the triple " + model_.objects[t.from] + ' ' + model_.objects[t.via] + ' ' +
                       model_.objects[t.to] + " passes on " + out.get_str() +
                       ", more than the bound of its next pair";
        }
        for (const auto& [pair, bound] : bounds_)
            if (pair.second == model_.receiver && (!best_ || bound > *best_))
                return "the bound " + bound.get_str() + " at the receiver (from " +
                       model_.objects[pair.first] + ") exceeds best";
        return {};
    }
};

} // namespace

RealisticVerdict verify_realistic_certificate(const RealisticModel& model, std::istream& in,
                                              const std::string& name) {
    return CertificateCheck(model, in, name).run();
}

} // namespace orthoray
