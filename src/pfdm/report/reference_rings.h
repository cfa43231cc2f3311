// What the clinical summary measures on the reference (end-diastole's)
// model, found once for every frame measured against it: each ring's u is a
// bisection of 50-60 steps of 24 model points (a solid's frame asked for 14
// of them, as much as the rest of its summary), and the delta method
// (number_uncertainty.h) measures a frame again hundreds of times against
// the same reference.
#ifndef PFDM_REPORT_REFERENCE_RINGS_H_
#define PFDM_REPORT_REFERENCE_RINGS_H_

#include <map>
#include <tuple>
#include <utility>

#include "pfdm/model/model.h"
#include "pfdm/report/material_rings.h"

namespace pfdm {

// Not thread-safe: the look-ups fill the caches.  `reference` must outlive
// it and not change.
class ReferenceRings {
 public:
  explicit ReferenceRings(const Model& reference) : reference_(reference) {}
  const Model& model() const { return reference_; }
  // RingAtHeightFraction(reference, h, w).
  double At(double h, double w = 0.0);
  // SampleRing(reference, u, samples, w).
  const MaterialRing& Ring(double u, int samples = kRingSamples,
                           double w = 0.0);
  // MeanWallThickness(reference, u), a solid's.
  double Thickness(double u);
  // MaterialMyocardiumMl of the reference between the rings at u_low and
  // u_high.
  double MyocardiumMl(double u_low, double u_high);

 private:
  const Model& reference_;
  std::map<std::pair<double, double>, double> u_;
  std::map<std::tuple<double, int, double>, MaterialRing> rings_;
  std::map<double, double> thickness_;
  std::map<std::pair<double, double>, double> myocardium_ml_;
};

}  // namespace pfdm

#endif  // PFDM_REPORT_REFERENCE_RINGS_H_
