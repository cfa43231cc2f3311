// The parameter functions of the model and their piecewise-linear
// representation over K knots.
#ifndef PFDM_MODEL_PARAMETER_FUNCTION_H_
#define PFDM_MODEL_PARAMETER_FUNCTION_H_

#include <array>
#include <string>
#include <vector>

namespace pfdm {

// Order of the functions inside one knot's parameter block.
enum Function : int {
  kA0 = 0,     // Overall scale (mm).
  kA1,         // Radius along axis 1, as a fraction of a0.
  kA2,         // Radius along axis 2, as a fraction of a0.
  kA3,         // Half-length along axis 3, as a fraction of a0.
  kEps1,       // Latitude squareness.
  kEps2,       // Longitude squareness.
  kB0,         // Bending amplitude across axis 1 (mm).
  kB1,         // Bending shape across axis 1 (Model::CanonicalizeBending).
  kB2,         // Bending amplitude across axis 2 (mm).
  kB3,         // Bending shape across axis 2, likewise.
  kTau,        // Twist about axis 3 (radians).
  kE1o,        // Axis offset along axis 1 (mm).
  kE2o,        // Axis offset along axis 2 (mm).
  kE3o,        // Axis offset along axis 3 (mm).
  kH,          // Wall thickness (mm): endocardium w = -1 to epicardium w = +1.
  kDtau,       // Epicardial minus endocardial twist (radians).
  kWallShift,  // The walls' middle, outward of the layer w = 0 (mm).
  kWallSqueeze,  // Layers crowding toward w = 0, walls held (mm).
  kNumFunctions
};

const char* FunctionName(int function);
// Returns -1 for an unknown name.
int FunctionFromName(const std::string& name);

// Where a latitude u falls among the knots: value = (1 - weight) * knot[k0]
// + weight * knot[k0 + 1].  With one knot, k0 = 0 and weight = 0.
struct KnotSpan {
  int k0 = 0;
  double weight = 0.0;
};

// Knots are equally spaced along the long axis of the undeformed model
// (uniform in sin u), as short-axis MR slices are, and functions are linear
// in u between them.  Equal steps in u would crowd knots at the apex, where
// rings are too small for data to pin a1, a2 or tau.
class KnotGrid {
 public:
  KnotGrid(int num_knots, double u_min, double u_max);

  int num_knots() const { return num_knots_; }
  double u_min() const { return u_min_; }
  double u_max() const { return u_max_; }
  double KnotU(int k) const { return knot_u_[k]; }
  // u is clamped to [u_min, u_max]; the last span is used at u_max so that
  // every span names two distinct knots when K >= 2.
  KnotSpan Span(double u) const;

 private:
  int num_knots_;
  double u_min_;
  double u_max_;
  std::vector<double> knot_u_;
};

using FunctionValues = std::array<double, kNumFunctions>;

}  // namespace pfdm

#endif  // PFDM_MODEL_PARAMETER_FUNCTION_H_
