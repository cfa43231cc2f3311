// pfdm: fits deformable models with parameter functions to LV point data.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "pfdm/cli/commands.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

struct Command {
  const char* name;
  int (*run)();
  const char* usage;
  std::string flags;  // Those it reads, each followed by a space.
};

// The model's and the fit's, FitSettings' but for the solver and outputs.
const std::string kFitFlags =
    "format contours model knots wall surface ed_frame smoothness prior "
    "untracked_prior loss "
    "loss_scale threads apex base linear_solver time_step rest_tolerance "
    "max_steps integrator damping damping_scale jacobian local local_grid "
    "local_stiffness uncertainty ";

const Command kCommands[] = {
    {"fit", RunFit,
     "--points FILE --out DIR [--model paper|superellipsoid] [--knots 17] "
     "[--solver direct|damped|integrator [--integrator rkc|euler]]",
     "points out solver vtk_format base_plane extrapolated rv_insertion " +
         kFitFlags},
    {"simulate", RunSimulate,
     "--out FILE.csv [--noise 0.5 --outliers 0 --frames 5 --tags 2000]",
     "out frames tags noise outliers seed phantom kinematics wall_tags "
     "breathing lesion region sampling slices "},
    {"check-jacobians", RunCheckJacobians, "[--tolerance 1e-6]", "tolerance "},
    {"compare-solvers", RunCompareSolvers,
     "--points FILE --out DIR: direct, damped and integrator side by side",
     "points out trajectory_per_decade " + kFitFlags},
    {"batch", RunBatch,
     "--manifest cases.csv --out DIR [--jobs N] [--shard i/n]: fits a cohort",
     "manifest out jobs shard solver vtk_format base_plane extrapolated " +
         kFitFlags},
    {"mesh-points", RunMeshPoints,
     "--mesh FILE|DIR --out FILE.csv [--mesh_filter S] [--label 0] "
     "[--cap_surfaces ED-endo,ES-endo]: mesh vertices as tracked points",
     "mesh out mesh_filter mesh_format label cap_surfaces "},
};

bool Reads(const Command& command, const std::string& flag) {
  return (" " + command.flags).find(" " + flag + " ") != std::string::npos;
}

// A flag of another command, given to this one, was once ignored without a
// word (`fit --noise 3`, `fit --jobs 4`).  Flags of no command are gflags'
// and glog's own, or pfdm's that no command lists: those are refused too,
// so that a new flag left out of kCommands fails its first test.
void CheckFlagsAreTheCommands(const Command& command) {
  std::vector<gflags::CommandLineFlagInfo> flags;
  gflags::GetAllFlags(&flags);
  for (const gflags::CommandLineFlagInfo& flag : flags) {
    if (flag.is_default || Reads(command, flag.name)) continue;
    std::string owners;
    for (const Command& other : kCommands) {
      if (Reads(other, flag.name)) {
        owners += (owners.empty() ? "" : ", ") + std::string(other.name);
      }
    }
    if (!owners.empty()) {
      throw InputError("--" + flag.name + " is a flag of " + owners +
                       ", not of " + command.name);
    }
    if (flag.filename.find("pfdm/cli/") != std::string::npos) {
      throw InputError("--" + flag.name + " is not a flag of " + command.name);
    }
  }
}

std::string Usage() {
  std::string usage = "pfdm <command> [flags]\n";
  for (const Command& command : kCommands) {
    usage += "  " + std::string(command.name) + "  " + command.usage + "\n";
  }
  return usage + "Run 'pfdm --help' for every flag.";
}

}  // namespace
}  // namespace pfdm

int main(int argc, char** argv) {
  const std::string usage = pfdm::Usage();
  gflags::SetUsageMessage(usage);
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  if (argc != 2) {
    std::fprintf(stderr, "%s\n", usage.c_str());
    return 2;
  }
  const std::string name = argv[1];
  for (const pfdm::Command& command : pfdm::kCommands) {
    if (name != command.name) continue;
    try {
      CheckFlagsAreTheCommands(command);
      return command.run();
    } catch (const std::bad_alloc&) {  // Its what() is "std::bad_alloc".
      std::fprintf(stderr,
                   "pfdm: error: out of memory (is the input that large?)\n");
      return 1;
    } catch (const std::exception& error) {
      std::fprintf(stderr, "pfdm: error: %s\n", error.what());
      return 1;
    }
  }
  std::fprintf(stderr, "pfdm: unknown command '%s'\n%s\n", name.c_str(),
               usage.c_str());
  return 2;
}
