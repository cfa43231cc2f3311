// The planes that close the LV cavity where guide points carry the mitral
// valve.
#ifndef PFDM_IO_MITRAL_VALVE_PLANES_H_
#define PFDM_IO_MITRAL_VALVE_PLANES_H_

#include <string>
#include <vector>

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/base_plane.h"

namespace pfdm {

// Per frame, the plane through the MITRAL_VALVE points of biv-me guide
// point files (path and format as for ReadPoints: the format, not the
// file's name, says whether they are guide points); empty when the input is
// not guide points or some frame has fewer than 3 such points.  Throws
// InputError when a frame's 3 or more points lie at one place or on a line.
// biv-me closes its own LV meshes at the valves, and a flat lid at the
// highest contour point overestimates the cavity by the tilt of the annulus
// (by up to 19 % on biv-me's patient 1).
std::vector<BasePlane> MitralValvePlanes(const std::string& gp_path,
                                         const std::string& format = "auto");

// Throws InputError "PATH: frame N: the MITRAL_VALVE plane lies D mm
// beyond the fitted apex ..." when a frame's plane leaves the apex of the
// fitted cavity on its base side: it would close a cavity of 0 ml.  Planes
// not one per frame are not the fit's (AnalyzeFit ignores them): no check.
void CheckPlanesBelowApex(const std::string& gp_path,
                          const std::vector<BasePlane>& planes,
                          const SequenceFit& fit);

}  // namespace pfdm

#endif  // PFDM_IO_MITRAL_VALVE_PLANES_H_
