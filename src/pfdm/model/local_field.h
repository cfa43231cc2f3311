// Local deformations (Park, Metaxas & Young 1994, section 2.2): a finite
// element displacement field d(u, v) = S(u, v) q_d on top of the global
// parameter functions, p = s + d in the model frame
// (docs/local_deformations.md).
//
// Nodes: rows 0 .. rows - 1 at u equally spaced from u_min to u_max and
// `cols` columns at v = -pi + 2 pi j / cols, periodic in v.  Row 0, the apex
// pole, is ONE node: every v meets there, so the surface stays closed.  The
// elements are bilinear in (u, v) between rows 1 .. rows - 1, and in the
// first row the pole's value blends linearly in u with the bilinear ring of
// row 1: a point touches 4 nodes (pole row: the pole and 2).  In a solid
// the field may vary through the wall, d(u, v, w) = S (q + w q_w + k(w)
// q_k) with w in [-1, 1] (transmural.h): q moves the mid-wall, q_w half the
// epicardium's displacement less the endocardium's, so that a segment's
// inner layers can contract unlike its outer ones, and q_k bends the
// profile between them (TransmuralKink), so that a lesion of the inner
// half is not read as a line through the wall.  Without q_w (a surface,
// or a solid fitted so) d moves every layer alike.
#ifndef PFDM_MODEL_LOCAL_FIELD_H_
#define PFDM_MODEL_LOCAL_FIELD_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include "Eigen/Core"

namespace pfdm {

struct LocalGrid {
  int rows = 0;  // 0: no field.
  int cols = 0;
  double u_min = 0.0;
  double u_max = 0.0;

  // Bounds of --local_grid: a few nodes per AHA segment at most; the cost
  // grows with them and the data do not resolve more.
  static constexpr int kMinRows = 3, kMaxRows = 40;
  static constexpr int kMinCols = 4, kMaxCols = 72;

  int NumNodes() const { return rows > 0 ? 1 + (rows - 1) * cols : 0; }
  // Node index of (row, col), col taken modulo cols; row 0 is the pole.
  int Node(int row, int col) const {
    if (row == 0) return 0;
    const int wrapped = ((col % cols) + cols) % cols;
    return 1 + (row - 1) * cols + wrapped;
  }
  double RowU(int row) const {
    return u_min + (u_max - u_min) * row / (rows - 1);
  }
  double ColV(int col) const;
};

// "NUxNV", e.g. "9x16", within LocalGrid's bounds; throws InputError naming
// --local_grid otherwise.  u_min, u_max are left 0.
LocalGrid ParseLocalGrid(const std::string& text);

// The nodes whose shape functions cover (u, v) and their values there:
// d(u, v) = sum_k weight[k] q[node[k]].  u is clamped to [u_min, u_max].
struct ShapeWeights {
  int count = 0;
  std::array<int, 4> node{};
  std::array<double, 4> weight{};
};

// The element of (u, v): s = (u - u0) / du along u from the element's lower
// row and t = (v - v0) / dv along v from its first column are in [0, 1]
// (v0 is shifted by whole turns to v's side of the seam at -pi).
struct LocalElement {
  int row = 0;  // Lower row, 0 .. rows - 2.
  int col = 0;  // 0 .. cols - 1.
  double u0 = 0.0, du = 1.0, v0 = 0.0, dv = 1.0;
};
LocalElement ElementAt(const LocalGrid& grid, double u, double v);

ShapeWeights ShapeAt(const LocalGrid& grid, double u, double v);

struct LocalField {
  LocalGrid grid;
  std::vector<double> values;  // q: 3 per node, model frame, mm.
  // q_w, the change per unit w: 3 per node, or empty (no transmural part).
  std::vector<double> slope;
  // q_k, the mid-layers' bend away from the line between the walls:
  // TransmuralKink(w) q_k, zero at both walls; 3 per node or empty.
  std::vector<double> kink;

  bool empty() const { return values.empty(); }
  bool transmural() const { return !slope.empty(); }
  // A field of zeros on `grid` (with a zero slope and kink when
  // `transmural`).
  static LocalField Zero(const LocalGrid& grid, bool transmural = false);
  Eigen::Vector3d Displacement(double u, double v, double w = 0.0) const;
  // q, q_w then q_k in one vector, as the noise draws perturb them and
  // the contour rounds mix them; adding such a vector (a shorter one adds
  // to q alone), or replacing them by one.
  std::vector<double> Coefficients() const;
  void AddCoefficients(const std::vector<double>& change);
  void SetCoefficients(const double* coefficients);
};

// clamp(3 w, -1, 1) - w: odd, zero at w = 0 and at both walls, 2/3 at
// w = 1/3.  With 1 and w it spans the profiles linear on [-1, -1/3],
// [-1/3, 1/3], [1/3, 1] that are odd about the mid-wall's mean.
inline double TransmuralKink(double w) {
  return std::clamp(3.0 * w, -1.0, 1.0) - w;
}

// d(u, v, w) for any scalar type (a Jet when u and v are differentiated, as
// the closest-point search does); zero for an empty field.
template <typename T>
Eigen::Matrix<T, 3, 1> LocalDisplacement(const LocalField& field, const T& u,
                                         const T& v, double w = 0.0) {
  Eigen::Matrix<T, 3, 1> d(T(0.0), T(0.0), T(0.0));
  if (field.empty()) return d;
  double u_value, v_value;
  if constexpr (std::is_same_v<T, double>) {
    u_value = u;
    v_value = v;
  } else {
    u_value = u.a;
    v_value = v.a;
  }
  const LocalGrid& grid = field.grid;
  const LocalElement e = ElementAt(grid, u_value, v_value);
  // The element's coordinates as T, so that a Jet carries ds/du, dt/dv; the
  // clamp at u_max leaves s a constant.
  const T s = u_value >= grid.u_max   ? T(1.0)
              : u_value <= grid.u_min ? T(0.0)
                                      : (u - e.u0) / e.du;
  const T t = (v - e.v0) / e.dv;
  const bool layered = field.transmural() && w != 0.0;
  // col is e.col or the next, in [0, cols]: Node's wrap without its two
  // integer divisions, at every point of every surface and sample.
  auto node = [&](int row, int col) -> Eigen::Matrix<T, 3, 1> {
    const int index =
        row == 0 ? 0 : 1 + (row - 1) * grid.cols + (col == grid.cols ? 0 : col);
    const int at = 3 * index;
    const double* q = &field.values[at];
    if (!layered) return Eigen::Matrix<T, 3, 1>(T(q[0]), T(q[1]), T(q[2]));
    const double* q_w = &field.slope[at];
    const double k = field.kink.empty() ? 0.0 : TransmuralKink(w);
    const double* q_k = field.kink.empty() ? q_w : &field.kink[at];
    return Eigen::Matrix<T, 3, 1>(T(q[0] + w * q_w[0] + k * q_k[0]),
                                  T(q[1] + w * q_w[1] + k * q_k[1]),
                                  T(q[2] + w * q_w[2] + k * q_k[2]));
  };
  const Eigen::Matrix<T, 3, 1> upper =
      (T(1.0) - t) * node(e.row + 1, e.col) + t * node(e.row + 1, e.col + 1);
  const Eigen::Matrix<T, 3, 1> lower =
      e.row == 0 ? node(0, 0)
                 : Eigen::Matrix<T, 3, 1>((T(1.0) - t) * node(e.row, e.col) +
                                          t * node(e.row, e.col + 1));
  return (T(1.0) - s) * lower + s * upper;
}

}  // namespace pfdm

#endif  // PFDM_MODEL_LOCAL_FIELD_H_
