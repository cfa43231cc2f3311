// How much a tracked frame stretches frame 0's noise along the wall: a tag's
// (u, v) is frame 0's closest point, so frame 0's noise across the normal
// moves the tag's material point, and a later frame carries that offset
// stretched by the wall's deformation between the two.
#ifndef PFDM_FIT_CORRESPONDENCE_TANGENTIAL_STRETCH_H_
#define PFDM_FIT_CORRESPONDENCE_TANGENTIAL_STRETCH_H_

#include <vector>

#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"

namespace pfdm {

// At each material point, the sum of the squared principal stretches of
// its surface w from `reference` to `model`: |F|^2 = tr(G_ref^-1 G), G =
// J'J the surface's metric, J = dx/d(u, v).  Frame 0's isotropic noise of
// sigma^2 per coordinate across the normal reaches the later frame with
// variance sigma^2 |F|^2 over both tangential directions (2 sigma^2 where
// nothing moved).  2 where the reference's metric is singular (the apex
// pole) or the result is not finite.
std::vector<double> TangentialStretchSquared(
    const Model& reference, const Model& model,
    const std::vector<MaterialPoint>& material);

}  // namespace pfdm

#endif  // PFDM_FIT_CORRESPONDENCE_TANGENTIAL_STRETCH_H_
