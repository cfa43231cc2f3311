#include "pfdm/fit/correspondence/frame_correspondence.h"

#include <algorithm>
#include <optional>

#include "pfdm/fit/correspondence/measured_depths.h"
#include "pfdm/fit/correspondence/surface_grid.h"
#include "pfdm/fit/correspondence/transmural.h"

namespace pfdm {
namespace {

// The points' depth ranks (QuantileDepths' bands or NeighbourhoodDepths),
// among those within the wall widened by the outlier band when that is
// positive; their measured depths where the contours place the walls.
std::vector<double> RankedDepths(const Model& model,
                                 const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<MaterialPoint>& material,
                                 const DepthRanking& ranking) {
  std::vector<Eigen::Vector3d> midwall;
  const std::vector<double> distances =
      MidwallDistances(model, points, material, &midwall);
  if (ranking.measured) return MeasuredDepths(model, material, distances);
  const std::vector<bool> ranked =
      ranking.outlier_band_mm > 0.0
          ? WithinWall(model, material, distances, ranking.outlier_band_mm)
          : std::vector<bool>(points.size(), true);
  if (ranking.neighbourhoods) {
    return NeighbourhoodDepths(midwall, distances, ranked);
  }
  std::vector<double> u;
  for (const MaterialPoint& m : material) u.push_back(m.u);
  return QuantileDepths(u, distances, ranked);
}

// In a solid, each listed point's surface: its contour's wall (layer_w), or
// for a tag whose depth is assigned, its RankedDepths rank among the
// listed tags; 0, the mid-wall, for the rest.
std::vector<double> SurfacesOf(const Model& model,
                               const std::vector<Eigen::Vector3d>& subset,
                               const std::vector<size_t>& which,
                               const std::vector<double>& layer_w,
                               const std::vector<bool>& assign_depth,
                               const std::vector<MaterialPoint>& closest,
                               const DepthRanking& ranking) {
  std::vector<double> surfaces(which.size(), 0.0);
  std::vector<size_t> tags;
  std::vector<Eigen::Vector3d> tag_points;
  std::vector<MaterialPoint> tag_material;
  for (size_t j = 0; j < which.size(); ++j) {
    surfaces[j] = layer_w[which[j]];
    if (!assign_depth[which[j]]) continue;
    tags.push_back(j);
    tag_points.push_back(subset[j]);
    tag_material.push_back(closest[j]);
  }
  if (tags.empty()) return surfaces;
  const std::vector<double> depths =
      RankedDepths(model, tag_points, tag_material, ranking);
  for (size_t t = 0; t < tags.size(); ++t) surfaces[tags[t]] = depths[t];
  return surfaces;
}

// The rows of `which` whose search starts on the mid-wall: all of them
// but, in a solid, the contour points whose wall is known (layer_w, not
// ranked), which are sought on that wall alone (the mid-wall's closest
// point was thrown away: half of both walls' searches).
std::vector<size_t> MidwallRows(const Model& model,
                                const std::vector<size_t>& which,
                                const std::vector<double>& layer_w,
                                const std::vector<bool>& assign_depth) {
  std::vector<size_t> rows;
  for (size_t j = 0; j < which.size(); ++j) {
    const size_t i = which[j];
    if (model.config.Solid() && layer_w[i] != 0.0 && !assign_depth[i]) {
      continue;
    }
    rows.push_back(j);
  }
  return rows;
}

// The rows of `surfaces` off the mid-wall: a solid's points sought on a
// wall or a layer, whose closest point there replaces the mid-wall's.
std::vector<size_t> OffMidwallRows(const std::vector<double>& surfaces) {
  std::vector<size_t> rows;
  for (size_t j = 0; j < surfaces.size(); ++j) {
    if (surfaces[j] != 0.0) rows.push_back(j);
  }
  return rows;
}

// The closest points of the listed rows of `subset` on their surfaces
// (`surfaces`, a value per row of `subset`; empty: the mid-wall), each
// search from its row's hint where `correspondence` has hints, written
// into those rows of closest, found and found_normals.
void SearchRows(const SurfaceGrid& grid, const Model& model,
                const std::vector<Eigen::Vector3d>& subset,
                const std::vector<size_t>& rows,
                const std::vector<double>& surfaces,
                const CorrespondenceOptions& correspondence,
                std::vector<MaterialPoint>* closest,
                std::vector<Eigen::Vector3d>* found,
                std::vector<Eigen::Vector3d>* found_normals) {
  CorrespondenceOptions listed = correspondence;
  listed.hints.clear();
  listed.surfaces.clear();
  std::vector<Eigen::Vector3d> points;
  for (size_t j : rows) {
    points.push_back(subset[j]);
    if (!correspondence.hints.empty()) {
      listed.hints.push_back(correspondence.hints[j]);
    }
    if (!surfaces.empty()) listed.surfaces.push_back(surfaces[j]);
  }
  std::vector<Eigen::Vector3d> found_rows, normal_rows;
  const std::vector<MaterialPoint> closest_rows = ClosestMaterialPointsFrom(
      grid, model, points, listed, &found_rows, &normal_rows);
  for (size_t k = 0; k < rows.size(); ++k) {
    (*closest)[rows[k]] = closest_rows[k];
    (*found)[rows[k]] = found_rows[k];
    (*found_normals)[rows[k]] = normal_rows[k];
  }
}

// Held depths (DepthRanking::hold): each tag whose depth was assigned is
// sought on its material point's layer, as a contour on its wall, and none
// is ranked.
struct Surfaces {
  std::vector<double> layer_w;
  std::vector<bool> assign_depth;
};
Surfaces HeldDepths(const std::vector<double>& layer_w,
                    const std::vector<bool>& assign_depth,
                    const std::vector<size_t>& which,
                    const std::vector<MaterialPoint>& material) {
  Surfaces held{layer_w, assign_depth};
  for (size_t i : which) {
    if (!assign_depth[i]) continue;
    held.layer_w[i] = material[i].w;
    held.assign_depth[i] = false;
  }
  return held;
}

}  // namespace

std::vector<MaterialPoint> Listed(const std::vector<MaterialPoint>& material,
                                  const std::vector<size_t>& which) {
  std::vector<MaterialPoint> listed;
  listed.reserve(which.size());
  for (size_t i : which) listed.push_back(material[i]);
  return listed;
}

double MaxDistance(const std::vector<Eigen::Vector3d>& a,
                   const std::vector<Eigen::Vector3d>& b) {
  double distance = 0.0;
  for (size_t j = 0; j < a.size(); ++j) {
    distance = std::max(distance, (a[j] - b[j]).norm());
  }
  return distance;
}

void UpdateClosest(const Model& model,
                   const std::vector<Eigen::Vector3d>& points,
                   const std::vector<size_t>& which, int num_threads,
                   const std::vector<double>& layer_w,
                   const std::vector<bool>& assign_depth, bool warm,
                   std::vector<MaterialPoint>* material,
                   std::vector<Eigen::Vector3d>* normals,
                   std::vector<Eigen::Vector3d>* found,
                   const DepthRanking& ranking, SurfaceGrid* grid) {
  // A frame of tracked tags alone has nothing to search, and its grid need
  // not follow the model: 7 % of a tracked frame's instructions at 2,000
  // tags.
  if (which.empty()) {
    found->clear();
    return;
  }
  if (ranking.hold && warm && model.config.Solid()) {
    const Surfaces held = HeldDepths(layer_w, assign_depth, which, *material);
    DepthRanking unranked = ranking;
    unranked.hold = false;
    UpdateClosest(model, points, which, num_threads, held.layer_w,
                  held.assign_depth, warm, material, normals, found, unranked,
                  grid);
    return;
  }
  std::vector<Eigen::Vector3d> subset;
  for (size_t i : which) subset.push_back(points[i]);
  // One grid for the mid-wall search and, in a solid, the walls' after it:
  // both searches start from the mid-wall's samples.
  std::optional<SurfaceGrid> own_grid;
  if (grid == nullptr) {
    grid = &own_grid.emplace(model);
  } else {
    grid->Follow(model);
  }
  CorrespondenceOptions correspondence;
  correspondence.num_threads = num_threads;
  if (warm) {
    for (size_t i : which) correspondence.hints.push_back((*material)[i]);
  }
  found->resize(which.size());
  std::vector<Eigen::Vector3d> found_normals(which.size());
  std::vector<MaterialPoint> closest(which.size());
  SearchRows(*grid, model, subset,
             MidwallRows(model, which, layer_w, assign_depth), {},
             correspondence, &closest, found, &found_normals);
  if (model.config.Solid()) {
    const std::vector<double> surfaces = SurfacesOf(
        model, subset, which, layer_w, assign_depth, closest, ranking);
    SearchRows(*grid, model, subset, OffMidwallRows(surfaces), surfaces,
               correspondence, &closest, found, &found_normals);
  }
  for (size_t j = 0; j < which.size(); ++j) {
    (*material)[which[j]] = closest[j];
    (*normals)[which[j]] = PullsAlongNormal(model.config, closest[j])
                               ? found_normals[j]
                               : Eigen::Vector3d::Zero();
  }
}

void RerankDepths(const Model& model,
                  const std::vector<Eigen::Vector3d>& points,
                  const std::vector<size_t>& which,
                  std::vector<MaterialPoint>* material,
                  const DepthRanking& ranking, double* moved_mm) {
  std::vector<Eigen::Vector3d> subset;
  std::vector<MaterialPoint> subset_material;
  for (size_t i : which) {
    subset.push_back(points[i]);
    subset_material.push_back((*material)[i]);
  }
  const std::vector<double> depths =
      RankedDepths(model, subset, subset_material, ranking);
  std::vector<Eigen::Vector3d> before;
  if (moved_mm != nullptr) before = WorldPoints(model, subset_material);
  for (size_t j = 0; j < which.size(); ++j) {
    subset_material[j].w = depths[j];
    (*material)[which[j]].w = depths[j];
  }
  if (moved_mm == nullptr) return;
  const std::vector<Eigen::Vector3d> after =
      WorldPoints(model, subset_material);
  *moved_mm = 0.0;
  for (size_t j = 0; j < which.size(); ++j) {
    *moved_mm = std::max(*moved_mm, (after[j] - before[j]).norm());
  }
}

}  // namespace pfdm
