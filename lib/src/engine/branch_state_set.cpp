#include "engine/branch_state_set.hpp"

#include <cstring>
#include <limits>
#include <stdexcept>

namespace orthoray::engine {
namespace {

Vector magnitude(const Vector& v) {
    Vector m;
    for (int j = 0; j < 3; ++j) m[j] = abs(v[j]);
    return m;
}

std::uint64_t get_varint(const std::uint8_t*& at) {
    std::uint64_t x = 0;
    for (int shift = 0;; shift += 7) {
        const std::uint8_t b = *at++;
        x |= std::uint64_t{b & 0x7fu} << shift;
        if (b < 0x80) return x;
    }
}

// Big-endian magnitude bytes, as put_magnitude wrote them.
mpz_class get_magnitude(const std::uint8_t*& at, std::size_t bytes) {
    mpz_class z;
    if (bytes > 0) mpz_import(z.get_mpz_t(), bytes, 1, 1, 1, 0, at);
    at += bytes;
    return z;
}

} // namespace

BranchStateSet::BranchStateSet(const Scene& scene, ByteBudget& budget)
    : dim_(scene.dim), budget_(budget) {
    auto add_class = [&](const Vector& m) {
        const auto [it, added] =
            direction_class_.emplace(m, static_cast<std::uint32_t>(class_magnitude_.size()));
        if (added) class_magnitude_.push_back(it->first);
    };
    for (const Ray& r : scene.rays) {
        add_class(magnitude(r.direction));
        // A diagonal swaps the components (docs/octagonal.md): (|b|, |a|) is
        // a class of its own unless |a| = |b| (then the map merges them).
        // Each class's magnitudes are stored as they are, so a key names
        // (|a|, |b|) and (|b|, |a|) apart exactly.
        if (scene.has_diagonal()) {
            const Vector m = magnitude(r.direction);
            add_class({m[1], m[0], m[2]});
        }
    }
    offsets_.push_back(0);
    budget_.allocated(offsets_.capacity() * sizeof(std::uint64_t));
}

void BranchStateSet::put_varint(std::uint64_t x) {
    while (x >= 0x80) {
        key_.push_back(static_cast<std::uint8_t>(x | 0x80));
        x >>= 7;
    }
    key_.push_back(static_cast<std::uint8_t>(x));
}

void BranchStateSet::put_magnitude(const mpz_class& z) {
    const std::size_t at = key_.size();
    const std::size_t bytes = sgn(z) == 0 ? 0 : (mpz_sizeinbase(z.get_mpz_t(), 2) + 7) / 8;
    key_.resize(at + bytes);
    if (bytes > 0) mpz_export(key_.data() + at, nullptr, 1, 1, 1, 0, z.get_mpz_t());
}

// A canonical rational (GMP keeps them in lowest terms, denominator > 0) as
// a header varint: 4 * (numerator bytes) + 2 * (negative) + (denominator
// != 1); the numerator's magnitude bytes; then, if the denominator is not 1,
// its byte count and bytes. A small integer takes 2 bytes, 0 takes 1.
void BranchStateSet::put_rational(const Rational& q) {
    const mpz_class& num = q.get_num();
    const mpz_class& den = q.get_den();
    const std::size_t bytes = sgn(num) == 0 ? 0 : (mpz_sizeinbase(num.get_mpz_t(), 2) + 7) / 8;
    put_varint(4 * std::uint64_t{bytes} + (sgn(num) < 0 ? 2 : 0) + (den != 1 ? 1 : 0));
    put_magnitude(abs(num));
    if (den == 1) return;
    put_varint((mpz_sizeinbase(den.get_mpz_t(), 2) + 7) / 8);
    put_magnitude(den);
}

void BranchStateSet::encode(const Vector& point, const Vector& direction) {
    key_.clear();
    for (int j = 0; j < dim_; ++j) put_rational(point[j]);
    const auto it = direction_class_.find(magnitude(direction));
    if (it == direction_class_.end())
        throw std::logic_error("branch state set: a direction no ray has, up to sign");
    put_varint(it->second);
    unsigned negative = 0;
    for (int j = 0; j < dim_; ++j)
        if (sgn(direction[j]) < 0) negative |= 1u << j;
    key_.push_back(static_cast<std::uint8_t>(negative));
}

// FNV-1a over the bytes, then a 64-bit finaliser (MurmurHash3's fmix64) so
// that both the low bits (the slot) and the high bits (the tag) are mixed.
std::uint64_t BranchStateSet::hash_of(std::size_t from, std::size_t to,
                                      const std::uint8_t* bytes) const {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t i = from; i < to; ++i) h = (h ^ bytes[i]) * 0x100000001b3ull;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    return h ^ (h >> 33);
}

