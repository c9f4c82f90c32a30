#include "induction/rauzy_induction.hpp"

#include "lattice/lattice_int.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

namespace orthoray::induction {
namespace {

constexpr std::size_t none = ~std::size_t{0};

// A piece of the induced map: its length, its return time, its first event.
// Every one of these numbers, and every product the steps form, is at most
// N: a return time counts distinct states. So machine integers serve
// whenever N fits them.
template <class Int>
struct Piece {
    Int length, ret, offset;
    ExchangeEvent event = ExchangeEvent::none;
};

// A doubly linked order of piece numbers (the domain order or the image order).
class Order {
public:
    explicit Order(const std::vector<std::size_t>& sequence)
        : prev_(sequence.size(), none), next_(sequence.size(), none) {
        for (std::size_t i = 0; i < sequence.size(); ++i) {
            if (i > 0) prev_[sequence[i]] = sequence[i - 1];
            if (i + 1 < sequence.size()) next_[sequence[i]] = sequence[i + 1];
        }
        head_ = sequence.front();
        tail_ = sequence.back();
    }
    std::size_t tail() const { return tail_; }
    std::size_t prev(std::size_t p) const { return prev_[p]; }
    std::size_t next(std::size_t p) const { return next_[p]; }

    void remove(std::size_t p) {
        (prev_[p] == none ? head_ : next_[prev_[p]]) = next_[p];
        (next_[p] == none ? tail_ : prev_[next_[p]]) = prev_[p];
    }
    void insert_after(std::size_t p, std::size_t anchor) {
        prev_[p] = anchor;
        next_[p] = next_[anchor];
        (next_[anchor] == none ? tail_ : prev_[next_[anchor]]) = p;
        next_[anchor] = p;
    }
    // p takes q's place; q leaves the order.
    void replace(std::size_t q, std::size_t p) {
        prev_[p] = prev_[q];
        next_[p] = next_[q];
        (prev_[q] == none ? head_ : next_[prev_[q]]) = p;
        (next_[q] == none ? tail_ : prev_[next_[q]]) = p;
    }

private:
    std::vector<std::size_t> prev_, next_;
    std::size_t head_ = none, tail_ = none;
};

// `a` becomes "a, then b": the first event of a if it has one, else b's.
template <class Int>
void then(Piece<Int>& a, const Piece<Int>& b) {
    if (a.event == ExchangeEvent::none && b.event != ExchangeEvent::none) {
        a.event = b.event;
        a.offset = a.ret + b.offset;
    }
    a.ret += b.ret;
}

// `a` becomes "b, `times` times, then a" (b's return time is r_b).
template <class Int>
void after(Piece<Int>& a, const Piece<Int>& b, const Int& times) {
    if (b.event != ExchangeEvent::none) {
        a.event = b.event;
        a.offset = b.offset;
    } else if (a.event != ExchangeEvent::none) {
        a.offset += times * b.ret;
    }
    a.ret += times * b.ret;
}

// `a` becomes "a, then b `times` times".
template <class Int>
void then_repeated(Piece<Int>& a, const Piece<Int>& b, const Int& times) {
    if (a.event == ExchangeEvent::none && b.event != ExchangeEvent::none) {
        a.event = b.event;
        a.offset = a.ret + b.offset;
    }
    a.ret += times * b.ret;
}

template <class Int>
std::optional<InducedOrbit> induce_on(const IntervalExchange& exchange, InductionObserver* observer,
                                      const std::function<bool(std::uint64_t)>& stop) {
    const std::size_t k = exchange.pieces.size();
    std::vector<Piece<Int>> piece(k);
    for (std::size_t i = 0; i < k; ++i) {
        const ExchangePiece& e = exchange.pieces[i];
        piece[i].length = lattice::from_integer<Int>(e.length);
        piece[i].ret = 1;
        piece[i].offset = 0;
        piece[i].event = e.hit                           ? ExchangeEvent::hit
                         : e.kind == PieceKind::escape   ? ExchangeEvent::escape
                         : e.kind == PieceKind::absorbed ? ExchangeEvent::absorbed
                                                         : ExchangeEvent::none;
    }
    std::vector<std::size_t> by_start(k), by_image(k);
    std::iota(by_start.begin(), by_start.end(), std::size_t{0});
    std::iota(by_image.begin(), by_image.end(), std::size_t{0});
    std::sort(by_image.begin(), by_image.end(), [&](std::size_t a, std::size_t b) {
        return exchange.pieces[a].image < exchange.pieces[b].image;
    });
    Order domain(by_start), image(by_image);

    InducedOrbit orbit;
    Int total, rounds;
    std::vector<std::size_t> walked;
    for (std::uint64_t iteration = 1;; ++iteration) {
        if ((iteration & 0xfff) == 0 && stop && stop(orbit.steps)) return std::nullopt;
        const std::size_t d = domain.tail(), r = image.tail();
        if (d == r) {
            // Piece 0 (x) is first in the domain: it is last only when alone.
            if (d == 0) break;
            ++orbit.steps;
            if (observer) observer->invariant(d);
            domain.remove(d);
            image.remove(d);
            continue;
        }
        const int order = piece[d].length < piece[r].length   ? -1
                          : piece[r].length < piece[d].length ? 1
                                                              : 0;
        if (order == 0) {
            ++orbit.steps;
            if (observer) observer->equal(r, d);
            then(piece[r], piece[d]);
            image.remove(r);
            image.replace(d, r);
            domain.remove(d);
            continue;
        }
        // The winner w keeps its place; the losers are the pieces after it
        // in the other order, consumed from the end of that order.
        const bool top = order > 0;
        const std::size_t w = top ? d : r;
        const Order& losers = top ? image : domain;
        walked.clear();
        total = 0;
        std::size_t p = top ? r : d;
        while (p != w && total < piece[w].length) {
            walked.push_back(p);
            total += piece[p].length;
            p = losers.prev(p);
        }
        if (p == w && total < piece[w].length) {
            // Whole rounds through every loser: floor((l_w - 1) / S) of them
            // leave l_w positive, and the orders are as before.
            rounds = (piece[w].length - 1) / total;
            for (std::size_t q : walked) {
                if (top)
                    then_repeated(piece[q], piece[w], rounds);
                else
                    after(piece[q], piece[w], rounds);
            }
            piece[w].length -= rounds * total;
            ++orbit.steps;
            ++orbit.rounds;
            if (observer) {
                const Integer count = lattice::to_integer(rounds);
                top ? observer->top_cycle(w, count) : observer->bottom_cycle(w, count);
            }
            continue;
        }
        // Single steps against every loser whose running total stays below
        // l_w (all walked pieces but the last); the last one is compared again.
        for (std::size_t i = 0; i + 1 < walked.size(); ++i) {
            const std::size_t q = walked[i];
            ++orbit.steps;
            if (top) {
                if (observer) observer->top(w, q);
                then(piece[q], piece[w]);
                image.remove(q);
                image.insert_after(q, w);
            } else {
                if (observer) observer->bottom(w, q);
                after(piece[q], piece[w], Int(1));
                domain.remove(q);
                domain.insert_after(q, w);
            }
            piece[w].length -= piece[q].length;
        }
    }
    orbit.arithmetic = lattice::arithmetic_used(Int{});
    orbit.event = piece[0].event;
    orbit.offset = lattice::to_integer(piece[0].offset);
    orbit.period = lattice::to_integer(piece[0].ret);
    return orbit;
}

} // namespace

std::optional<InducedOrbit> induce(const IntervalExchange& exchange, InductionObserver* observer,
                                   const std::function<bool(std::uint64_t)>& stop) {
    if (exchange.size < lattice::int64_limit())
        return induce_on<std::int64_t>(exchange, observer, stop);
    if (exchange.size < lattice::int128_limit())
        return induce_on<lattice::int128_t>(exchange, observer, stop);
    return induce_on<Integer>(exchange, observer, stop);
}

} // namespace orthoray::induction
