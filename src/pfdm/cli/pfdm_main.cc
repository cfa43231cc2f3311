// pfdm: fits deformable models with parameter functions to LV point data.
#include <cstdio>
#include <exception>
#include <iterator>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "pfdm/cli/commands.h"
#include "pfdm/cli/help.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

std::string command_line;

// argv as one line, each argument with a space or quote in single quotes.
std::string QuotedCommandLine(int argc, char** argv) {
  std::string line = "pfdm";
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.find_first_of(" \t'\"$") != std::string::npos) {
      std::string quoted = "'";
      for (char c : arg)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
      arg = quoted + "'";
    }
    line += " " + arg;
  }
  return line;
}

struct Command {
  const char* name;
  int (*run)();
  const char* usage;
  std::string flags;  // Those it reads, each followed by a space.
  const char* summary;
};

// The model's and the fit's, FitSettings' but for the solver and outputs.
const std::string kFitFlags =
    "format contours model knots wall surface ed_frame smoothness prior "
    "untracked_prior untracked_prior_radii temporal_prior incompressible loss "
    "loss_scale threads apex base linear_solver time_step rest_tolerance "
    "max_steps integrator damping damping_scale jacobian local local_grid "
    "local_stiffness local_transmural tag_depths uncertainty ";

const Command kCommands[] = {
    {"fit", RunFit,
     "--points FILE|--segmentation NIFTI [--labels acdc] --out DIR [--model "
     "paper|superellipsoid] [--knots 17] [--solver direct|damped|integrator]",
     "points segmentation labels out solver vtk_format vtk_precision "
     "base_plane extrapolated rv_insertion " +
         kFitFlags,
     "fits the model to tags, contours or segmentation masks over the cycle: "
     "functions, clinical numbers, report"},
    {"simulate", RunSimulate,
     "--out FILE.csv [--noise 0.5 --outliers 0 --frames 5 --tags 2000]",
     "out frames tags noise outliers seed phantom kinematics wall_tags "
     "breathing lesion region sampling slices geometry thickening ",
     "writes a phantom's points and its truth (the model's own, or the "
     "independent LV)"},
    {"check-jacobians", RunCheckJacobians, "[--tolerance 1e-6]", "tolerance ",
     "checks the analytic Jacobians against Ceres' GradientChecker"},
    {"compare-solvers", RunCompareSolvers, "--points FILE --out DIR",
     "points out trajectory_per_decade " + kFitFlags,
     "fits with the direct, damped and integrator solvers side by side"},
    {"batch", RunBatch,
     "--manifest cases.csv --out DIR [--jobs N] [--shard i/n]",
     "manifest out jobs shard solver vtk_format vtk_precision base_plane "
     "extrapolated " +
         kFitFlags,
     "fits a cohort: one case per manifest row, a merged summary.csv"},
    {"mesh-points", RunMeshPoints,
     "--mesh FILE|DIR --out FILE.csv [--mesh_filter S] [--label 0] "
     "[--cap_surfaces ED-endo,ES-endo]",
     "mesh out mesh_filter mesh_format label cap_surfaces ",
     "writes a mesh sequence's vertices as tracked points for fit"},
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

std::vector<CommandHelp> Help() {
  std::vector<CommandHelp> help;
  for (const Command& command : kCommands) {
    std::istringstream names(command.flags);
    std::vector<std::string> flags(std::istream_iterator<std::string>(names),
                                   {});
    help.push_back({command.name, command.usage, command.summary, flags});
  }
  return help;
}

// Help, version and usage errors, before gflags sees argv; -1 to go on.
int AnswerHelpRequest(const HelpRequest& request,
                      const std::vector<CommandHelp>& help) {
  switch (request.kind) {
    case HelpRequest::kRun:
      return -1;
    case HelpRequest::kNoCommand:
      std::fprintf(stderr, "%s", OverviewText(help).c_str());
      return 2;
    case HelpRequest::kOverview:
      std::printf("%s", OverviewText(help).c_str());
      return 0;
    case HelpRequest::kVersion:
      std::printf("%s", VersionText().c_str());
      return 0;
    case HelpRequest::kUsageError:
      std::fprintf(stderr, "pfdm: error: %s\n", request.message.c_str());
      return 2;
    case HelpRequest::kCommand:
      break;
  }
  for (const CommandHelp& command : help) {
    if (command.name == request.command) {
      std::printf("%s", CommandText(command).c_str());
    }
  }
  return 0;
}

}  // namespace

const std::string& CommandLine() { return command_line; }

}  // namespace pfdm

int main(int argc, char** argv) {
  pfdm::command_line = pfdm::QuotedCommandLine(argc, argv);
  const std::vector<pfdm::CommandHelp> help = pfdm::Help();
  const pfdm::HelpRequest request = pfdm::ReadHelpRequest(argc, argv, help);
  if (request.kind == pfdm::HelpRequest::kNoCommand) {
    // gflags' --helpxml, which tools (and CliTest) read the flags from.
    gflags::ParseCommandLineNonHelpFlags(&argc, &argv, true);
    gflags::HandleCommandLineHelpFlags();
  }
  const int answered = pfdm::AnswerHelpRequest(request, help);
  if (answered >= 0) return answered;
  gflags::ParseCommandLineNonHelpFlags(&argc, &argv, true);
  for (const pfdm::Command& command : pfdm::kCommands) {
    if (request.command != command.name) continue;
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
  return 2;  // ReadHelpRequest found the command.
}
