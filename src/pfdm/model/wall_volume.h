// The volume of a solid's wall between two rings, from the primitive: what
// an incompressible myocardium keeps (--incompressible, issue 32).
#ifndef PFDM_MODEL_WALL_VOLUME_H_
#define PFDM_MODEL_WALL_VOLUME_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/model/model.h"
#include "pfdm/model/parameter_function.h"
#include "pfdm/model/superellipsoid.h"
#include "pfdm/model/transmural.h"
#include "pfdm/util/angles.h"

namespace pfdm {

// The volume between the endocardium (w = -1), the epicardium (w = +1) and
// the rings u_low < u_high, in the primitive: the superellipsoid with its
// wall offsets (transmural.h), before the bend, the twist and the offsets.
// Those move each ring sideways or turn it, which keeps the volume to first
// order (wall_volume_test.cc measures how closely on a bent, twisted wall).
// f_low and f_high are the functions at the two rings; in between they are
// linear in u, as within a knot span.  Only a0..a3, the exponents, h and
// the shift enter: the squeeze moves the layers between the walls, not the
// walls.
//
// The closed surface is triangulated: u_steps x v_steps quads on each wall
// and v_steps on each ring, where the layers between the walls lie along
// the wall direction, so one quad spans the wall.  The divergence theorem
// then sums (1/6) a . (b x c) over the triangles, positive when oriented
// outward.  A polygon of v_steps sides cuts a ring's area by about
// (2 pi / v_steps)^2 / 6 (2.6 % at 16): relative changes between frames
// lose far less.
template <typename T>
T WallVolume(const T* f_low, const T* f_high, double u_low, double u_high,
             bool unit_exponents, int u_steps, int v_steps) {
  using Point = Eigen::Matrix<T, 3, 1>;
  // points[(i * 2 + side) * v_steps + j]: ring i, wall side (0 endo, 1 epi).
  std::vector<Point> points(2 * (u_steps + 1) * v_steps);
  T f[kNumFunctions];
  for (int i = 0; i <= u_steps; ++i) {
    const double t = static_cast<double>(i) / u_steps;
    for (int n = 0; n < kNumFunctions; ++n) {
      f[n] = (1.0 - t) * f_low[n] + t * f_high[n];
    }
    const double u = u_low + t * (u_high - u_low);
    for (int j = 0; j < v_steps; ++j) {
      const Angles<double> angles =
          MakeAngles(u, -kPi + 2.0 * kPi * j / v_steps);
      const Point e = Superellipsoid(f, angles, unit_exponents);
      const Point n = WallDirection(f, angles);
      points[(i * 2 + 0) * v_steps + j] = e + WallDepth(f, -1.0) * n;
      points[(i * 2 + 1) * v_steps + j] = e + WallDepth(f, 1.0) * n;
    }
  }
  auto at = [&](int i, int side, int j) -> const Point& {
    return points[(i * 2 + side) * v_steps + (j % v_steps)];
  };
  // A quad a b c d (counter-clockwise seen from outside).
  auto quad = [](const Point& a, const Point& b, const Point& c,
                 const Point& d) {
    return a.dot(b.cross(c)) + a.dot(c.cross(d));
  };
  T six_volume = T(0.0);
  for (int j = 0; j < v_steps; ++j) {
    for (int i = 0; i < u_steps; ++i) {
      // d/du x d/dv points into the model (u runs apex to base, v counter-
      // clockwise about the axis): the endocardium's outward, the
      // epicardium's reversed.
      six_volume += quad(at(i, 1, j), at(i, 1, j + 1), at(i + 1, 1, j + 1),
                         at(i + 1, 1, j));
      six_volume += quad(at(i, 0, j), at(i + 1, 0, j), at(i + 1, 0, j + 1),
                         at(i, 0, j + 1));
    }
    // The base ring faces +u, the apical ring -u.
    six_volume += quad(at(u_steps, 0, j), at(u_steps, 1, j),
                       at(u_steps, 1, j + 1), at(u_steps, 0, j + 1));
    six_volume +=
        quad(at(0, 0, j), at(0, 0, j + 1), at(0, 1, j + 1), at(0, 1, j));
  }
  return six_volume / 6.0;
}

// The wall's volume (mm^3) between the rings u_low < u_high, knot span by
// knot span (the part of each within them) with u_steps x v_steps quads
// each.  Zero for a model without a wall (h held).
double ModelWallVolume(const Model& model, double u_low, double u_high,
                       int u_steps, int v_steps);

}  // namespace pfdm

#endif  // PFDM_MODEL_WALL_VOLUME_H_
