// The checkers' own reading of how an event attenuates a ray
// (docs/intensity.md, "The rule"): the factor of each direction leaving an
// event, and the floor after it. Written apart from the engines'
// outgoing_factor (engine/event_rule.cpp) on purpose, like acting_rule.hpp:
// an intensity certificate is trusted only if a second reading agrees.
#pragma once

#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

namespace orthoray::certify {

// The factor by which the event at q multiplies the intensity of a ray
// arriving along v and leaving along c (one of the directions that
// outgoing() allows there): the product of the reflectances and
// transmittances of the elements acting on v that lie on q, by the rule.
Rational intensity_factor(const Scene& scene, const Vector& q, const Vector& v, const Vector& c);

// floor(intensity * factor), for a natural intensity and 0 <= factor <= 1.
Integer attenuate(const Integer& intensity, const Rational& factor);

} // namespace orthoray::certify
