// The checkers' attenuation rule; see intensity_rule.hpp.
#include "certify/intensity_rule.hpp"

#include "certify/acting_rule.hpp"

#include <vector>

namespace orthoray::certify {
namespace {

// Whether q lies on the closed element: on its plane within its extent, or
// on its diagonal segment (docs/octagonal.md: '/' runs from lo to hi, '\'
// from (lo.x, hi.y) to (hi.x, lo.y)).
bool lies_on(const Element& e, const Vector& q, int dim) {
    if (e.diagonal == Diagonal::rising)
        return q[0] - e.lo[0] == q[1] - e.lo[1] && e.lo[0] <= q[0] && q[0] <= e.hi[0];
    if (e.diagonal == Diagonal::falling)
        return q[0] - e.lo[0] == e.hi[1] - q[1] && e.lo[0] <= q[0] && q[0] <= e.hi[0];
    for (int j = 0; j < dim; ++j)
        if (q[j] < e.lo[j] || e.hi[j] < q[j]) return false;
    return true;
}

Rational reflectance(const Element& e) {
    return e.reflectance ? *e.reflectance : Rational(1);
}

Rational transmittance(const Element& e) {
    return e.transmittance ? *e.transmittance : Rational(1);
}

// An orientation: 0-2 the normal axes, 3 '/' and 4 '\'.
int orientation(const Element& e) {
    if (e.diagonal == Diagonal::rising) return 3;
    if (e.diagonal == Diagonal::falling) return 4;
    return e.axis;
}

} // namespace

Rational intensity_factor(const Scene& scene, const Vector& q, const Vector& v, const Vector& c) {
    std::vector<const Element*> acting;
    bool attenuating = false;
    for (const Element& e : scene.elements)
        if (acts_on(e, v) && lies_on(e, q, scene.dim)) {
            acting.push_back(&e);
            attenuating = attenuating || e.reflectance || e.transmittance;
        }
    if (!attenuating) return 1;
    unsigned orientations = 0, mirrored = 0, diagonal = 0;
    for (const Element* e : acting) {
        orientations |= 1u << orientation(*e);
        if (e->is_diagonal()) diagonal = 1;
        if (e->kind == ElementKind::mirror) mirrored |= 1u << orientation(*e);
    }
    const bool mixed = (orientations & (orientations - 1)) != 0;
    Rational factor = 1;
    for (const Element* e : acting) {
        const int o = orientation(*e);
        if (diagonal && mixed) {
            // Orientations meet at a diagonal: the ray goes back, reflected
            // by every element there.
            factor *= reflectance(*e);
        } else if (e->kind == ElementKind::mirror) {
            factor *= reflectance(*e);
        } else if (e->kind == ElementKind::splitter && !(mirrored & (1u << o))) {
            // A splitter under no mirror of its orientation: reflected when
            // the ray turns there, passed when it goes straight on (along
            // its normal axis; across a diagonal, when c == v).
            const bool turned = e->is_diagonal() ? c != v : c[o] != v[o];
            factor *= turned ? reflectance(*e) : transmittance(*e);
        }
    }
    return factor;
}

Integer attenuate(const Integer& intensity, const Rational& factor) {
    Integer product = intensity * factor.get_num();
    mpz_fdiv_q(product.get_mpz_t(), product.get_mpz_t(), factor.get_den().get_mpz_t());
    return product;
}

} // namespace orthoray::certify
