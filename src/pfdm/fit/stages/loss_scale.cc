#include "pfdm/fit/stages/loss_scale.h"

#include "pfdm/fit/residuals/robust_loss.h"

namespace pfdm {

bool MeasuresLossScale(const FitOptions& options) {
  return options.loss != "none" && options.loss_scale_auto;
}

FitOptions WithoutLoss(const FitOptions& options) {
  FitOptions without = options;
  without.loss = "none";
  return without;
}

FitOptions WithLossScale(const FitOptions& options, double scale_mm) {
  FitOptions with = options;
  if (MeasuresLossScale(options)) with.loss_scale_mm = scale_mm;
  return with;
}

double MeasureLossScale(const std::string& loss, const Model& model,
                        const std::vector<Eigen::Vector3d>& points,
                        const std::vector<MaterialPoint>& material) {
  const std::vector<Eigen::Vector3d> at = WorldPoints(model, material);
  std::vector<double> distances;
  distances.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    distances.push_back((at[i] - points[i]).norm());
  }
  return LossTuning(loss) * RobustScaleMm(std::move(distances));
}

double RankBandMm(const std::string& loss, double reference_scale_mm) {
  return OutlierBandMm(loss, reference_scale_mm);
}

void WeighPoints(const std::string& loss, SequenceFit* result) {
  if (loss == "none") return;
  for (FrameFit& frame : result->frames) {
    frame.loss_weights =
        LossWeights(loss, frame.loss_scale_mm, frame.residuals);
  }
}

}  // namespace pfdm
