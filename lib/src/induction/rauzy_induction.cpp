#include "induction/rauzy_induction.hpp"

#include "induction/exchange_builder.hpp"
#include "lattice/lattice_int.hpp"

#include <algorithm>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace orthoray::induction {
namespace {

using Link = std::uint32_t;
constexpr Link none = ~Link{0};

// The pieces of the induced map, as separate arrays: their lengths, their
// return times with their first events, and the two orders' links. A step walks one
// order back from its end, adding lengths: the walk is a chain of dependent
// loads through that order's `prev` links, so those are 32-bit and alone in
// their array (at 10^4 mirrors, 140,000 pieces: 560 kB, against 9 MB for
// whole pieces), and the lengths are loaded beside the chain, not in it.
// The first event is packed with its offset: mark = 4 offset + event.
//
// Every length, return time and product the steps form is at most N (a
// return time counts distinct states), and a mark at most 4N + 3: machine
// integers serve whenever N < 2^59 (int64) or 2^123.
template <class Int>
struct Pieces {
    // What a piece's orbit segment does, read and written together by every
    // composition. Aligned to its size, so that it never straddles two cache
    // lines: malloc aligns to 16 bytes only, and on 128-bit integers (32
    // bytes) every other return would take two misses, or not, depending on
    // where the array happened to land (then() took 4% or 12% of a solve at
    // 10^4 mirrors between two builds that differed elsewhere).
    struct alignas(2 * sizeof(Int)) Return {
        Int time;
        Int mark; // 4 * offset + the first event (an ExchangeEvent, none = 0)
    };
    std::vector<Int> length;
    std::vector<Return> ret;
};

static_assert(static_cast<int>(ExchangeEvent::none) == 0 &&
                  static_cast<int>(ExchangeEvent::absorbed) == 3,
              "an event fits the two low bits of a mark");

template <class Int>
unsigned event_of(const Int& mark) {
    if constexpr (std::is_same_v<Int, Integer>)
        return static_cast<unsigned>(mpz_fdiv_ui(mark.get_mpz_t(), 4));
    else
        return static_cast<unsigned>(mark & 3);
}

// A doubly linked order of piece numbers (the domain order or the image order).
class Order {
public:
    explicit Order(const std::vector<Link>& sequence)
        : prev_(sequence.size(), none), next_(sequence.size(), none) {
        for (std::size_t i = 0; i < sequence.size(); ++i) {
            if (i > 0) prev_[sequence[i]] = sequence[i - 1];
            if (i + 1 < sequence.size()) next_[sequence[i]] = sequence[i + 1];
        }
        head_ = sequence.front();
        tail_ = sequence.back();
    }
    Link tail() const { return tail_; }
    Link prev(Link p) const { return prev_[p]; }
    // The `prev` links as one array, for a walk that keeps its pointer in a
    // register (the array never moves). The walk must take it itself: it
    // stores the pieces it passes, Links like these, so the compiler cannot
    // tell that the vector's own pointer is unchanged and reloads it (and
    // l_w) on every piece, as it did with prev() in the loop.
    const Link* prevs() const { return prev_.data(); }
    Link next(Link p) const { return next_[p]; }
    // A hint that p's `prev` link is about to be rewritten.
    void prefetch_prev(Link p) const { __builtin_prefetch(&prev_[p], 1); }

