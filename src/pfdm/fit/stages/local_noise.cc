#include "pfdm/fit/stages/local_noise.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "pfdm/fit/problem/gauge.h"
#include "pfdm/fit/problem/local_fit.h"
#include "pfdm/fit/residuals/robust_loss.h"
#include "pfdm/fit/stages/local_stage.h"
#include "pfdm/util/parallel_for.h"

namespace pfdm {
namespace {

// `surface` moved by one draw of noise: a point along_normal along its
// normal, the others in every coordinate.
std::vector<Eigen::Vector3d> Noisy(const std::vector<Eigen::Vector3d>& surface,
                                   const std::vector<Eigen::Vector3d>& normals,
                                   const std::vector<bool>& along_normal,
                                   double sigma_mm, std::mt19937* random) {
  std::normal_distribution<double> noise(0.0, sigma_mm);
  std::vector<Eigen::Vector3d> out = surface;
  for (size_t i = 0; i < out.size(); ++i) {
    if (along_normal[i]) {
      out[i] += noise(*random) * normals[i];
    } else {
      out[i] += Eigen::Vector3d(noise(*random), noise(*random), noise(*random));
    }
  }
  return out;
}

// The points that can be the highest or hold it up (TopHeight's support
// below it) in a draw of noise of sd sigma_mm: within 8 sigma and the
// outlier band of `top`.  The rest cannot change it, and with a robust
// loss each draw searches its points' closest points.
std::vector<Eigen::Vector3d> NearTheTop(
    const std::vector<Eigen::Vector3d>& points, double top, double sigma_mm,
    const FitOptions& options, const Model& model) {
  const double band = options.loss != "none"
                          ? OutlierBandMm(options.loss, options.loss_scale_mm)
                          : 0.0;
  const Eigen::Vector3d axis = model.Rotation().col(2);
  const Eigen::Vector3d center(model.state.center.data());
  std::vector<Eigen::Vector3d> near;
  for (const Eigen::Vector3d& p : points) {
    if ((p - center).dot(axis) >= top - 8.0 * sigma_mm - band) {
      near.push_back(p);
    }
  }
  return near;
}

}  // namespace

std::vector<std::vector<double>> LocalNoiseDraws(
    const FramePoints& points, const std::vector<MaterialPoint>& material,
    const FitOptions& options, const Model& model, double sigma_mm, int draws) {
  std::vector<std::vector<double>> fields;
  if (!options.local.enabled || !(sigma_mm > 0.0) || material.empty()) {
    return fields;
  }
  Model global = model;
  global.state.local = LocalField();
  const std::vector<bool> sliding = LocalSlidingPoints(points);
  // A point whose material point was searched on this frame (contours,
  // and tags on their first) keeps only its noise along the normal: the
  // search moved it along the surface by the rest.
  const std::vector<bool>& searched = points.sliding;
  std::vector<Eigen::Vector3d> surface;
  const std::vector<Eigen::Vector3d> normals =
      SurfaceNormals(global, material, &surface);
  // The draws' noise in their order, whatever the threads.
  std::mt19937 random(1000003u + static_cast<unsigned>(points.index));
  std::vector<std::vector<Eigen::Vector3d>> noisy;
  for (int k = 0; k < draws; ++k) {
    noisy.push_back(Noisy(surface, normals, searched, sigma_mm, &random));
  }
  // One solver a thread: the draws' points, weights and grid are the same,
  // so each factorizes once, to the same bits.
  const int threads = options.solver.num_threads;
  std::vector<LocalDirectSolver> direct(ParallelWorkers(draws, threads));
  fields.resize(draws);
  std::vector<char> usable(draws, 0);
  ParallelFor(draws, threads, [&](int worker, size_t k) {
    Model fitted = global;
    const SolverReport report = FitLocalField(
        noisy[k], material, sliding, options, &fitted, &direct[worker]);
    usable[k] = report.usable;
    fields[k] = fitted.state.local.Coefficients();
  });
  if (std::find(usable.begin(), usable.end(), 0) != usable.end()) return {};
  return fields;
}

std::vector<double> LengthNoiseDraws(const FramePoints& points,
                                     const std::vector<MaterialPoint>& material,
                                     const FitOptions& options,
                                     const Model& model, double sigma_mm,
                                     int draws) {
  std::vector<double> stretches;
  if (!(sigma_mm > 0.0) || material.empty()) return stretches;
  std::vector<Eigen::Vector3d> all;
  SurfaceNormals(model, material, &all);
  const double top = TopHeight(all, options, model);
  const double length = top - ApexHeight(model);
  if (!std::isfinite(top) || !(length > 0.0)) return stretches;
  const std::vector<Eigen::Vector3d> surface =
      NearTheTop(all, top, sigma_mm, options, model);
  const std::vector<Eigen::Vector3d> no_normals(surface.size());
  const std::vector<bool> every_coordinate(surface.size(), false);
  std::mt19937 random(2000003u + static_cast<unsigned>(points.index));
  for (int k = 0; k < draws; ++k) {
    const double moved = TopHeight(
        Noisy(surface, no_normals, every_coordinate, sigma_mm, &random),
        options, model);
    if (!std::isfinite(moved)) return {};
    stretches.push_back((moved - top) / length);
  }
  return stretches;
}

}  // namespace pfdm
