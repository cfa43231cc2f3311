#include "pfdm/report/mesh_motion.h"

#include <algorithm>
#include <string>

#include "pfdm/report/surface_strain.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

double DistanceFromLine(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b) {
  const Eigen::Vector3d axis = (b - a).normalized();
  const Eigen::Vector3d d = p - a;
  return (d - d.dot(axis) * axis).norm();
}

}  // namespace

std::vector<MeshFrameMotion> MeasureMeshMotion(
    const std::vector<TriangleMesh>& frames) {
  if (frames.empty()) return {};
  const TriangleMesh& ed = frames.front();
  std::vector<int> rim;
  for (const auto& loop : BoundaryLoops(ed))
    rim.insert(rim.end(), loop.begin(), loop.end());
  if (rim.empty()) throw InputError("mesh has no open boundary (base rim)");
  auto rim_centre = [&](const TriangleMesh& mesh) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int i : rim) c += mesh.points[i];
    return Eigen::Vector3d(c / static_cast<double>(rim.size()));
  };
  const Eigen::Vector3d base0 = rim_centre(ed);
  int apex = 0;
  for (size_t i = 0; i < ed.points.size(); ++i) {
    if ((ed.points[i] - base0).norm() > (ed.points[apex] - base0).norm()) {
      apex = static_cast<int>(i);
    }
  }
  std::vector<double> rho0;
  for (const auto& p : ed.points)
    rho0.push_back(DistanceFromLine(p, ed.points[apex], base0));
  const double rho_floor = 0.2 * *std::max_element(rho0.begin(), rho0.end());

  std::vector<MeshFrameMotion> motion;
  for (size_t t = 0; t < frames.size(); ++t) {
    if (frames[t].points.size() != ed.points.size()) {
      throw InputError("mesh frame " + std::to_string(t) + " has " +
                       std::to_string(frames[t].points.size()) +
                       " vertices, frame 0 " +
                       std::to_string(ed.points.size()));
    }
    TriangleMesh mesh{frames[t].points, ed.triangles};
    MeshFrameMotion m;
    m.volume_ml = EnclosedVolume(CapBoundaryLoops(mesh)) / 1000.0;
    const Eigen::Vector3d base = rim_centre(mesh);
    const Eigen::Vector3d& tip = mesh.points[apex];
    m.length_mm = (base - tip).norm();
    if (t > 0) {
      m.longitudinal_shortening_percent =
          100.0 * (1.0 - m.length_mm / motion.front().length_mm);
    }
    double sum = 0.0;
    int counted = 0;
    for (size_t i = 0; i < mesh.points.size(); ++i) {
      if (rho0[i] < rho_floor) continue;
      sum += 1.0 - DistanceFromLine(mesh.points[i], tip, base) / rho0[i];
      ++counted;
    }
    m.radial_contraction_percent = 100.0 * sum / counted;
    const Eigen::Vector3d axis = (base0 - ed.points[apex]).normalized();
    double area = 0.0;
    for (const auto& tri : ed.triangles) {
      const Eigen::Vector3d& p0 = ed.points[tri[0]];
      const Eigen::Vector3d a0 = ed.points[tri[1]] - p0;
      const Eigen::Vector3d b0 = ed.points[tri[2]] - p0;
      const Eigen::Vector3d turn =
          axis.cross((p0 + (a0 + b0) / 3.0) - ed.points[apex]);
      const double weight = 0.5 * a0.cross(b0).norm();
      // At the apex vertex the turn has no direction.
      if (turn.norm() < 1e-9 || weight == 0.0) continue;
      const Eigen::Vector3d& p = mesh.points[tri[0]];
      const SurfaceStrain e = PlaneStrain(a0, b0, mesh.points[tri[1]] - p,
                                          mesh.points[tri[2]] - p, turn, axis);
      m.gcs_percent += weight * 100.0 * e.ecc;
      m.gls_percent += weight * 100.0 * e.ell;
      area += weight;
    }
    m.gcs_percent /= area;
    m.gls_percent /= area;
    motion.push_back(m);
  }
  return motion;
}

}  // namespace pfdm
