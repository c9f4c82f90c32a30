#include "induction/rauzy_induction.hpp"

#include "lattice/lattice_int.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace orthoray::induction {
namespace {

using Link = std::uint32_t;
constexpr Link none = ~Link{0};

// A piece of the induced map, with its places in the two orders: one cache
// line on 128-bit integers. At 10^5 mirrors there are over a million pieces
// (about 100 MB with 64-bit links and the orders apart), every step touches
// a few of them at random, and a step costs its cache misses: so one line
// a piece, 32-bit links, and the first event packed into `mark`.
//
// Every length, return time and product the steps form is at most N (a
// return time counts distinct states), and mark = 4 offset + event is at
// most 4N + 3: machine integers serve whenever N < 2^59 (int64) or 2^123.
template <class Int>
struct alignas(64) Node {
    Int length, ret;
    Int mark;     // 4 * offset + the first event (an ExchangeEvent, none = 0)
    Link link[4]; // previous and next in the domain order, then in the image order
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

// A doubly linked order of piece numbers (the domain order, side 0, or the
// image order, side 1), its links kept in the nodes.
template <class Int>
class Order {
public:
    Order(std::vector<Node<Int>>& nodes, int side, const std::vector<Link>& sequence)
        : nodes_(nodes), prev_(2 * side), next_(2 * side + 1) {
        for (std::size_t i = 0; i < sequence.size(); ++i) {
            nodes_[sequence[i]].link[prev_] = i > 0 ? sequence[i - 1] : none;
            nodes_[sequence[i]].link[next_] = i + 1 < sequence.size() ? sequence[i + 1] : none;
        }
        head_ = sequence.front();
        tail_ = sequence.back();
    }
    Link tail() const { return tail_; }
    Link prev(Link p) const { return nodes_[p].link[prev_]; }

    void remove(Link p) {
        const Link before = prev(p), after = next(p);
        (before == none ? head_ : next_of(before)) = after;
        (after == none ? tail_ : prev_of(after)) = before;
    }
    void insert_after(Link p, Link anchor) {
        const Link after = next(anchor);
        prev_of(p) = anchor;
        next_of(p) = after;
        (after == none ? tail_ : prev_of(after)) = p;
        next_of(anchor) = p;
    }
    // p takes q's place; q leaves the order.
    void replace(Link q, Link p) {
        const Link before = prev(q), after = next(q);
        prev_of(p) = before;
        next_of(p) = after;
        (before == none ? head_ : next_of(before)) = p;
        (after == none ? tail_ : prev_of(after)) = p;
    }

private:
    Link next(Link p) const { return nodes_[p].link[next_]; }
    Link& prev_of(Link p) { return nodes_[p].link[prev_]; }
    Link& next_of(Link p) { return nodes_[p].link[next_]; }

    std::vector<Node<Int>>& nodes_;
    int prev_, next_;
    Link head_ = none, tail_ = none;
};

// `a` becomes "a, then b": the first event of a if it has one, else b's.
template <class Int>
void then(Node<Int>& a, const Node<Int>& b) {
    if (event_of(a.mark) == 0 && event_of(b.mark) != 0) a.mark = 4 * a.ret + b.mark;
    a.ret += b.ret;
}

// `a` becomes "b, `times` times, then a" (b's return time is r_b).
template <class Int>
void after(Node<Int>& a, const Node<Int>& b, const Int& times) {
    if (event_of(b.mark) != 0)
        a.mark = b.mark;
    else if (event_of(a.mark) != 0)
        a.mark += 4 * times * b.ret;
    a.ret += times * b.ret;
}

// `a` becomes "a, then b `times` times".
template <class Int>
void then_repeated(Node<Int>& a, const Node<Int>& b, const Int& times) {
    if (event_of(a.mark) == 0 && event_of(b.mark) != 0) a.mark = 4 * a.ret + b.mark;
    a.ret += times * b.ret;
}

template <class Int>
std::optional<InducedOrbit> induce_on(const IntervalExchange& exchange, InductionObserver* observer,
                                      const std::function<bool(std::uint64_t)>& stop) {
    const std::size_t k = exchange.pieces.size();
    if (k >= none) throw std::length_error("an exchange of 2^32 pieces or more");
    std::vector<Node<Int>> node(k);
    std::vector<Int> image_start(k);
    for (std::size_t i = 0; i < k; ++i) {
        const ExchangePiece& e = exchange.pieces[i];
        node[i].length = lattice::from_integer<Int>(e.length);
        node[i].ret = 1;
        const ExchangeEvent event = e.hit                           ? ExchangeEvent::hit
                                    : e.kind == PieceKind::escape   ? ExchangeEvent::escape
                                    : e.kind == PieceKind::absorbed ? ExchangeEvent::absorbed
                                                                    : ExchangeEvent::none;
        node[i].mark = static_cast<int>(event);
        image_start[i] = lattice::from_integer<Int>(e.image);
    }
    std::vector<Link> by_start(k), by_image(k);
    std::iota(by_start.begin(), by_start.end(), Link{0});
    std::iota(by_image.begin(), by_image.end(), Link{0});
    std::sort(by_image.begin(), by_image.end(),
              [&](Link a, Link b) { return image_start[a] < image_start[b]; });
    image_start = {};
    Order<Int> domain(node, 0, by_start), image(node, 1, by_image);

    InducedOrbit orbit;
    Int total, rounds;
    std::vector<Link> walked;
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
        const int order = node[d].length < node[r].length   ? -1
                          : node[r].length < node[d].length ? 1
                                                            : 0;
        if (order == 0) {
            ++orbit.steps;
            if (observer) observer->equal(r, d);
            then(node[r], node[d]);
            image.remove(r);
            image.replace(d, r);
            domain.remove(d);
            continue;
        }
        // The winner w keeps its place; the losers are the pieces after it
        // in the other order, consumed from the end of that order.
        const bool top = order > 0;
        const Link w = top ? d : r;
        const Order<Int>& losers = top ? image : domain;
        walked.clear();
        total = 0;
        Link p = top ? r : d;
        while (p != w && total < node[w].length) {
            walked.push_back(p);
            total += node[p].length;
            p = losers.prev(p);
        }
        if (p == w && total < node[w].length) {
            // Whole rounds through every loser: floor((l_w - 1) / S) of them
            // leave l_w positive, and the orders are as before.
            rounds = (node[w].length - 1) / total;
            for (Link q : walked) {
                if (top)
                    then_repeated(node[q], node[w], rounds);
                else
                    after(node[q], node[w], rounds);
            }
            node[w].length -= rounds * total;
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
            const Link q = walked[i];
            ++orbit.steps;
            if (top) {
                if (observer) observer->top(w, q);
                then(node[q], node[w]);
                image.remove(q);
                image.insert_after(q, w);
            } else {
                if (observer) observer->bottom(w, q);
                after(node[q], node[w], Int(1));
                domain.remove(q);
                domain.insert_after(q, w);
            }
            node[w].length -= node[q].length;
        }
    }
    orbit.arithmetic = lattice::arithmetic_used(Int{});
    orbit.event = static_cast<ExchangeEvent>(event_of(node[0].mark));
    orbit.offset = lattice::to_integer(Int(node[0].mark >> 2));
    orbit.period = lattice::to_integer(node[0].ret);
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
