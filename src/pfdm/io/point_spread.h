// Whether a frame's points lie together, as the points of one heart do.
#ifndef PFDM_IO_POINT_SPREAD_H_
#define PFDM_IO_POINT_SPREAD_H_

#include <string>
#include <vector>

#include "pfdm/util/point_data.h"

namespace pfdm {

// No heart, with its valves and the right ventricle, spans this far from
// the middle of its points.
inline constexpr double kMaxHeartRadiusMm = 500.0;

// Throws InputError "PATH:LINE: frame F: the point lies D mm from the
// centre of the frame's points, beyond any heart (500 mm)" for the first
// point (by line) that lies farther than kMaxHeartRadiusMm from the
// frame's coordinate-wise median, which one stray point cannot move.  One
// point at 9e5 mm was refused before as "the points lie on a line".
// lines[i] is points[i]'s line in path.
void CheckPointsLieTogether(const std::string& path, int frame,
                            const std::vector<DataPoint>& points,
                            const std::vector<unsigned>& lines);

}  // namespace pfdm

#endif  // PFDM_IO_POINT_SPREAD_H_
