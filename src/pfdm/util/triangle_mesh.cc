#include "pfdm/util/triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "Eigen/Geometry"
#include "pfdm/util/error.h"

namespace pfdm {

std::vector<std::vector<int>> BoundaryLoops(const TriangleMesh& mesh) {
  // Directed edges grouped by their first vertex (a counting sort, then
  // each vertex's few targets sorted); an edge is on the boundary when its
  // reverse is absent.  Not a map: the cavity volume closes a 97 x 128
  // surface per frame, and a map's nodes were most of writing a fit's
  // outputs.
  using Edge = std::pair<int, int>;
  int lowest = 0, highest = -1;
  for (const auto& t : mesh.triangles) {
    for (int v : t)
      lowest = std::min(lowest, v), highest = std::max(highest, v);
  }
  const size_t num_vertices = static_cast<size_t>(highest - lowest + 1);
  std::vector<int> first_target(num_vertices + 1, 0);
  for (const auto& t : mesh.triangles) {
    for (int v : t) ++first_target[v - lowest + 1];
  }
  for (size_t v = 0; v < num_vertices; ++v) {
    first_target[v + 1] += first_target[v];
  }
  std::vector<int> targets(first_target.back());
  std::vector<int> filled(first_target.begin(), first_target.end() - 1);
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      targets[filled[t[i] - lowest]++] = t[(i + 1) % 3];
    }
  }
  const auto begin = [&](int v) {
    return targets.begin() + first_target[v - lowest];
  };
  const auto end = [&](int v) {
    return targets.begin() + first_target[v - lowest + 1];
  };
  // Boundary edges a -> b in order of a, each a once.
  std::vector<Edge> next;
  for (size_t index = 0; index < num_vertices; ++index) {
    const int a = static_cast<int>(index) + lowest;
    std::sort(begin(a), end(a));
  }
  for (size_t index = 0; index < num_vertices; ++index) {
    const int a = static_cast<int>(index) + lowest;
    for (auto it = begin(a); it != end(a);) {
      const int b = *it;
      size_t count = 0;
      for (; it != end(a) && *it == b; ++it) ++count;
      if (std::binary_search(begin(b), end(b), a)) continue;
      if (count != 1 || (!next.empty() && next.back().first == a)) {
        throw InputError(
            "mesh boundary is not a set of simple loops at vertex " +
            std::to_string(a));
      }
      next.emplace_back(a, b);
    }
  }
  // Each loop starts at the smallest vertex left and follows its edges.
  std::vector<bool> used(next.size(), false);
  const auto find = [&](int a) {
    const auto it = std::lower_bound(
        next.begin(), next.end(), Edge(a, 0),
        [](const Edge& x, const Edge& y) { return x.first < y.first; });
    const size_t at = static_cast<size_t>(it - next.begin());
    return at < next.size() && next[at].first == a && !used[at] ? at
                                                                : next.size();
  };
  std::vector<std::vector<int>> loops;
  for (size_t first = 0; first < next.size(); ++first) {
    if (used[first]) continue;
    std::vector<int> loop;
    int at = next[first].first;
    for (size_t edge = first; edge < next.size(); edge = find(at)) {
      loop.push_back(at);
      at = next[edge].second;
      used[edge] = true;
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

namespace {

// Triangles per block of PlaneVolume: a ring's strip of a cavity's surface
// at 128 meridians, of which a knot's step moves some 6-20 % (17 % on the
// README example's steps, the apex's spans wider in u).
constexpr size_t kBlockTriangles = 256;

// Six times the signed volume of the part of triangle (p0, p1, p2), taken
// from a point of the plane, below the plane: clipped to that side.
double SixVolumeBelow(const Eigen::Vector3d (&p)[3],
                      const Eigen::Vector3d& normal) {
  const double d[3] = {normal.dot(p[0]), normal.dot(p[1]), normal.dot(p[2])};
  // Most triangles lie wholly on one side: the clip below keeps all
  // three corners in order, or none.  (The uncertainty's many
  // measurements of a cavity spent a fifth of their time here.)
  if (d[0] <= 0.0 && d[1] <= 0.0 && d[2] <= 0.0) {
    return p[0].dot(p[1].cross(p[2]));
  }
  if (d[0] > 0.0 && d[1] > 0.0 && d[2] > 0.0) return 0.0;
  // Sutherland-Hodgman against one plane: 3 or 4 corners.
  Eigen::Vector3d kept[4];
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (d[i] <= 0.0) kept[count++] = p[i];
    if ((d[i] <= 0.0) != (d[j] <= 0.0)) {
      kept[count++] = p[i] + (p[j] - p[i]) * (d[i] / (d[i] - d[j]));
    }
  }
  double six_volume = 0.0;
  for (int i = 1; i + 1 < count; ++i) {
    six_volume += kept[0].dot(kept[i].cross(kept[i + 1]));
  }
  return six_volume;
}

// Six times the signed volume below the plane of the triangles [begin,
// end), about `point`; a zero normal clips nothing (a plain loop: the
// clip's tests had made a flat lid's volume several times dearer).
double BlockSixVolume(const TriangleMesh& mesh, size_t begin, size_t end,
                      const Eigen::Vector3d& point,
                      const Eigen::Vector3d& normal) {
  double six_volume = 0.0;
  if (normal == Eigen::Vector3d::Zero()) {
    for (size_t t = begin; t < end; ++t) {
      const std::array<int, 3>& c = mesh.triangles[t];
      six_volume +=
          (mesh.points[c[0]] - point)
              .dot(
                  (mesh.points[c[1]] - point).cross(mesh.points[c[2]] - point));
    }
    return six_volume;
  }
  for (size_t t = begin; t < end; ++t) {
    const std::array<int, 3>& c = mesh.triangles[t];
    const Eigen::Vector3d p[3] = {mesh.points[c[0]] - point,
                                  mesh.points[c[1]] - point,
                                  mesh.points[c[2]] - point};
    six_volume += SixVolumeBelow(p, normal);
  }
  return six_volume;
}

}  // namespace

double SixVolumeBelowPlane(const TriangleMesh& closed,
                           const Eigen::Vector3d& point,
                           const Eigen::Vector3d& normal) {
  const size_t count = closed.triangles.size();
  double six_volume = 0.0;
  for (size_t begin = 0; begin < count; begin += kBlockTriangles) {
    six_volume += BlockSixVolume(
        closed, begin, std::min(count, begin + kBlockTriangles), point, normal);
  }
  return six_volume;
}

double VolumeBelowPlane(const TriangleMesh& closed,
                        const Eigen::Vector3d& point,
                        const Eigen::Vector3d& normal) {
  return std::abs(SixVolumeBelowPlane(closed, point, normal)) / 6.0;
}

PlaneVolume::PlaneVolume(const TriangleMesh& closed,
                         const Eigen::Vector3d& point,
                         const Eigen::Vector3d& normal)
    : point_(point), normal_(normal) {
  const size_t count = closed.triangles.size();
  for (size_t begin = 0; begin < count; begin += kBlockTriangles) {
    Block block;
    block.begin = begin;
    block.end = std::min(count, begin + kBlockTriangles);
    block.low = closed.points.size();
    for (size_t t = block.begin; t < block.end; ++t) {
      for (int corner : closed.triangles[t]) {
        block.low = std::min(block.low, static_cast<size_t>(corner));
        block.high = std::max(block.high, static_cast<size_t>(corner));
      }
    }
    block.six_volume = SixVolume(closed, block);
    blocks_.push_back(block);
  }
}

double PlaneVolume::SixVolume(const TriangleMesh& mesh,
                              const Block& block) const {
  return BlockSixVolume(mesh, block.begin, block.end, point_, normal_);
}

double PlaneVolume::six_volume() const {
  double six_volume = 0.0;
  for (const Block& block : blocks_) six_volume += block.six_volume;
  return six_volume;
}

double PlaneVolume::MovedSixVolume(const TriangleMesh& moved, size_t first,
                                   size_t last) const {
  double six_volume = 0.0;
  for (const Block& block : blocks_) {
    const bool touched = block.low < last && block.high >= first;
    six_volume += touched ? SixVolume(moved, block) : block.six_volume;
  }
  return six_volume;
}

double PlaneVolume::volume() const { return std::abs(six_volume()) / 6.0; }

double PlaneVolume::Moved(const TriangleMesh& moved, size_t first,
                          size_t last) const {
  return std::abs(MovedSixVolume(moved, first, last)) / 6.0;
}

}  // namespace pfdm
