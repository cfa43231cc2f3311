#include "pfdm/report/fit_analysis.h"

#include "pfdm/model/model_surface.h"

namespace pfdm {

FitAnalysis AnalyzeFit(const SequenceFit& fit,
                       const std::vector<BasePlane>& base_planes,
                       const RegionLayout& layout) {
  FitAnalysis analysis;
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    analysis.models.push_back(fit.ModelAt(static_cast<int>(t)));
  }
  analysis.clinical = SummarizeSequence(analysis.models);
  if (base_planes.size() == fit.frames.size()) {
    analysis.base_planes = base_planes;
    for (size_t t = 0; t < fit.frames.size(); ++t) {
      analysis.clinical[t].volume_ml =
          CavityVolumeMl(analysis.models[t], &base_planes[t]);
    }
  }
  analysis.ejection_fraction = EjectionFractionOf(analysis.clinical);
  analysis.layout = layout;
  analysis.regions = Regions(layout);
  const ReferenceSamples reference =
      SampleReference(analysis.models.front(), layout);
  for (const Model& model : analysis.models) {
    analysis.region_motion.push_back(SummarizeRegions(reference, model));
    analysis.strain.push_back(
        SummarizeStrain(analysis.regions, analysis.region_motion.back()));
  }
  return analysis;
}

}  // namespace pfdm
