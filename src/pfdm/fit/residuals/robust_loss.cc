#include "pfdm/fit/residuals/robust_loss.h"

#include <algorithm>
#include <memory>

#include "pfdm/util/error.h"

namespace pfdm {

void CheckLossName(const std::string& name) {
  if (name == "none" || name == "huber" || name == "cauchy") return;
  throw InputError("unknown --loss '" + name +
                   "' (expected none, huber or cauchy)");
}

ceres::LossFunction* MakeLoss(const std::string& name, double scale_mm) {
  CheckLossName(name);
  if (name == "huber") return new ceres::HuberLoss(scale_mm);
  if (name == "cauchy") return new ceres::CauchyLoss(scale_mm);
  return nullptr;
}

std::vector<double> LossWeights(const std::string& name, double scale_mm,
                                const std::vector<Eigen::Vector3d>& residuals) {
  std::vector<double> weights(residuals.size(), 1.0);
  const std::unique_ptr<ceres::LossFunction> loss(MakeLoss(name, scale_mm));
  if (!loss) return weights;
  for (size_t i = 0; i < residuals.size(); ++i) {
    double rho[3];
    loss->Evaluate(residuals[i].squaredNorm(), rho);
    weights[i] = rho[1];
  }
  return weights;
}

double LossTuning(const std::string& name) {
  CheckLossName(name);
  if (name == "huber") return 1.345;
  if (name == "cauchy") return 2.385;
  return 1.0;
}

double OutlierBandMm(const std::string& name, double scale_mm) {
  if (name == "none") return 0.0;
  return 3.0 * scale_mm / LossTuning(name);
}

double RobustScaleMm(std::vector<double> distances) {
  if (distances.empty()) return kMinLossScaleMm;
  const auto middle = distances.begin() + distances.size() / 2;
  std::nth_element(distances.begin(), middle, distances.end());
  double median = *middle;
  if (distances.size() % 2 == 0) {
    median = 0.5 * (median + *std::max_element(distances.begin(), middle));
  }
  return std::max(kMinLossScaleMm, 1.4826 * median);
}

}  // namespace pfdm
