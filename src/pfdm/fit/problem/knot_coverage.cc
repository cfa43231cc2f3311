#include "pfdm/fit/problem/knot_coverage.h"

#include <cmath>

namespace pfdm {
namespace {

int SectorOf(double v) {
  const double turn = (v + M_PI) / (2.0 * M_PI);
  const int sector = static_cast<int>(std::floor(turn * kCoverageSectors));
  return ((sector % kCoverageSectors) + kCoverageSectors) % kCoverageSectors;
}

}  // namespace

SectorCounts KnotSectorCounts(const KnotGrid& grid,
                              const std::vector<MaterialPoint>& material) {
  SectorCounts counts(grid.num_knots(),
                      std::vector<double>(kCoverageSectors, 0.0));
  for (const MaterialPoint& m : material) {
    const KnotSpan span = grid.Span(m.u);
    const int sector = SectorOf(m.v);
    counts[span.k0][sector] += 1.0 - span.weight;
    if (span.k0 + 1 < grid.num_knots()) {
      counts[span.k0 + 1][sector] += span.weight;
    }
  }
  return counts;
}

std::vector<bool> CoveredKnots(const KnotGrid& grid,
                               const std::vector<MaterialPoint>& material,
                               double min_share, int min_sectors) {
  const SectorCounts counts = KnotSectorCounts(grid, material);
  const double even_share =
      static_cast<double>(material.size()) / grid.num_knots();
  std::vector<bool> covered(grid.num_knots(), false);
  for (int k = 0; k < grid.num_knots(); ++k) {
    double total = 0.0;
    int filled = 0;
    for (double count : counts[k]) {
      total += count;
      filled += count >= 1.0;
    }
    covered[k] = total >= min_share * even_share && filled >= min_sectors;
  }
  return covered;
}

std::vector<FunctionValues> CoveredRadiiScales(
    const KnotGrid& grid, const std::vector<MaterialPoint>& material,
    const FunctionValues& scales, double radii_scale) {
  std::vector<FunctionValues> per_knot(grid.num_knots(), scales);
  const std::vector<bool> covered =
      CoveredKnots(grid, material, kCoveredKnotShare, kCoveredKnotSectors);
  for (int k = 0; k < grid.num_knots(); ++k) {
    if (!covered[k]) continue;
    per_knot[k][kA1] *= radii_scale;
    per_knot[k][kA2] *= radii_scale;
  }
  return per_knot;
}

}  // namespace pfdm
