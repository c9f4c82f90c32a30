// The branch states of the illumination search (docs/optics.md) in an exact,
// compact hash set. A state (point, direction) is kept as a short canonical
// byte string in one arena: each coordinate of the point as its rational's
// numerator and denominator bytes, the direction as the number of its
// direction class (the rays' directions up to sign, and with diagonals
// up to a swap of x and y too: one class each) and a sign mask. Equal
// states have equal strings, so lookups compare bytes, never rationals. An
// open-addressing table of 8-byte slots (state number, 32 hash bits) finds
// them. Every buffer grows through a ByteBudget.
#pragma once

#include "engine/byte_budget.hpp"
#include "orthoray/scene.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace orthoray::engine {

class BranchStateSet {
public:
    // Directions reachable from the scene's rays are their directions with
    // components negated, and with diagonals also swapped; those are the
    // only ones insert() accepts.
    BranchStateSet(const Scene& scene, ByteBudget& budget);

    struct Inserted {
        std::uint32_t index; // states are numbered 0, 1, ... in insertion order
        bool added;          // false: it was there already
    };
    // nullopt, with nothing changed, when a new state would pass the budget
    // (or the 2^32 - 1 states the numbering allows).
    std::optional<Inserted> insert(const Vector& point, const Vector& direction);

    std::size_t size() const { return offsets_.size() - 1; }
    // State `index`, decoded back to exact rationals.
    void state(std::uint32_t index, Vector& point, Vector& direction) const;
    // Bytes of the encodings alone (the arena's used part).
    std::size_t key_bytes() const { return static_cast<std::size_t>(offsets_.back()); }

private:
    struct Slot {
        std::uint32_t index_plus_one = 0; // 0: empty
        std::uint32_t tag = 0;            // the hash's high 32 bits
    };

    void encode(const Vector& point, const Vector& direction);
    void put_rational(const Rational& q);
    void put_magnitude(const mpz_class& z);
    void put_varint(std::uint64_t x);
    std::uint64_t hash_of(std::size_t from, std::size_t to, const std::uint8_t* bytes) const;
    // The slot holding key_, or the empty slot where it belongs.
    std::size_t probe(std::uint64_t hash) const;
    bool grow_table();

    int dim_;
    ByteBudget& budget_;
    std::map<Vector, std::uint32_t> direction_class_; // |direction| -> class
    std::vector<Vector> class_magnitude_;
    std::vector<std::uint8_t> arena_;
    std::vector<std::uint64_t> offsets_; // state i is arena_[offsets_[i], offsets_[i + 1])
    std::vector<Slot> table_;            // a power of two, at most 3/4 full
    std::vector<std::uint8_t> key_;      // scratch: the key being looked up
};

} // namespace orthoray::engine
