#include "pfdm/fit/correspondence/transmural.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "pfdm/util/error.h"
#include "pfdm/util/point_cloud_tree.h"

namespace pfdm {
namespace {

// Tags whose neighbour WallSpreadMm compares, at most, and tags it takes
// them from.
constexpr size_t kMaxSpreadPairs = 4096;
constexpr size_t kMaxSpreadNeighbours = 16384;

}  // namespace

WallModel WallModelFromName(const std::string& name) {
  if (name == "auto") return WallModel::kAuto;
  if (name == "midwall") return WallModel::kMidwall;
  if (name == "solid") return WallModel::kSolid;
  throw InputError("unknown --wall '" + name +
                   "' (expected auto, midwall or solid)");
}

const char* WallModelName(WallModel model) {
  switch (model) {
    case WallModel::kAuto:
      return "auto";
    case WallModel::kMidwall:
      return "midwall";
    case WallModel::kSolid:
      return "solid";
  }
  return "";
}

std::vector<double> MidwallDistances(
    const Model& model, const std::vector<Eigen::Vector3d>& points,
    const std::vector<MaterialPoint>& material,
    std::vector<Eigen::Vector3d>* midwall_points) {
  std::vector<MaterialPoint> midwall = material;
  for (MaterialPoint& m : midwall) m.w = 0.0;
  std::vector<Eigen::Vector3d> model_points;
  const std::vector<Eigen::Vector3d> normals =
      SurfaceNormals(model, midwall, &model_points);
  std::vector<double> distances;
  distances.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    distances.push_back(normals[i].dot(points[i] - model_points[i]));
  }
  if (midwall_points != nullptr) *midwall_points = std::move(model_points);
  return distances;
}

double WallSpreadMm(const std::vector<Eigen::Vector3d>& midwall_points,
                    const std::vector<double>& distances) {
  // Neighbours among every step-th tag: at most kMaxSpreadNeighbours, 0.9
  // mm apart on an LV's mid-wall (0.5 mm for all of 50,000 tags), where
  // the fit's error changes too little to tell them apart; building the
  // tree of all 50,000 took 13 ms.
  const size_t step =
      (midwall_points.size() + kMaxSpreadNeighbours - 1) / kMaxSpreadNeighbours;
  PointCloud cloud;
  std::vector<double> cloud_distances;
  for (size_t i = 0; i < midwall_points.size(); i += step) {
    cloud.points.push_back(midwall_points[i]);
    cloud_distances.push_back(distances[i]);
  }
  const size_t num_points = cloud.points.size();
  if (num_points < 2) return 0.0;
  PointCloudTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  // The mean over at most kMaxSpreadPairs tags' pairs (every stride-th)
  // estimates the mean over all to about 1 % (one in sqrt(2 x 4096)),
  // plenty for a threshold.
  const size_t stride = (num_points + kMaxSpreadPairs - 1) / kMaxSpreadPairs;
  double sum_squared = 0.0;
  size_t pairs = 0;
  for (size_t i = 0; i < num_points; i += stride, ++pairs) {
    unsigned int nearest[2];
    double distance_squared[2];
    tree.knnSearch(cloud.points[i].data(), 2, nearest, distance_squared);
    const size_t j = nearest[0] == i ? nearest[1] : nearest[0];
    const double difference = cloud_distances[i] - cloud_distances[j];
    sum_squared += difference * difference;
  }
  return std::sqrt(6.0 * sum_squared / pairs);
}

std::vector<double> QuantileDepths(const std::vector<double>& u,
                                   const std::vector<double>& distances) {
  return QuantileDepths(u, distances, std::vector<bool>(u.size(), true));
}

std::vector<double> QuantileDepths(const std::vector<double>& u,
                                   const std::vector<double>& distances,
                                   const std::vector<bool>& ranked) {
  const size_t n = u.size();
  std::vector<size_t> by_u(n);
  std::iota(by_u.begin(), by_u.end(), 0);
  std::stable_sort(by_u.begin(), by_u.end(),
                   [&](size_t a, size_t b) { return u[a] < u[b]; });
  const size_t band = std::max<size_t>(kMinBand, n / 16);
  std::vector<double> depths(n, 0.0);
  for (size_t begin = 0, end = 0; begin < n; begin = end) {
    // The last band takes the remainder rather than leaving a runt.
    end = std::min(n, begin + band);
    if (n - end < band / 2) end = n;
    std::vector<size_t> members;
    for (size_t k = begin; k < end; ++k) {
      const size_t i = by_u[k];
      if (ranked[i]) {
        members.push_back(i);
      } else {
        depths[i] = distances[i] < 0.0 ? -1.0 : 1.0;
      }
    }
    std::stable_sort(members.begin(), members.end(), [&](size_t a, size_t b) {
      return distances[a] < distances[b];
    });
    const double count = static_cast<double>(members.size());
    for (size_t rank = 0; rank < members.size(); ++rank) {
      depths[members[rank]] = 2.0 * (rank + 0.5) / count - 1.0;
    }
  }
  return depths;
}

std::vector<bool> WithinWall(const Model& model,
                             const std::vector<MaterialPoint>& material,
                             const std::vector<double>& distances,
                             double band_mm) {
  std::vector<MaterialPoint> endo = material, epi = material;
  for (MaterialPoint& m : endo) m.w = -1.0;
  for (MaterialPoint& m : epi) m.w = 1.0;
  const std::vector<double> inner =
      MidwallDistances(model, WorldPoints(model, endo), material);
  const std::vector<double> outer =
      MidwallDistances(model, WorldPoints(model, epi), material);
  std::vector<bool> within(distances.size());
  for (size_t i = 0; i < distances.size(); ++i) {
    within[i] = distances[i] >= inner[i] - band_mm &&
                distances[i] <= outer[i] + band_mm;
  }
  return within;
}

double TangentialNoiseMm(const Model& model,
                         const std::vector<Eigen::Vector3d>& residuals,
                         const std::vector<MaterialPoint>& material,
                         const std::vector<size_t>& which, bool robust) {
  if (which.empty()) return 0.0;
  double sum = 0.0;
  std::vector<double> squares;
  for (size_t i : which) {
    const MaterialPoint& m = material[i];
    const Eigen::Vector3d n = SurfaceNormal(model, m.u, m.v, m.w);
    const double square =
        (residuals[i] - residuals[i].dot(n) * n).squaredNorm();
    sum += square;
    if (robust) squares.push_back(square);
  }
  if (!robust) return std::sqrt(sum / (4.0 * which.size()));
  const auto middle = squares.begin() + squares.size() / 2;
  std::nth_element(squares.begin(), middle, squares.end());
  return std::sqrt(*middle / (4.0 * std::log(2.0)));
}

double DeconvolvedThickness(double h_obs, double sigma) {
  const double root = h_obs * h_obs - 24.0 * sigma * sigma;
  return 0.5 * (h_obs + std::sqrt(std::max(0.0, root)));
}

double ThicknessFromDepths(const std::vector<double>& distances,
                           const std::vector<double>& depths) {
  double dw = 0.0, ww = 0.0, d_sum = 0.0, w_sum = 0.0;
  const double n = static_cast<double>(distances.size());
  for (size_t i = 0; i < distances.size(); ++i) {
    d_sum += distances[i];
    w_sum += depths[i];
  }
  for (size_t i = 0; i < distances.size(); ++i) {
    const double w = depths[i] - w_sum / n;
    dw += w * (distances[i] - d_sum / n);
    ww += w * w;
  }
  return ww > 0.0 ? 2.0 * dw / ww : 0.0;
}

}  // namespace pfdm
