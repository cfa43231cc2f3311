#include "pfdm/report/reference_rings.h"

#include "pfdm/report/material_myocardium.h"

namespace pfdm {

double ReferenceRings::At(double h, double w) {
  const auto [it, inserted] = u_.try_emplace({h, w}, 0.0);
  if (inserted) it->second = RingAtHeightFraction(reference_, h, w);
  return it->second;
}

const MaterialRing& ReferenceRings::Ring(double u, int samples, double w) {
  const auto [it, inserted] = rings_.try_emplace({u, samples, w});
  if (inserted) it->second = SampleRing(reference_, u, samples, w);
  return it->second;
}

double ReferenceRings::Thickness(double u) {
  const auto [it, inserted] = thickness_.try_emplace(u, 0.0);
  if (inserted) it->second = MeanWallThickness(reference_, u);
  return it->second;
}

double ReferenceRings::MyocardiumMl(double u_low, double u_high) {
  const auto [it, inserted] = myocardium_ml_.try_emplace({u_low, u_high});
  if (inserted) {
    it->second = MaterialMyocardiumMl(reference_, u_low, u_high);
  }
  return it->second;
}

}  // namespace pfdm