    void remove(Link p) {
        (prev_[p] == none ? head_ : next_[prev_[p]]) = next_[p];
        (next_[p] == none ? tail_ : prev_[next_[p]]) = prev_[p];
    }
    // The block from `first` to the tail moves to right after `anchor`,
    // keeping its own order; `anchor` is not in it. The links inside the
    // block stay as they are: only its two ends are rewritten.
    void move_tail_after(Link first, Link anchor) {
        const Link last = tail_, before = prev_[first];
        next_[before] = none;
        tail_ = before;
        const Link after = next_[anchor];
        prev_[first] = anchor;
        next_[anchor] = first;
        next_[last] = after;
        (after == none ? tail_ : prev_[after]) = last;
    }
    // p takes q's place; q leaves the order.
    void replace(Link q, Link p) {
        prev_[p] = prev_[q];
        next_[p] = next_[q];
        (prev_[q] == none ? head_ : next_[prev_[q]]) = p;
        (next_[q] == none ? tail_ : prev_[next_[q]]) = p;
    }

private:
    std::vector<Link> prev_, next_;
    Link head_ = none, tail_ = none;
};

// Piece a becomes "a, then b": the first event of a if it has one, else b's.
template <class Int>
void then(Pieces<Int>& x, Link a_link, Link b_link) {
    auto& a = x.ret[a_link];
    const auto& b = x.ret[b_link];
    if (event_of(a.mark) == 0 && event_of(b.mark) != 0) a.mark = 4 * a.time + b.mark;
    a.time += b.time;
}

// Piece a becomes "b, `times` times, then a" (b's return time is r_b).
template <class Int>
void after(Pieces<Int>& x, Link a_link, Link b_link, const Int& times) {
    auto& a = x.ret[a_link];
    const auto& b = x.ret[b_link];
    if (event_of(b.mark) != 0)
        a.mark = b.mark;
    else if (event_of(a.mark) != 0)
        a.mark += 4 * times * b.time;
    a.time += times * b.time;
}

// Piece a becomes "a, then b `times` times".
template <class Int>
void then_repeated(Pieces<Int>& x, Link a_link, Link b_link, const Int& times) {
    auto& a = x.ret[a_link];
    const auto& b = x.ret[b_link];
    if (event_of(a.mark) == 0 && event_of(b.mark) != 0) a.mark = 4 * a.time + b.mark;
    a.time += times * b.time;
}

// `pieces`: ExchangePiece or RawPieceOn (start, length, image, kind, hit),
// sorted by start, x's first.
template <class Int, class Piece>
std::optional<InducedOrbit> induce_on(const std::vector<Piece>& pieces, InductionObserver* observer,
                                      const std::function<bool(std::uint64_t)>& stop) {
    const std::size_t k = pieces.size();
    if (k >= none) throw std::length_error("an exchange of 2^32 pieces or more");
    Pieces<Int> piece;
    piece.length.resize(k);
    piece.ret.resize(k);
    std::vector<Int> image_start(k);
    for (std::size_t i = 0; i < k; ++i) {
        const Piece& e = pieces[i];
        piece.length[i] = lattice::convert<Int>(e.length);
        const ExchangeEvent event = e.hit                           ? ExchangeEvent::hit
                                    : e.kind == PieceKind::escape   ? ExchangeEvent::escape
                                    : e.kind == PieceKind::absorbed ? ExchangeEvent::absorbed
                                                                    : ExchangeEvent::none;
        piece.ret[i].time = 1;
        piece.ret[i].mark = static_cast<int>(event);
        image_start[i] = lattice::convert<Int>(e.image);
    }
    std::vector<Link> by_start(k), by_image(k);
    std::iota(by_start.begin(), by_start.end(), Link{0});
    std::iota(by_image.begin(), by_image.end(), Link{0});
    std::sort(by_image.begin(), by_image.end(),
              [&](Link a, Link b) { return image_start[a] < image_start[b]; });
    image_start = {};
    Order domain(by_start), image(by_image);

    InducedOrbit orbit;
    Int total, rounds;
    // The pieces a walk passes, at most all k: allocated once (and touched
    // only as far as walks reach), so that the walk has no call in it (a
    // push_back's growth) around which its pointers and running total would
    // be spilled to the stack and reloaded.
    const auto walked_buffer = std::make_unique_for_overwrite<Link[]>(k);
    Link* const walked = walked_buffer.get();
    std::size_t walked_count = 0;
    // On machine integers 4096 steps take about a millisecond; a step on GMP
    // integers of a million digits takes milliseconds by itself, so there
    // every step asks (a clock read, small beside one big division).
    constexpr std::uint64_t poll_mask = std::is_same_v<Int, Integer> ? 0 : 0xfff;
    for (std::uint64_t iteration = 1;; ++iteration) {
        if ((iteration & poll_mask) == 0 && stop && stop(orbit.steps)) return std::nullopt;
        const Link d = domain.tail(), r = image.tail();
        if (d == r) {
            // Piece 0 (x) is first in the domain: it is last only when alone.
            if (d == 0) break;
            ++orbit.steps;
            if (observer) observer->invariant(d);
            domain.remove(d);
            image.remove(d);
            continue;
        }
        const std::vector<Int>& length = piece.length;
        const int order = length[d] < length[r] ? -1 : length[r] < length[d] ? 1 : 0;
        if (order == 0) {
            ++orbit.steps;
            if (observer) observer->equal(r, d);
            then(piece, r, d);
            image.remove(r);
            image.replace(d, r);
            domain.remove(d);
            continue;
        }
        // The winner w keeps its place; the losers are the pieces after it
        // in the other order, consumed from the end of that order.
        const bool top = order > 0;
        const Link w = top ? d : r;
        const Order& losers = top ? image : domain;
        walked_count = 0;
        Link p = top ? r : d;
        // The walk is a chain of dependent misses; the loads it does not
        // depend on are issued along it. Each consumed piece's return time
        // is written right after the walk: fetch it now.
        // And the next step walks the other order back from w (a top run
        // leaves w last in the domain and the last walked piece last in the
        // image, so the next step is a bottom one with w among its losers, or
        // equal; likewise the other way): its first links are followed here,
        // one a link of this walk, a second chain beside this one. It never
        // runs off its order: both orders hold the same pieces, w is last in
        // the other one, and this walk passes at most all of them but w.
        const Order& winners = top ? domain : image;
        const Link* const loser_prev = losers.prevs();
        const Link* const winner_prev = winners.prevs();
        // If the walk ends in single steps, the consumed block is spliced in
        // right after w, rewriting w's `next` link in the losers' order and
        // the `prev` link of the piece that follows w there: two dependent
        // misses after the walk (most of the splice's time at 10^4 mirrors).
        // Read the first and fetch the second now, beside the walk's chain.
        if (const Link after = losers.next(w); after != none) losers.prefetch_prev(after);
        Link ahead = w;
        const Int* const lengths = length.data();
        const Int& bound = lengths[w];
        const auto* const returns = piece.ret.data();
        total = 0;
        while (p != w && total < bound) {
            walked[walked_count++] = p;
            __builtin_prefetch(&returns[p], 1);
            total += lengths[p];
            p = loser_prev[p];
            ahead = winner_prev[ahead];
            __builtin_prefetch(&lengths[ahead]);
        }
        if (p == w && total < length[w]) {
            // Whole rounds through every loser: floor((l_w - 1) / S) of them
            // leave l_w positive, and the orders are as before.
            rounds = (length[w] - 1) / total;
            for (std::size_t i = 0; i < walked_count; ++i) {
                const Link q = walked[i];
                if (top)
                    then_repeated(piece, q, w, rounds);
                else
                    after(piece, q, w, rounds);
            }
            piece.length[w] -= rounds * total;
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
        // One by one, each goes from the end of its order to right after w,
        // so together they move as one block in their own order.
        const std::size_t consumed = walked_count - 1;
        for (std::size_t i = 0; i < consumed; ++i) {
            const Link q = walked[i];
            if (top) {
                if (observer) observer->top(w, q);
                then(piece, q, w);
            } else {
                if (observer) observer->bottom(w, q);
                after(piece, q, w, Int(1));
            }
        }
        if (consumed > 0) {
            orbit.steps += consumed;
            (top ? image : domain).move_tail_after(walked[consumed - 1], w);
            piece.length[w] -= total - length[walked[consumed]];
        }
    }
    orbit.arithmetic = lattice::arithmetic_used(Int{});
    orbit.event = static_cast<ExchangeEvent>(event_of(piece.ret[0].mark));
    orbit.offset = lattice::to_integer(Int(piece.ret[0].mark >> 2));
    orbit.period = lattice::to_integer(piece.ret[0].time);
    return orbit;
}

// The narrowest integers N allows (the induction's own bound, above).
template <class Piece>
std::optional<InducedOrbit> induce_pieces(const Integer& size, const std::vector<Piece>& pieces,
                                          InductionObserver* observer,
                                          const std::function<bool(std::uint64_t)>& stop) {
    if (size < lattice::int64_limit()) return induce_on<std::int64_t>(pieces, observer, stop);
    if (size < lattice::int128_limit()) return induce_on<lattice::int128_t>(pieces, observer, stop);
    return induce_on<Integer>(pieces, observer, stop);
}

} // namespace

std::optional<InducedOrbit> induce(const IntervalExchange& exchange, InductionObserver* observer,
                                   const std::function<bool(std::uint64_t)>& stop) {
    return induce_pieces(exchange.size, exchange.pieces, observer, stop);
}

template <class Num>
std::optional<InducedOrbit> induce(const ExchangeOn<Num>& exchange,
                                   const std::function<bool(std::uint64_t)>& stop) {
    return induce_pieces(lattice::to_integer(exchange.size), exchange.pieces, nullptr, stop);
}

template std::optional<InducedOrbit> induce(const ExchangeOn<std::int64_t>&,
                                            const std::function<bool(std::uint64_t)>&);
template std::optional<InducedOrbit> induce(const ExchangeOn<lattice::int128_t>&,
                                            const std::function<bool(std::uint64_t)>&);
template std::optional<InducedOrbit> induce(const ExchangeOn<Integer>&,
                                            const std::function<bool(std::uint64_t)>&);

} // namespace orthoray::induction
