// Everything derived from a fitted sequence that the outputs report.
#ifndef PFDM_FIT_ANALYSIS_H_
#define PFDM_FIT_ANALYSIS_H_

#include <vector>

#include "pfdm/base_plane.h"
#include "pfdm/clinical_summary.h"
#include "pfdm/fitter.h"
#include "pfdm/model.h"
#include "pfdm/wall_motion.h"

namespace pfdm {

struct FitAnalysis {
  std::vector<Model> models;              // Per frame.
  std::vector<BasePlane> base_planes;     // Empty: flat lid at the rim.
  std::vector<ClinicalSummary> clinical;  // Per frame, against frame 0.
  EjectionFraction ejection_fraction;
  RegionLayout layout;
  std::vector<WallRegion> regions;
  std::vector<std::vector<RegionMotion>> region_motion;  // [frame][region]
};

// base_planes: one per frame to close the cavity there (see
// CavityVolumeMl), or empty for the flat lid at the base rim.
FitAnalysis AnalyzeFit(const SequenceFit& fit,
                       const std::vector<BasePlane>& base_planes = {},
                       const RegionLayout& layout = RegionLayout());

}  // namespace pfdm

#endif  // PFDM_FIT_ANALYSIS_H_