std::size_t BranchStateSet::probe(std::uint64_t hash) const {
    const std::size_t mask = table_.size() - 1;
    const auto tag = static_cast<std::uint32_t>(hash >> 32);
    for (std::size_t i = hash & mask;; i = (i + 1) & mask) {
        const Slot& slot = table_[i];
        if (slot.index_plus_one == 0) return i;
        if (slot.tag != tag) continue;
        const std::uint32_t s = slot.index_plus_one - 1;
        const std::size_t length = static_cast<std::size_t>(offsets_[s + 1] - offsets_[s]);
        if (length == key_.size() &&
            std::memcmp(arena_.data() + offsets_[s], key_.data(), length) == 0)
            return i;
    }
}

// Doubles the table (16 slots at first) and re-inserts every state, hashing
// its bytes again: the slots keep only 32 of the 64 hash bits.
bool BranchStateSet::grow_table() {
    const std::size_t slots = table_.empty() ? 16 : 2 * table_.size();
    if (!budget_.fits(slots * sizeof(Slot))) return false;
    std::vector<Slot> bigger(slots);
    budget_.allocated(slots * sizeof(Slot));
    const std::size_t mask = slots - 1;
    for (std::size_t s = 0; s < size(); ++s) {
        const std::uint64_t h = hash_of(static_cast<std::size_t>(offsets_[s]),
                                        static_cast<std::size_t>(offsets_[s + 1]), arena_.data());
        std::size_t i = h & mask;
        while (bigger[i].index_plus_one != 0) i = (i + 1) & mask;
        bigger[i] = {static_cast<std::uint32_t>(s + 1), static_cast<std::uint32_t>(h >> 32)};
    }
    budget_.freed(table_.capacity() * sizeof(Slot));
    table_ = std::move(bigger);
    return true;
}

std::optional<BranchStateSet::Inserted> BranchStateSet::insert(const Vector& point,
                                                               const Vector& direction) {
    encode(point, direction);
    const std::uint64_t hash = hash_of(0, key_.size(), key_.data());
    if (!table_.empty()) {
        const std::size_t i = probe(hash);
        if (table_[i].index_plus_one != 0) return Inserted{table_[i].index_plus_one - 1, false};
    }
    // A new state: make every room first, so a refusal changes nothing.
    if (size() >= std::numeric_limits<std::uint32_t>::max() - 1) return std::nullopt;
    if (!budget_.make_room(arena_, key_.size()) || !budget_.make_room(offsets_))
        return std::nullopt;
    if (4 * (size() + 1) > 3 * table_.size() && !grow_table()) return std::nullopt;
    const auto index = static_cast<std::uint32_t>(size());
    arena_.insert(arena_.end(), key_.begin(), key_.end());
    offsets_.push_back(arena_.size());
    table_[probe(hash)] = {index + 1, static_cast<std::uint32_t>(hash >> 32)};
    return Inserted{index, true};
}

void BranchStateSet::state(std::uint32_t index, Vector& point, Vector& direction) const {
    const std::uint8_t* at = arena_.data() + offsets_[index];
    point = Vector{};
    for (int j = 0; j < dim_; ++j) {
        const std::uint64_t header = get_varint(at);
        mpz_class num = get_magnitude(at, static_cast<std::size_t>(header / 4));
        if (header & 2) num = -num;
        mpz_class den = 1;
        if (header & 1) den = get_magnitude(at, static_cast<std::size_t>(get_varint(at)));
        point[j] = Rational(num, den); // already in lowest terms
    }
    direction = class_magnitude_[static_cast<std::size_t>(get_varint(at))];
    const unsigned negative = *at;
    for (int j = 0; j < dim_; ++j)
        if (negative & (1u << j)) direction[j] = -direction[j];
}

} // namespace orthoray::engine
