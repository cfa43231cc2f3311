// A model's top raised along its axis, its apex and its shape below the old
// top kept where they are in the world: what a fit answers when its
// highest data point lies higher.  Frame 0's length is set by its highest
// point (fit/problem/gauge.h, SpanAxialExtent: a0 scaled about the apex,
// every ring's height with it) and its radii are fitted again to the same
// data at the same heights; an untracked later frame's base rim is held at
// its own highest points, its radii fitted likewise.  A volume then changes
// by the top's cross-section times the rise, where a uniform stretch along
// the axis (a3 scaled, the radii of each ring kept) changes it by the mean
// cross-section: on the LV phantom's mid-wall contours the length noise's
// share of ESV's variance came out half of what the fits showed
// (report/local_field_noise.h, docs/uncertainty.md).
#ifndef PFDM_MODEL_RAISED_TOP_H_
#define PFDM_MODEL_RAISED_TOP_H_

#include "pfdm/model/model.h"

namespace pfdm {

// `model` with its length, apex to top ring, made longer by the fraction
// `stretch`: every ring's height from the apex scaled by 1 + stretch (a3
// scaled, the centre moved along the axis to keep the apex), and each
// knot's radii (a1, a2) and axis offsets (e1o, e2o) those the old model has
// at the new ring's height, the top's above the old top.  The paper's
// models (no bending along the way) keep their world shape exactly at the
// knots below the old top; between knots the functions stay linear.
Model RaisedTop(const Model& model, double stretch);

}  // namespace pfdm

#endif  // PFDM_MODEL_RAISED_TOP_H_
