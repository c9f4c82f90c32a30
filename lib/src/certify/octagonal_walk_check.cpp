#include "certify/octagonal_walk_check.hpp"

#include "certify/induction_check_failure.hpp"

#include <algorithm>
#include <string>

namespace orthoray::certify::induction_check {
namespace {

// The listed pieces re-rooted at `from`: each cut at every point c of
// `cuts` and at c + 1, so that c is a piece of its own; hits cleared unless
// kept, then set on the marks; the coordinates turned so that `from` is 0,
// in domain order from it, an image that passes N split in two.
std::vector<PieceSpec> rerooted(const std::vector<PieceSpec>& listed, const Integer& size,
                                const Integer& from, std::vector<Integer> marks, bool keep_hits) {
    std::vector<Integer> cuts = marks;
    cuts.push_back(from);
    std::sort(cuts.begin(), cuts.end());
    std::sort(marks.begin(), marks.end());
    std::vector<Integer> bounds; // every place a piece must start
    for (const Integer& c : cuts) {
        bounds.push_back(c);
        bounds.push_back(c + 1);
    }
    std::sort(bounds.begin(), bounds.end());
    bounds.erase(std::unique(bounds.begin(), bounds.end()), bounds.end());
    std::vector<PieceSpec> parts;
    for (const PieceSpec& piece : listed) {
        const Integer end = piece.start + piece.length;
        Integer at = piece.start;
        auto b = std::upper_bound(bounds.begin(), bounds.end(), piece.start);
        for (;;) {
            const Integer stop = (b != bounds.end() && *b < end) ? *b : end;
            PieceSpec part = piece;
            part.start = at;
            part.length = stop - at;
            part.image = piece.image + (at - piece.start);
            part.hit = keep_hits && piece.hit;
            if (part.length == 1 && std::binary_search(marks.begin(), marks.end(), at))
                part.hit = true;
            parts.push_back(part);
            if (stop == end) break;
            at = stop;
            ++b;
        }
    }
    std::vector<PieceSpec> out;
    const auto first = std::find_if(parts.begin(), parts.end(),
                                    [&](const PieceSpec& p) { return p.start == from; });
    for (std::size_t k = 0; k < parts.size(); ++k) {
        PieceSpec p = parts[static_cast<std::size_t>((first - parts.begin()) + k) % parts.size()];
        p.start = floor_mod(p.start - from, size);
        p.image = floor_mod(p.image - from, size);
        const Integer over = p.image + p.length - size;
        if (sgn(over) > 0) {
            PieceSpec rest = p;
            rest.start = p.start + (p.length - over);
            rest.length = over;
            rest.image = 0;
            p.length -= over;
            out.push_back(p);
            out.push_back(rest);
        } else {
            out.push_back(p);
        }
    }
    return out;
}

const PieceSpec& piece_at(const std::vector<PieceSpec>& listed, const Integer& s) {
    const auto after =
        std::upper_bound(listed.begin(), listed.end(), s,
                         [](const Integer& v, const PieceSpec& p) { return v < p.start; });
    return *(after - 1);
}

} // namespace

WalkCheck::WalkCheck(std::vector<PieceSpec> listed, Integer size,
                     std::function<std::optional<Integer>(const Integer&)> twin_of)
    : listed_(std::move(listed)), size_(std::move(size)), twin_of_(std::move(twin_of)) {
    // x, every cut state and every join, and the other lift of each.
    std::vector<Integer> special{Integer(0)};
    for (const PieceSpec& p : listed_)
        if (p.kind == Kind::cut) {
            if (p.join >= size_) fail("walk", "a cut piece's join " + str(p.join) + " is no state");
            special.push_back(p.start);
            special.push_back(p.join);
        }
    marks_ = special;
    for (const Integer& s : special)
        if (const std::optional<Integer> twin = twin_of_(s)) marks_.push_back(*twin);
    std::sort(marks_.begin(), marks_.end());
    marks_.erase(std::unique(marks_.begin(), marks_.end()), marks_.end());
    at_ = 0;
    time_ = 0;
    visit(at_, time_);
    advance();
}

bool WalkCheck::is_cut(const Integer& s, Integer* join) const {
    const PieceSpec& p = piece_at(listed_, s);
    if (p.kind != Kind::cut) return false;
    *join = p.join;
    return true;
}

bool WalkCheck::flagged(const Integer& s) const {
    return piece_at(listed_, s).hit;
}

void WalkCheck::advance() {
    Integer join;
    while (!answer_ && is_cut(at_, &join)) {
        if (flagged(at_)) return end(Reason::hit, time_ + 1);
        at_ = join;
        time_ += 1;
        visit(at_, time_);
    }
}

// A state seen again closes the lifted cycle: the tail is the time of its
// first visit (every state where the orbit can enter its cycle is marked),
// the period the time since, halved when its twin came half-way.
bool WalkCheck::visit(const Integer& s, const Integer& t) {
    const auto [it, fresh] = seen_.emplace(s, t);
    if (fresh) return false;
    WalkAnswer a;
    a.tail = it->second;
    Integer period = t - it->second;
    if (const std::optional<Integer> twin = twin_of_(s)) {
        const auto met = seen_.find(*twin);
        if (met != seen_.end() && 2 * (met->second - a.tail) == period) period /= 2;
    }
    a.reflections = a.tail + period;
    answer_ = a;
    return true;
}

void WalkCheck::end(Reason reason, const Integer& reflections) {
    answer_ = WalkAnswer{reason, reflections, 0};
}

std::vector<PieceSpec> WalkCheck::search(const Integer& from, const std::optional<Integer>& only) {
    const std::string where = "walk-search " + str(from);
    if (answer_) fail(where, "the walk has already proven its answer");
    if (from != at_)
        fail(where,
             "the walk is at state " + str(at_) + " (time " + str(time_) + "), not " + str(from));
    if (expecting_only_ != only.has_value())
        fail(where, expecting_only_ ? "the last search met a mark: `only` must name it"
                                    : "the walk needs a search with every mark (`all`)");
    only_ = only;
    if (only) {
        if (*only >= size_) fail(where, "there is no state " + str(*only));
        return rerooted(listed_, size_, from, {*only}, false);
    }
    std::vector<Integer> marks;
    for (const Integer& m : marks_)
        if (m != from) marks.push_back(m);
    return rerooted(listed_, size_, from, marks, true);
}

void WalkCheck::finished(const ReplayedPiece& x) {
    const std::string where = "walk-search " + str(at_);
    if (!only_) {
        switch (x.event.kind) {
        case FirstEvent::none: // back at the start
            if (!visit(at_, time_ + x.return_time))
                fail(where, "the orbit returned to a state the walk never recorded");
            return;
        case FirstEvent::escape:
            return end(Reason::escape, time_ + x.event.offset + 1);
        case FirstEvent::absorbed:
            return end(Reason::absorbed, time_ + x.event.offset + 1);
        case FirstEvent::hit:
            hit_offset_ = x.event.offset;
            expecting_only_ = true;
            return;
        }
    }
    if (x.event.kind != FirstEvent::hit || x.event.offset != *hit_offset_)
        fail(where, "with only state " + str(*only_) + " marked, the orbit does not meet it " +
                        str(*hit_offset_) + " steps on, where the search with every mark stopped");
    expecting_only_ = false;
    const Integer z = *only_;
    // Z is the K-th state from the start, and the first marked one: the
    // target's (flagged) or a special state.
    if (flagged(z)) return end(Reason::hit, time_ + *hit_offset_ + 1);
    at_ = z;
    time_ += *hit_offset_;
    if (visit(at_, time_)) return;
    advance();
}

const WalkAnswer& WalkCheck::answer() const {
    if (!answer_) fail("walk", "the searches end before the walk proves an answer");
    return *answer_;
}

} // namespace orthoray::certify::induction_check
