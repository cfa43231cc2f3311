// The pfdm subcommands, each in its own file, and what they share.
#ifndef PFDM_CLI_COMMANDS_H_
#define PFDM_CLI_COMMANDS_H_

#include "gflags/gflags.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/io/fit_settings.h"
#include "pfdm/model/base_plane.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_data.h"

DECLARE_string(points);
DECLARE_string(out);
DECLARE_int32(threads);

namespace pfdm {

// Exit codes: 0 done (warnings included, said on stderr), 1 an error (bad
// input: nothing written), 2 a usage error, kExitImplausible a fit done and
// written whose verdict failed (util/verdict.h): the numbers are not to be
// used.
constexpr int kExitImplausible = 3;

// Each returns the exit code; bad input throws InputError.
int RunFit();
int RunSimulate();
int RunCheckJacobians();
int RunCompareSolvers();
int RunBatch();
int RunMeshPoints();

// From the shared flags (--points --format --contours; --model --knots;
// --smoothness --prior --loss --loss_scale --threads --apex --base --solver
// ...; --base_plane --vtk_format), all of them FitSettings' (fit_flags.cc).
FitSettings FitSettingsFromFlags();
PointSequence PointsFromFlags();
ModelConfig ModelConfigFromFlags();
FitOptions FitOptionsFromFlags();
VtkFormat VtkFormatFromFlags();
// --extrapolated: AnalyzeFit's show_extrapolated.
bool ShowExtrapolatedFromFlags();
// Per frame, the plane closing the cavity for --base_plane; "" only checks
// the flag.
std::vector<BasePlane> BasePlanesFromFlags(const std::string& points);

}  // namespace pfdm

#endif  // PFDM_CLI_COMMANDS_H_
