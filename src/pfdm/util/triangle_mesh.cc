#include "pfdm/util/triangle_mesh.h"

#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "Eigen/Geometry"
#include "pfdm/util/error.h"

namespace pfdm {

std::vector<std::vector<int>> BoundaryLoops(const TriangleMesh& mesh) {
  // Directed edges; an edge is on the boundary when its reverse is absent.
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) ++uses[{t[i], t[(i + 1) % 3]}];
  }
  std::map<int, int> next;  // Boundary edge a -> b, keyed by a.
  for (const auto& [edge, count] : uses) {
    if (uses.count({edge.second, edge.first}) > 0) continue;
    if (count != 1 || !next.emplace(edge.first, edge.second).second) {
      throw InputError("mesh boundary is not a set of simple loops at vertex " +
                       std::to_string(edge.first));
    }
  }
  std::vector<std::vector<int>> loops;
  while (!next.empty()) {
    std::vector<int> loop;
    int at = next.begin()->first;
    while (true) {
      const auto it = next.find(at);
      if (it == next.end()) break;
      loop.push_back(at);
      at = it->second;
      next.erase(it);
    }
    if (at != loop.front()) {
      throw InputError("mesh boundary is not a set of simple loops at vertex " +
                       std::to_string(at));
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

TriangleMesh CapBoundaryLoops(const TriangleMesh& mesh) {
  TriangleMesh closed = mesh;
  for (const std::vector<int>& loop : BoundaryLoops(mesh)) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int i : loop) centroid += mesh.points[i];
    centroid /= static_cast<double>(loop.size());
    const int c = static_cast<int>(closed.points.size());
    closed.points.push_back(centroid);
    // The surface runs a -> b along the loop, so the lid runs b -> a.
    for (size_t i = 0; i < loop.size(); ++i) {
      closed.triangles.push_back({loop[(i + 1) % loop.size()], loop[i], c});
    }
  }
  return closed;
}

double EnclosedVolume(const TriangleMesh& mesh) {
  // Relative to the first point, which keeps the sum's terms small.
  if (mesh.points.empty()) return 0.0;
  const Eigen::Vector3d origin = mesh.points.front();
  double six_volume = 0.0;
  for (const auto& t : mesh.triangles) {
    six_volume +=
        (mesh.points[t[0]] - origin)
            .dot(
                (mesh.points[t[1]] - origin).cross(mesh.points[t[2]] - origin));
  }
  return std::abs(six_volume) / 6.0;
}

double VolumeBelowPlane(const TriangleMesh& closed,
                        const Eigen::Vector3d& point,
                        const Eigen::Vector3d& normal) {
  double six_volume = 0.0;
  std::vector<Eigen::Vector3d> kept;
  for (const auto& t : closed.triangles) {
    // Sutherland-Hodgman against one plane: 0, 3 or 4 corners.
    kept.clear();
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d a = closed.points[t[i]] - point;
      const Eigen::Vector3d b = closed.points[t[(i + 1) % 3]] - point;
      const double da = normal.dot(a), db = normal.dot(b);
      if (da <= 0.0) kept.push_back(a);
      if ((da <= 0.0) != (db <= 0.0))
        kept.push_back(a + (b - a) * (da / (da - db)));
    }
    for (size_t i = 1; i + 1 < kept.size(); ++i) {
      six_volume += kept[0].dot(kept[i].cross(kept[i + 1]));
    }
  }
  return std::abs(six_volume) / 6.0;
}

}  // namespace pfdm
