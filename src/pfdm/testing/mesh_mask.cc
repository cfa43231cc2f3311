#include "pfdm/testing/mesh_mask.h"

#include <algorithm>
#include <cmath>
#include <queue>

#include "Eigen/Geometry"
#include "Eigen/LU"

namespace pfdm {

namespace {

using Segment = std::pair<Eigen::Vector2d, Eigen::Vector2d>;

// The closed mesh's cut by the plane z = k, in voxel coordinates (i, j).  A
// vertex on the plane counts as above it, so no edge is cut twice.
std::vector<Segment> Cut(const TriangleMesh& closed,
                         const Eigen::Matrix4d& voxel_from_world, int k) {
  std::vector<Eigen::Vector3d> voxel;
  voxel.reserve(closed.points.size());
  for (const Eigen::Vector3d& p : closed.points) {
    voxel.push_back((voxel_from_world * p.homogeneous()).head<3>());
  }
  std::vector<Segment> segments;
  for (const std::array<int, 3>& triangle : closed.triangles) {
    std::vector<Eigen::Vector2d> ends;
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d& a = voxel[triangle[e]];
      const Eigen::Vector3d& b = voxel[triangle[(e + 1) % 3]];
      const double da = a.z() - k, db = b.z() - k;
      if ((da >= 0) == (db >= 0)) continue;
      ends.push_back((a + (b - a) * (da / (da - db))).head<2>());
    }
    if (ends.size() == 2) segments.emplace_back(ends[0], ends[1]);
  }
  return segments;
}

// The stack of frame 0: see MakeMeshMask.
StackGeometry StackOf(const MeshMaskFrame& frame, double in_plane_mm,
                      double slice_mm) {
  const TriangleMesh& endo = frame.lv_endocardium;
  Eigen::Vector3d rim = Eigen::Vector3d::Zero();
  int rim_points = 0;
  for (const std::vector<int>& loop : BoundaryLoops(endo)) {
    for (int v : loop) rim += endo.points[v];
    rim_points += static_cast<int>(loop.size());
  }
  rim /= rim_points;
  Eigen::Vector3d apex = rim;
  for (const Eigen::Vector3d& p : endo.points) {
    if ((p - rim).norm() > (apex - rim).norm()) apex = p;
  }
  StackGeometry stack;
  stack.origin = rim;
  stack.to_apex = (apex - rim).normalized();
  stack.in_plane_mm = in_plane_mm;
  stack.slice_mm = slice_mm;
  stack.first_slice_mm = -0.5 * slice_mm;
  double depth = 0.0, radius = 0.0;
  for (const Eigen::Vector3d& p : frame.epicardium.points) {
    const double along = (p - rim).dot(stack.to_apex);
    depth = std::max(depth, along);
    radius = std::max(radius, (p - rim - along * stack.to_apex).norm());
  }
  stack.slices =
      static_cast<int>(std::ceil((depth - stack.first_slice_mm) / slice_mm)) +
      1;
  stack.size =
      2 * static_cast<int>(std::ceil((radius + 5.0) / in_plane_mm)) + 1;
  return stack;
}

double WallThickness(const MeshMaskFrame& frame) {
  std::vector<double> near;
  for (const Eigen::Vector3d& p : frame.lv_endocardium.points) {
    double best = 1e300;
    for (const Eigen::Vector3d& q : frame.epicardium.points) {
      best = std::min(best, (p - q).squaredNorm());
    }
    if (best < 15.0 * 15.0) near.push_back(std::sqrt(best));
  }
  std::nth_element(near.begin(), near.begin() + near.size() / 2, near.end());
  return near[near.size() / 2];
}

// Per voxel of the slice in `where`, the in-plane distance (voxels) to the
// nearest voxel of `from`, by brute force over from's voxels (a slice holds a
// few hundred).
std::vector<double> DistanceTo(const std::vector<bool>& from,
                               const std::vector<bool>& where, int size) {
  std::vector<Eigen::Vector2d> sources;
  for (int n = 0; n < size * size; ++n) {
    if (from[n]) sources.emplace_back(n % size, n / size);
  }
  std::vector<double> distance(size * size, 1e300);
  for (int n = 0; n < size * size; ++n) {
    if (!where[n]) continue;
    const Eigen::Vector2d p(n % size, n / size);
    for (const Eigen::Vector2d& s : sources) {
      distance[n] = std::min(distance[n], (p - s).squaredNorm());
    }
    distance[n] = std::sqrt(distance[n]);
  }
  return distance;
}

// The largest 4-connected set of `in`.
std::vector<bool> LargestComponent(const std::vector<bool>& in, int size) {
  std::vector<int> component(in.size(), -1);
  std::vector<int> sizes;
  for (int start = 0; start < size * size; ++start) {
    if (!in[start] || component[start] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    sizes.push_back(0);
    std::queue<int> queue;
    queue.push(start);
    component[start] = id;
    while (!queue.empty()) {
      const int n = queue.front();
      queue.pop();
      ++sizes[id];
      const int i = n % size, j = n / size;
      for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int a = i + di, b = j + dj;
        if (a < 0 || b < 0 || a >= size || b >= size) continue;
        const int m = b * size + a;
        if (in[m] && component[m] < 0) {
          component[m] = id;
          queue.push(m);
        }
      }
    }
  }
  std::vector<bool> out(in.size(), false);
  if (sizes.empty()) return out;
  const int largest = static_cast<int>(
      std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for (size_t n = 0; n < in.size(); ++n) out[n] = component[n] == largest;
  return out;
}

void LabelSlice(const TriangleMesh& endo, const TriangleMesh& epi,
                double wall_voxels, const LabelMap& labels, int k, int t,
                LabelVolume* volume) {
  const int size = volume->nx;
  const std::vector<bool> cavity =
      InsideSlice(endo, volume->world_from_voxel, size, k);
  const std::vector<bool> inside =
      InsideSlice(epi, volume->world_from_voxel, size, k);
  const std::vector<double> distance = DistanceTo(cavity, inside, size);
  std::vector<bool> rest(cavity.size(), false);
  for (int n = 0; n < size * size; ++n) {
    std::int32_t label = 0;
    if (cavity[n]) {
      label = labels.lv;
    } else if (inside[n] && distance[n] <= wall_voxels) {
      label = labels.myo;
    } else if (inside[n]) {
      rest[n] = true;
    }
    volume->labels[volume->Index(n % size, n / size, k, t)] = label;
  }
  const std::vector<bool> rv = LargestComponent(rest, size);
  for (int n = 0; n < size * size; ++n) {
    if (rv[n])
      volume->labels[volume->Index(n % size, n / size, k, t)] = labels.rv;
  }
}

}  // namespace

Eigen::Matrix4d WorldFromVoxel(const StackGeometry& stack) {
  Eigen::Vector3d i = Eigen::Vector3d::UnitX();
  if (std::abs(i.dot(stack.to_apex)) > 0.9) i = Eigen::Vector3d::UnitY();
  i = (i - i.dot(stack.to_apex) * stack.to_apex).normalized();
  const Eigen::Vector3d j = stack.to_apex.cross(i);
  const double half = 0.5 * (stack.size - 1) * stack.in_plane_mm;
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 1>(0, 0) = i * stack.in_plane_mm;
  m.block<3, 1>(0, 1) = j * stack.in_plane_mm;
  m.block<3, 1>(0, 2) = stack.to_apex * stack.slice_mm;
  m.block<3, 1>(0, 3) =
      stack.origin + stack.first_slice_mm * stack.to_apex - half * (i + j);
  return m;
}

std::vector<bool> InsideSlice(const TriangleMesh& closed,
                              const Eigen::Matrix4d& world_from_voxel, int size,
                              int k) {
  const std::vector<Segment> segments =
      Cut(closed, world_from_voxel.inverse(), k);
  std::vector<bool> inside(static_cast<size_t>(size) * size, false);
  for (int j = 0; j < size; ++j) {
    std::vector<double> crossings;
    for (const auto& [a, b] : segments) {
      if ((a.y() > j) == (b.y() > j)) continue;
      crossings.push_back(a.x() +
                          (b.x() - a.x()) * (j - a.y()) / (b.y() - a.y()));
    }
    std::sort(crossings.begin(), crossings.end());
    for (int i = 0; i < size; ++i) {
      const auto beyond =
          crossings.end() - std::upper_bound(crossings.begin(), crossings.end(),
                                             static_cast<double>(i));
      inside[static_cast<size_t>(j) * size + i] = beyond % 2 == 1;
    }
  }
  return inside;
}

MeshMask MakeMeshMask(const std::vector<MeshMaskFrame>& frames,
                      const LabelMap& labels, double in_plane_mm,
                      double slice_mm) {
  const StackGeometry stack = StackOf(frames[0], in_plane_mm, slice_mm);
  MeshMask mask;
  LabelVolume& volume = mask.volume;
  volume.source = "mesh mask";
  volume.nx = volume.ny = stack.size;
  volume.nz = stack.slices;
  volume.nt = static_cast<int>(frames.size());
  volume.labels.assign(
      static_cast<size_t>(volume.nx) * volume.ny * volume.nz * volume.nt, 0);
  volume.world_from_voxel = WorldFromVoxel(stack);
  volume.geometry = "sform";
  for (int t = 0; t < volume.nt; ++t) {
    const TriangleMesh endo = CapBoundaryLoops(frames[t].lv_endocardium);
    const TriangleMesh epi = CapBoundaryLoops(frames[t].epicardium);
    mask.wall_mm.push_back(WallThickness(frames[t]));
    mask.mesh_cavity_ml.push_back(EnclosedVolume(endo) / 1000.0);
    for (int k = 0; k < volume.nz; ++k) {
      LabelSlice(endo, epi, mask.wall_mm[t] / in_plane_mm, labels, k, t,
                 &volume);
    }
  }
  const size_t per_frame = volume.labels.size() / volume.nt;
  for (int t = 0; t < volume.nt; ++t) {
    int cavity = 0, myocardium = 0;
    for (size_t n = per_frame * t; n < per_frame * (t + 1); ++n) {
      cavity += volume.labels[n] == labels.lv;
      myocardium += volume.labels[n] == labels.myo;
    }
    mask.cavity_ml.push_back(cavity * volume.VoxelVolumeMl());
    mask.myocardium_ml.push_back(myocardium * volume.VoxelVolumeMl());
  }
  return mask;
}

}  // namespace pfdm
