// Triangle meshes: closing open boundaries and the volume they enclose.
#ifndef PFDM_UTIL_TRIANGLE_MESH_H_
#define PFDM_UTIL_TRIANGLE_MESH_H_

#include <array>
#include <vector>

#include "Eigen/Core"

namespace pfdm {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;  // Indices into points.
};

// The closed loops of boundary edges (edges used by one triangle only), each
// as vertex indices in the direction the triangles run along them.  Throws
// InputError when the boundary is not a set of simple loops (a non-manifold
// or inconsistently oriented mesh).
std::vector<std::vector<int>> BoundaryLoops(const TriangleMesh& mesh);

// Closes every boundary loop with a fan of triangles around the loop's
// vertex centroid, oriented like the surface, so that the divergence
// theorem applies.  The LV's basal cap: a flat lid where the rim is planar.
TriangleMesh CapBoundaryLoops(const TriangleMesh& mesh);

// |sum over triangles of p0 . (p1 x p2) / 6| in mm^3: the enclosed volume of
// a closed, consistently oriented mesh, whatever the origin.
double EnclosedVolume(const TriangleMesh& mesh);

// Volume (mm^3) of the part of a closed, consistently oriented mesh on the
// side of the plane through `point` that `normal` points away from: each
// triangle clipped to that side; the cut needs no lid, since with the
// origin on the plane a lid's terms vanish.
double VolumeBelowPlane(const TriangleMesh& closed,
                        const Eigen::Vector3d& point,
                        const Eigen::Vector3d& normal);

// VolumeBelowPlane before the absolute value and the sixth: six times the
// signed volume, summed block by block as PlaneVolume sums it.  A zero
// normal clips nothing: the triangles' terms p0 . (p1 x p2) about `point`,
// which a mesh closed otherwise (lids) adds to its own.
double SixVolumeBelowPlane(const TriangleMesh& closed,
                           const Eigen::Vector3d& point,
                           const Eigen::Vector3d& normal);

// VolumeBelowPlane kept in blocks of consecutive triangles, so that a mesh
// whose vertices moved only in an index range (a surface's rings in a
// range of u, the delta method's knot steps) is summed again only in the
// blocks that use them.  The blocks' sums are added in order either way,
// so a kept volume has the bits of one summed anew (SixVolumeBelowPlane's);
// a zero normal clips nothing.
class PlaneVolume {
 public:
  PlaneVolume(const TriangleMesh& closed, const Eigen::Vector3d& point,
              const Eigen::Vector3d& normal);
  double volume() const;  // mm^3.
  // VolumeBelowPlane(moved, point, normal) of `moved`: this mesh's
  // triangles, its vertices moved only in [first, last).
  double Moved(const TriangleMesh& moved, size_t first, size_t last) const;
  // The same before the absolute value and the sixth: signed, six times.
  double six_volume() const;
  double MovedSixVolume(const TriangleMesh& moved, size_t first,
                        size_t last) const;

 private:
  struct Block {
    size_t begin = 0, end = 0;  // Its triangles.
    size_t low = 0, high = 0;   // The least and the greatest vertex used.
    double six_volume = 0.0;
  };
  double SixVolume(const TriangleMesh& mesh, const Block& block) const;

  Eigen::Vector3d point_, normal_;
  std::vector<Block> blocks_;
};

}  // namespace pfdm

#endif  // PFDM_UTIL_TRIANGLE_MESH_H_
