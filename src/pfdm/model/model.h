// Which parameter functions a model lets vary, and one fitted state of it.
#ifndef PFDM_MODEL_MODEL_H_
#define PFDM_MODEL_MODEL_H_

#include <array>
#include <string>
#include <vector>

#include "Eigen/Core"
#include "Eigen/Geometry"  // Users of models take cross products.
#include "pfdm/model/local_field.h"
#include "pfdm/model/model_point.h"
#include "pfdm/model/parameter_function.h"

namespace pfdm {

enum class FunctionMode {
  kFree,      // Piecewise linear over the knots.
  kConstant,  // One fitted value for every u.
  kFixed,     // Held at its initial value.
};

struct ModelConfig {
  std::string name = "paper";
  int num_knots = 17;
  // Apex at u_min, base at u_max.  The base sits above the equator so that
  // the base ring can move along the axis (a3 scales sin u, zero at u = 0).
  double u_min = -1.5707963267948966;
  double u_max = 0.5235987755982988;  // pi / 6
  std::array<FunctionMode, kNumFunctions> modes{};

  // The paper's LV set-up: a0 constant (held: it is the scale gauge),
  // eps1 = eps2 = 1, e3o = 0; a1 a2 a3 tau b0..b3 e1o e2o free.
  static ModelConfig Paper(int num_knots);
  // The paper's Fig. 2(b) baseline: the same functions, constant along u.
  static ModelConfig Superellipsoid(int num_knots);
  // "paper" or "superellipsoid" with 2 to kMaxKnots knots; throws
  // InputError otherwise.
  static constexpr int kMaxKnots = 100;
  static ModelConfig FromName(const std::string& name, int num_knots);

  // The wall (docs/gauge.md, "The wall"): a mid-wall surface holds the wall
  // thickness h, the transmural twist difference dtau and shift at 0; a
  // solid fits them as a1 is fitted (over the knots, or constant).
  void MakeSolid();
  bool Solid() const { return modes[kH] != FunctionMode::kFixed; }

  // The knots of this configuration; the reference stays valid until the
  // same thread asks for another configuration's grid.
  const KnotGrid& Grid() const;
  FunctionMask FreeMask() const;
};

// Values before any fit: eps = 1, b1 = b3 = 1 (bending, if any, tilts),
// everything else 0 but the a's, which initialization sets.
FunctionValues DefaultFunctionValues();

struct ModelState {
  std::array<double, 3> center{0.0, 0.0, 0.0};
  std::array<double, 4> quaternion{1.0, 0.0, 0.0, 0.0};  // (w, x, y, z)
  FunctionValues globals = DefaultFunctionValues();      // Non-free functions.
  std::vector<FunctionValues> knots;                     // Free functions.
  // Local displacements d(u, v), model frame; empty: none (p = s).
  LocalField local;
};

using BendingShift = std::array<double, 2>;

struct Model {
  ModelConfig config;
  ModelState state;

  // A model whose every knot and global holds `values`.
  static Model Uniform(const ModelConfig& config, const FunctionValues& values);

  bool UnitExponents() const;
  double FunctionAt(int function, double u) const;
  FunctionValues FunctionsAt(double u) const;
  // d/du of FunctionsAt within u's knot span (0 for functions not free).
  FunctionValues FunctionSlopesAt(double u) const;
  // p = s + d, model frame: the global shape and the local displacement, on
  // surface w (-1 endocardium, 0 mid-wall, +1 epicardium: transmural.h;
  // d moves every surface alike).
  Eigen::Vector3d ModelPoint(double u, double v, double w = 0.0) const;
  Eigen::Vector3d WorldPoint(double u, double v,
                             double w = 0.0) const;  // c + R p
  // The same with f = FunctionsAt(u) given, which a ring's points share.
  Eigen::Vector3d ModelPointWith(const FunctionValues& f, double u, double v,
                                 double w = 0.0) const;
  Eigen::Vector3d WorldPointWith(const FunctionValues& f, double u, double v,
                                 double w = 0.0) const;
  // Rotation world_from_model.
  Eigen::Matrix3d Rotation() const;
  // The superellipsoid's height of the ring at u along the model's axis
  // from its centre, a0 a3(u) sin u (eps1 = 1), its offset e3o and bends
  // aside (report/material_rings.h RingHeight adds e3o).
  double ShapeHeight(double u) const;

  // The bending gauge.  g(x, b + 2) = -g(x, b), so (b0, b1) and
  // (-b0, b1 + 2) are the same bend; shifting a whole shape function by a
  // multiple of 2 (negating its amplitude for an odd multiple) brings the
  // mean of its values over the knots into [0, 2).  The window is centred
  // on the tilt (b = 1), the LV's usual bend and the default, so a bend's
  // sign reads the same across frames.  The fit leaves b1 and b3 unbounded
  // (a bounded window would stop shape functions that cross its edge) and
  // applies this after each frame.  Returns the shift, in turns of 2, of
  // b1 and of b3.
  BendingShift CanonicalizeBending();
  // b1 and b3 less 2 x turns, b0 and b2 negated for odd turns.
  void ShiftBending(const BendingShift& turns);
};

}  // namespace pfdm

#endif  // PFDM_MODEL_MODEL_H_
