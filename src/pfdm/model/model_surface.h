// The fitted model as a triangle mesh, and the cavity volume it encloses.
#ifndef PFDM_MODEL_MODEL_SURFACE_H_
#define PFDM_MODEL_MODEL_SURFACE_H_

#include <optional>
#include <vector>

#include "pfdm/model/base_plane.h"
#include "pfdm/model/model.h"
#include "pfdm/util/triangle_mesh.h"

namespace pfdm {

// A (u, v) grid of the model surface in world coordinates: `rings` latitudes
// equally spaced in u from u_min to u_max, `meridians` longitudes from -pi.
// A ring at the apex pole (cos u = 0) is one vertex, so the only open
// boundary is the base rim.  Triangles face outward.
struct ModelSurface {
  TriangleMesh mesh;
  std::vector<double> u;  // Per vertex.
  std::vector<double> v;
  double w = 0.0;  // The solid's surface it samples.
  // CavitySurface with a base plane: the first vertex of the ring it stops
  // at, wholly above the plane; -1 for a surface that runs to its end.
  int cut_ring_first = -1;
};

// u_end > u_max continues the surface past the base rim with every
// function held at its base value; u_end = pi/2 closes it at a top pole.
// w: the solid's surface (model/transmural.h), 0 the mid-wall.
ModelSurface MakeModelSurface(const Model& model, int rings, int meridians,
                              std::optional<double> u_end = std::nullopt,
                              double w = 0.0);

// Volume (ml) inside the model's surface w (the cavity for the endocardium,
// w = -1 of a solid, or of a surface fitted to endocardial contours).
// Without a base plane: the model surface
// closed at the base by a fan of triangles around the rim's centroid (a
// flat lid for a planar rim).  With one: the model continued past its rim
// (see MakeModelSurface) and cut by the plane, keeping the apex's side, so a
// tilted annulus is followed where the flat lid would cut across it.
// Sampled finely enough that a sphere comes out within 0.1 %.
double CavityVolumeMl(const Model& model, const BasePlane* base = nullptr,
                      double w = 0.0);

// The least-squares plane of layer w's base rim (u_max; w = 0 the mid-wall,
// -1 and 1 a solid's walls).  Each wall's rim lies off the mid-wall's along
// the mid-wall's normal, by w h / 2 times the normal's axial part.
BasePlane RimPlane(const Model& model, double w = 0.0);

// The lowest rim of a model's walls along its axis (a solid's endocardium
// where the mid-wall narrows toward its rim, as above its widest ring; its
// epicardium where it widens; the mid-wall's for a surface): where a
// solid's walls end when its data end at one short-axis slice, which the
// fit's lowest rim reaches (fit/stages/top_slice.h, RimLift).
BasePlane LowestRimPlane(const Model& model);

// How far a solid's lowest wall rim lies below its mid-wall's, along the
// model's axis (0 for a surface).
double LowestRimDrop(const Model& model);

// CavityVolumeMl in two steps, for a model measured again after a move
// confined to a range of u (the delta method's knot steps,
// report/number_uncertainty.h): the surface CavityVolumeMl closes, whose
// vertices in a range of u ReplaceVertices re-places on a moved model.
ModelSurface CavitySurface(const Model& model, const BasePlane* base,
                           double w = 0.0);
// The vertices with u in [u_low, u_high] (the base plane's continuation
// past u_max has the functions at u_max), placed on `model`; returns the
// range of vertex indices [first, last) that holds them (the vertices run
// ring by ring from the apex).
struct VertexRange {
  size_t first = 0, last = 0;
};
VertexRange ReplaceVertices(const Model& model, double u_low, double u_high,
                            double w, ModelSurface* surface);
// CavityVolumeMl(model, base, w) for surface = CavitySurface(model, base, w).
double CavityVolumeMl(const Model& model, const ModelSurface& surface,
                      const BasePlane* base);

// CavityVolumeMl(model, surface, base) kept, and measured again for the
// surface with some of its vertices moved: only the triangles that use
// them are summed again (PlaneVolume), under a base plane with the same
// bits as CavityVolumeMl of the moved surface, with the flat lid about the
// kept apex (within round-off of CavityVolumeMl's about the moved one).
// `base` must outlive it.
class KeptCavityVolume {
 public:
  KeptCavityVolume(const Model& model, const ModelSurface& surface,
                   const BasePlane* base);
  double ml() const { return ml_; }
  // CavityVolumeMl(moved_model, moved, base) of `moved`, the kept surface
  // with its vertices moved only in `changed`, on `moved_model`.
  double MovedMl(const Model& moved_model, const ModelSurface& moved,
                 const VertexRange& changed) const;

 private:
  // The flat lid's volume (ml) of a surface whose triangles sum to
  // `surface_six_volume` about origin_.
  double FlatLidMl(const TriangleMesh& mesh, double surface_six_volume) const;

  const BasePlane* base_;
  bool apex_pole_, top_pole_;
  Eigen::Vector3d normal_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  std::optional<PlaneVolume> blocks_;
  double ml_ = 0.0;
};

}  // namespace pfdm

#endif  // PFDM_MODEL_MODEL_SURFACE_H_
