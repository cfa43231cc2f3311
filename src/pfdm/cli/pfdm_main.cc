// pfdm: fits deformable models with parameter functions to LV point data.
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "pfdm/cli/commands.h"

namespace pfdm {
namespace {

struct Command {
  const char* name;
  int (*run)();
  const char* usage;
};

const Command kCommands[] = {
    {"fit", RunFit,
     "--points FILE --out DIR [--model paper|superellipsoid] [--knots 17] "
     "[--solver direct|damped|integrator]"},
    {"simulate", RunSimulate,
     "--out FILE.csv [--noise 0.5 --outliers 0 --frames 5 --tags 2000]"},
    {"check-jacobians", RunCheckJacobians, "[--tolerance 1e-6]"},
    {"compare-solvers", RunCompareSolvers,
     "--points FILE --out DIR: direct, damped and integrator side by side"},
    {"batch", RunBatch,
     "--manifest cases.csv --out DIR [--jobs N] [--shard i/n]: fits a cohort"},
    {"mesh-points", RunMeshPoints,
     "--mesh FILE|DIR --out FILE.csv [--mesh_filter S] [--label 0] "
     "[--cap_surfaces ED-endo,ES-endo]: mesh vertices as tracked points"},
};

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
