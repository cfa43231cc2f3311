// The command-line conventions gflags lacks: -h/--help, `pfdm help CMD`,
// `pfdm CMD --help` with only that command's flags, --version, and unknown
// flags named with the nearest valid one (issue 34).  gflags still parses
// the flags; this only looks at argv first.
#ifndef PFDM_CLI_HELP_H_
#define PFDM_CLI_HELP_H_

#include <string>
#include <vector>

namespace pfdm {

struct CommandHelp {
  std::string name;
  std::string usage;
  std::string summary;             // One line: what it does.
  std::vector<std::string> flags;  // The flags it reads.
};

// What argv asks for before any command runs.
struct HelpRequest {
  enum Kind {
    kRun,
    kNoCommand,  // A bare `pfdm`: the overview, as a usage error.
    kOverview,
    kCommand,
    kVersion,
    kUsageError
  } kind = kRun;
  std::string command;  // kRun, kCommand: its name.
  std::string message;  // kUsageError: the one-line error.
};

// Reads argv without changing it: help and version requests, the command's
// name, and flags that are no flag of pfdm (kUsageError with the nearest
// valid name).  glog's and gflags' own flags stay accepted and unlisted.
HelpRequest ReadHelpRequest(int argc, const char* const* argv,
                            const std::vector<CommandHelp>& commands);

// The overview: what pfdm is, its commands, where the flags are.
std::string OverviewText(const std::vector<CommandHelp>& commands);
// One command's usage and flags, each with its default and meaning.
std::string CommandText(const CommandHelp& command);
// The version and how this binary was built.
std::string VersionText();

// Of `candidates`, the one closest to `name` by edit distance, or "" when
// none is close enough to be a slip (at most a third of the name's length,
// and at least 2, edits).
std::string NearestName(const std::string& name,
                        const std::vector<std::string>& candidates);

}  // namespace pfdm

#endif  // PFDM_CLI_HELP_H_
