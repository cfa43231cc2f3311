#include "pfdm/fit/correspondence/transmural.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <utility>

#include "pfdm/util/error.h"
#include "pfdm/util/point_cloud_tree.h"
#include "pfdm/util/stride.h"

namespace pfdm {
namespace {

// Tags whose neighbour WallSpreadMm compares, at most, and tags it takes
// them from.
constexpr size_t kMaxSpreadPairs = 4096;
constexpr size_t kMaxSpreadNeighbours = 16384;
// The standard deviation of a Gaussian over its median absolute deviation.
constexpr double kMadToSigma = 1.4826;

// The tags WallSpreadMm and NeighbourDepartures seek neighbours among: every
// step-th, at most kMaxSpreadNeighbours, 0.9 mm apart on an LV's mid-wall
// (0.5 mm for all of 50,000 tags), where the fit's error changes too little
// to tell them apart; building the tree of all 50,000 took 13 ms.
struct NeighbourCloud {
  NeighbourCloud(const std::vector<Eigen::Vector3d>& midwall_points,
                 const std::vector<double>& all_distances)
      : step(StrideForAtMost(midwall_points.size(), kMaxSpreadNeighbours)) {
    for (size_t i = 0; i < midwall_points.size(); i += step) {
      cloud.points.push_back(midwall_points[i]);
      distances.push_back(all_distances[i]);
    }
  }
  size_t step;
  PointCloud cloud;
  std::vector<double> distances;
};

// The median of *values (reordered); 0 for none.
double Median(std::vector<double>* values) {
  const size_t n = values->size();
  if (n == 0) return 0.0;
  auto middle = values->begin() + n / 2;
  std::nth_element(values->begin(), middle, values->end());
  if (n % 2 == 1) return *middle;
  return 0.5 * (*middle + *std::max_element(values->begin(), middle));
}

// Tags sorted by u in bands of a sixteenth of them, at least kMinBand; the
// last band takes the remainder rather than leaving a runt.
std::vector<std::vector<size_t>> LatitudeBands(const std::vector<double>& u) {
  const size_t n = u.size();
  std::vector<size_t> by_u(n);
  std::iota(by_u.begin(), by_u.end(), 0);
  std::stable_sort(by_u.begin(), by_u.end(),
                   [&](size_t a, size_t b) { return u[a] < u[b]; });
  const size_t band = std::max<size_t>(kMinBand, n / 16);
  std::vector<std::vector<size_t>> bands;
  for (size_t begin = 0, end = 0; begin < n; begin = end) {
    end = std::min(n, begin + band);
    if (n - end < band / 2) end = n;
    bands.emplace_back(by_u.begin() + begin, by_u.begin() + end);
  }
  return bands;
}

// The p-quantile of sorted values, interpolated between neighbours.
double Quantile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0.0;
  const double at = p * (sorted.size() - 1);
  const size_t below = static_cast<size_t>(at);
  if (below + 1 >= sorted.size()) return sorted.back();
  return sorted[below] + (at - below) * (sorted[below + 1] - sorted[below]);
}

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
  const NeighbourCloud sample(midwall_points, distances);
  const size_t num_points = sample.cloud.points.size();
  if (num_points < 2) return 0.0;
  PointCloudTree tree(3, sample.cloud,
                      nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  // The mean over at most kMaxSpreadPairs tags' pairs (every stride-th)
  // estimates the mean over all to about 1 % (one in sqrt(2 x 4096)),
  // plenty for a threshold.
  const size_t stride = StrideForAtMost(num_points, kMaxSpreadPairs);
  double sum_squared = 0.0;
  size_t pairs = 0;
  for (size_t i = 0; i < num_points; i += stride, ++pairs) {
    const size_t j = NearestOther(tree, sample.cloud, i);
    const double difference = sample.distances[i] - sample.distances[j];
    sum_squared += difference * difference;
  }
  return std::sqrt(6.0 * sum_squared / pairs);
}

namespace {

// The departures of the listed tags (NeighbourDepartures') from their
// neighbours among `sample`, whose tree is `tree`; when `lists` is given,
// tag k's neighbours (indices into the sample, nearest first, itself left
// out) in its entries k * kOutlierNeighbours on, kNoNeighbour past the
// last.
constexpr unsigned int kNoNeighbour = ~0u;
std::vector<double> DeparturesOf(
    const NeighbourCloud& sample, const PointCloudTree& tree,
    const std::vector<Eigen::Vector3d>& midwall_points,
    const std::vector<double>& distances, const std::vector<size_t>& tags,
    std::vector<unsigned int>* lists = nullptr) {
  const size_t num_points = sample.cloud.points.size();
  std::vector<double> departures(tags.size(), 0.0);
  if (lists != nullptr) {
    lists->assign(tags.size() * kOutlierNeighbours, kNoNeighbour);
  }
  if (num_points < 2) return departures;
  const size_t wanted = std::min<size_t>(kOutlierNeighbours + 1, num_points);
  std::vector<unsigned int> nearest(wanted);
  std::vector<double> distance_squared(wanted);
  std::vector<double> neighbours;
  for (size_t k = 0; k < tags.size(); ++k) {
    const size_t i = tags[k];
    const size_t found =
        tree.knnSearch(midwall_points[i].data(), wanted, nearest.data(),
                       distance_squared.data());
    // The tag itself, when it is among the sampled ones, is no neighbour.
    const bool sampled = i % sample.step == 0;
    neighbours.clear();
    for (size_t n = 0; n < found; ++n) {
      if (sampled && nearest[n] == i / sample.step) continue;
      if (neighbours.size() < kOutlierNeighbours) {
        if (lists != nullptr) {
          (*lists)[k * kOutlierNeighbours + neighbours.size()] = nearest[n];
        }
        neighbours.push_back(sample.distances[nearest[n]]);
      }
    }
    departures[k] = distances[i] - Median(&neighbours);
  }
  return departures;
}

// WallSpreadMm of the sample's inliers, each tag paired with the first
// inlier of its neighbour list (DeparturesOf's `lists` of every sampled
// tag): the nearest inlier, as WallSpreadMm's tree of the inliers would
// find it, without building that tree (a fifth of the spread's time at
// 20,000 tags).  Only a tag with no inlier among its neighbours asks that
// tree.
double InlierSpreadMm(const NeighbourCloud& sample,
                      const std::vector<bool>& inlier,
                      const std::vector<unsigned int>& lists) {
  std::vector<size_t> kept;
  for (size_t s = 0; s < inlier.size(); ++s) {
    if (inlier[s]) kept.push_back(s);
  }
  if (kept.size() < 2) return 0.0;
  PointCloud kept_cloud;
  std::optional<PointCloudTree> kept_tree;
  const auto nearest_kept = [&](size_t r) {
    if (!kept_tree) {
      kept_cloud.points = KeptEntries(sample.cloud.points, inlier);
      kept_tree.emplace(3, kept_cloud,
                        nanoflann::KDTreeSingleIndexAdaptorParams(10));
      kept_tree->buildIndex();
    }
    return kept[NearestOther(*kept_tree, kept_cloud, r)];
  };
  // As WallSpreadMm: every stride-th inlier's pair.
  const size_t stride = StrideForAtMost(kept.size(), kMaxSpreadPairs);
  double sum_squared = 0.0;
  size_t pairs = 0;
  for (size_t r = 0; r < kept.size(); r += stride, ++pairs) {
    const size_t s = kept[r];
    size_t j = kNoNeighbour;
    for (size_t n = 0; n < kOutlierNeighbours; ++n) {
      const unsigned int candidate = lists[s * kOutlierNeighbours + n];
      if (candidate == kNoNeighbour) break;
      if (inlier[candidate]) {
        j = candidate;
        break;
      }
    }
    if (j == kNoNeighbour) j = nearest_kept(r);
    const double difference = sample.distances[s] - sample.distances[j];
    sum_squared += difference * difference;
  }
  return std::sqrt(6.0 * sum_squared / pairs);
}

// Every tag's index, or the sampled ones' (every step-th).
std::vector<size_t> EveryNth(size_t count, size_t step) {
  std::vector<size_t> tags;
  for (size_t i = 0; i < count; i += step) tags.push_back(i);
  return tags;
}

}  // namespace

std::vector<double> NeighbourDepartures(
    const std::vector<Eigen::Vector3d>& midwall_points,
    const std::vector<double>& distances) {
  const NeighbourCloud sample(midwall_points, distances);
  PointCloudTree tree(3, sample.cloud,
                      nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  return DeparturesOf(sample, tree, midwall_points, distances,
                      EveryNth(distances.size(), 1));
}

RobustWallSpread RobustWallSpreadMm(
    const std::vector<Eigen::Vector3d>& midwall_points,
    const std::vector<double>& distances) {
  RobustWallSpread result;
  // Among the tags the neighbours are sought from: past 16,384 tags, a
  // departure for every one of them cost frame 0 a fifth of its time.
  const NeighbourCloud sample(midwall_points, distances);
  PointCloudTree tree(3, sample.cloud,
                      nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  result.step = sample.step;
  std::vector<unsigned int> lists;
  const std::vector<double> departures =
      DeparturesOf(sample, tree, midwall_points, distances,
                   EveryNth(distances.size(), sample.step), &lists);
  std::vector<double> sizes;
  sizes.reserve(departures.size());
  for (double d : departures) sizes.push_back(std::abs(d));
  result.fence_mm =
      std::max(kMinOutlierMm, kOutlierScales * kMadToSigma * Median(&sizes));
  result.inlier.resize(departures.size());
  for (size_t k = 0; k < departures.size(); ++k) {
    result.inlier[k] = std::abs(departures[k]) <= result.fence_mm;
    if (!result.inlier[k]) ++result.outliers;
  }
  result.spread_mm = InlierSpreadMm(sample, result.inlier, lists);
  return result;
}

std::vector<bool> TagInliers(const RobustWallSpread& spread,
                             const std::vector<Eigen::Vector3d>& midwall_points,
                             const std::vector<double>& distances) {
  if (spread.step == 1) return spread.inlier;
  const std::vector<double> departures =
      NeighbourDepartures(midwall_points, distances);
  std::vector<bool> inlier(departures.size());
  for (size_t i = 0; i < departures.size(); ++i) {
    inlier[i] = std::abs(departures[i]) <= spread.fence_mm;
  }
  return inlier;
}

std::vector<double> QuantileDepths(const std::vector<double>& u,
                                   const std::vector<double>& distances) {
  return QuantileDepths(u, distances, std::vector<bool>(u.size(), true));
}

std::vector<double> QuantileDepths(const std::vector<double>& u,
                                   const std::vector<double>& distances,
                                   const std::vector<bool>& ranked) {
  std::vector<double> depths(u.size(), 0.0);
  for (const std::vector<size_t>& band : LatitudeBands(u)) {
    std::vector<size_t> members;
    for (size_t i : band) {
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

std::vector<double> NeighbourhoodDepths(
    const std::vector<Eigen::Vector3d>& midwall_points,
    const std::vector<double>& distances, const std::vector<bool>& ranked) {
  std::vector<double> depths(distances.size(), 0.0);
  std::vector<size_t> members;
  PointCloud cloud;
  for (size_t i = 0; i < distances.size(); ++i) {
    if (ranked[i]) {
      members.push_back(i);
      cloud.points.push_back(midwall_points[i]);
    } else {
      depths[i] = distances[i] < 0.0 ? -1.0 : 1.0;
    }
  }
  if (members.empty()) return depths;
  PointCloudTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  const size_t wanted = std::min(
      members.size(),
      std::max<size_t>(kMinBand, members.size() / kDepthNeighbourhoods));
  std::vector<unsigned int> nearest(wanted);
  std::vector<double> distance_squared(wanted);
  for (size_t i : members) {
    const size_t found =
        tree.knnSearch(midwall_points[i].data(), wanted, nearest.data(),
                       distance_squared.data());
    // Its rank among them, ties (itself one) counted half.
    double below = 0.0;
    for (size_t k = 0; k < found; ++k) {
      const double d = distances[members[nearest[k]]];
      below += d < distances[i] ? 1.0 : d == distances[i] ? 0.5 : 0.0;
    }
    depths[i] = 2.0 * below / static_cast<double>(found) - 1.0;
  }
  return depths;
}

std::vector<bool> InsideTheWall(const std::vector<double>& u,
                                const std::vector<double>& distances) {
  std::vector<bool> inside(u.size(), true);
  for (const std::vector<size_t>& members : LatitudeBands(u)) {
    std::vector<double> sorted;
    sorted.reserve(members.size());
    for (size_t i : members) sorted.push_back(distances[i]);
    std::sort(sorted.begin(), sorted.end());
    const double middle = Quantile(sorted, 0.5);
    const double fence =
        kWallFenceIqr * (Quantile(sorted, 0.75) - Quantile(sorted, 0.25));
    for (size_t i : members) {
      inside[i] = std::abs(distances[i] - middle) <= fence;
    }
  }
  return inside;
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

double SigmaFromChiSquared2(std::vector<double>* squares, double scale,
                            bool robust) {
  if (squares->empty()) return 0.0;
  if (!robust) {
    double sum = 0.0;
    for (double square : *squares) sum += square;
    return std::sqrt(sum / (2.0 * scale * squares->size()));
  }
  const auto middle = squares->begin() + squares->size() / 2;
  std::nth_element(squares->begin(), middle, squares->end());
  return std::sqrt(*middle / (2.0 * scale * std::log(2.0)));
}

double TangentialNoiseMm(const Model& model,
                         const std::vector<Eigen::Vector3d>& residuals,
                         const std::vector<MaterialPoint>& material,
                         const std::vector<size_t>& which, bool robust,
                         const std::vector<double>* stretch_squared) {
  std::vector<double> squares;
  squares.reserve(which.size());
  for (size_t k = 0; k < which.size(); ++k) {
    const size_t i = which[k];
    const MaterialPoint& m = material[i];
    const Eigen::Vector3d n = SurfaceNormal(model, m.u, m.v, m.w);
    const double gain =
        stretch_squared == nullptr ? 1.0 : 4.0 / (2.0 + (*stretch_squared)[k]);
    squares.push_back(gain *
                      (residuals[i] - residuals[i].dot(n) * n).squaredNorm());
  }
  // Each tangential direction carries 2 sigma^2.
  return SigmaFromChiSquared2(&squares, 2.0, robust);
}

double DeconvolvedThickness(double h_obs, double sigma, bool squeezed) {
  if (squeezed) {
    if (!(h_obs > 0.0)) return h_obs;
    double h = h_obs;
    for (int i = 0; i < 50; ++i) {
      const double x = std::min(sigma / h, 0.2);
      h = h_obs / (1.0 + x * x * (19.77 - 62.11 * x + 85.48 * x * x));
    }
    return h;
  }
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
