#include "pfdm/cli/help.h"

#include <algorithm>
#include <sstream>

#include "Eigen/Core"
#include "ceres/version.h"
#include "gflags/gflags.h"
#include "pfdm/util/version.h"

#ifndef PFDM_BUILD_TYPE
#define PFDM_BUILD_TYPE "unknown"
#endif

namespace pfdm {
namespace {

constexpr int kTextWidth = 80;
#ifdef __clang__
constexpr char kCompiler[] = "";  // __VERSION__ names clang.
#else
constexpr char kCompiler[] = "gcc ";
#endif
constexpr int kDescriptionColumn = 26;

bool IsHelpFlag(const std::string& arg) {
  return arg == "-h" || arg == "--help" || arg == "-help" ||
         arg == "--helpfull" || arg == "-helpfull";
}

bool IsVersionFlag(const std::string& arg) {
  return arg == "--version" || arg == "-version";
}

const CommandHelp* FindCommand(const std::vector<CommandHelp>& commands,
                               const std::string& name) {
  for (const CommandHelp& command : commands) {
    if (command.name == name) return &command;
  }
  return nullptr;
}

std::vector<std::string> CommandNames(
    const std::vector<CommandHelp>& commands) {
  std::vector<std::string> names;
  for (const CommandHelp& command : commands) names.push_back(command.name);
  return names;
}

// Every flag some command reads: the names a slip is measured against when
// the command is not known yet.
std::vector<std::string> AllFlags(const std::vector<CommandHelp>& commands) {
  std::vector<std::string> flags;
  for (const CommandHelp& command : commands) {
    flags.insert(flags.end(), command.flags.begin(), command.flags.end());
  }
  std::sort(flags.begin(), flags.end());
  flags.erase(std::unique(flags.begin(), flags.end()), flags.end());
  return flags;
}

// "--name=value", "-name value", "--noname": the name, and whether the next
// argument is the value.  gflags takes a bool's value only after '='.
struct FlagArgument {
  std::string name;
  bool known = false;
  bool takes_next = false;
};

FlagArgument ReadFlagArgument(const std::string& arg) {
  FlagArgument flag;
  const size_t start = arg.find_first_not_of('-');
  const size_t equals = arg.find('=');
  flag.name = arg.substr(
      start, equals == std::string::npos ? std::string::npos : equals - start);
  gflags::CommandLineFlagInfo info;
  if (gflags::GetCommandLineFlagInfo(flag.name.c_str(), &info)) {
    flag.known = true;
    flag.takes_next = equals == std::string::npos && info.type != "bool";
  } else if (flag.name.rfind("no", 0) == 0 &&
             gflags::GetCommandLineFlagInfo(flag.name.substr(2).c_str(),
                                            &info) &&
             info.type == "bool") {
    flag.known = true;
  }
  return flag;
}

HelpRequest UsageError(const std::string& message) {
  HelpRequest request;
  request.kind = HelpRequest::kUsageError;
  request.message = message;
  return request;
}

HelpRequest UnknownFlag(const std::string& name, const CommandHelp* command,
                        const std::vector<CommandHelp>& commands) {
  const std::string nearest =
      NearestName(name, command ? command->flags : AllFlags(commands));
  std::string message = "unknown flag --" + name;
  if (command) message += " for " + command->name;
  if (!nearest.empty()) message += " (did you mean --" + nearest + "?)";
  return UsageError(message + "; see 'pfdm " +
                    (command ? command->name + " --help'" : "--help'"));
}

HelpRequest UnknownCommand(const std::string& name,
                           const std::vector<CommandHelp>& commands) {
  const std::string nearest = NearestName(name, CommandNames(commands));
  return UsageError(
      "unknown command '" + name + "'" +
      (nearest.empty() ? "" : " (did you mean " + nearest + "?)") +
      "; see 'pfdm --help'");
}

// `pfdm help [CMD]`.
HelpRequest HelpCommand(const std::vector<std::string>& positionals,
                        const std::vector<CommandHelp>& commands) {
  HelpRequest request;
  if (positionals.size() < 2) {
    request.kind = HelpRequest::kOverview;
    return request;
  }
  if (!FindCommand(commands, positionals[1])) {
    return UnknownCommand(positionals[1], commands);
  }
  request.kind = HelpRequest::kCommand;
  request.command = positionals[1];
  return request;
}

// Wraps `text` to the description column.
std::string Wrapped(const std::string& text) {
  std::istringstream words(text);
  std::string word, out, line;
  const int width = kTextWidth - kDescriptionColumn;
  while (words >> word) {
    if (!line.empty() &&
        static_cast<int>(line.size() + 1 + word.size()) > width) {
      out += line + "\n" + std::string(kDescriptionColumn, ' ');
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

std::string FlagLine(const std::string& name) {
  gflags::CommandLineFlagInfo info;
  if (!gflags::GetCommandLineFlagInfo(name.c_str(), &info)) return "";
  std::string head = "  --" + name;
  if (info.type == "string") {
    head += "=\"" + info.default_value + "\"";
  } else {
    head += "=" + info.default_value;
  }
  head += head.size() + 2 > kDescriptionColumn
              ? "\n" + std::string(kDescriptionColumn, ' ')
              : std::string(kDescriptionColumn - head.size(), ' ');
  return head + Wrapped(info.description) + "\n";
}

}  // namespace

std::string NearestName(const std::string& name,
                        const std::vector<std::string>& candidates) {
  std::string nearest;
  size_t best = std::max<size_t>(2, name.size() / 3) + 1;
  for (const std::string& candidate : candidates) {
    // Levenshtein distance, one row at a time.
    std::vector<size_t> row(candidate.size() + 1);
    for (size_t j = 0; j < row.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= name.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= candidate.size(); ++j) {
        const size_t substitution =
            diagonal + (name[i - 1] == candidate[j - 1] ? 0 : 1);
        diagonal = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
      }
    }
    if (row.back() < best) {
      best = row.back();
      nearest = candidate;
    }
  }
  return nearest;
}

HelpRequest ReadHelpRequest(int argc, const char* const* argv,
                            const std::vector<CommandHelp>& commands) {
  std::vector<std::string> positionals;
  std::vector<std::string> unknown;
  bool help = false, version = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (IsHelpFlag(arg)) {
      help = true;
    } else if (IsVersionFlag(arg)) {
      version = true;
    } else if (arg == "--") {
      break;
    } else if (arg.size() > 1 && arg[0] == '-') {
      const FlagArgument flag = ReadFlagArgument(arg);
      if (!flag.known) unknown.push_back(flag.name);
      if (flag.takes_next && i + 1 == argc) {
        return UsageError("--" + flag.name + " needs a value");
      }
      if (flag.takes_next) ++i;
    } else {
      positionals.push_back(arg);
    }
  }
  HelpRequest request;
  if (version) {
    request.kind = HelpRequest::kVersion;
    return request;
  }
  if (!positionals.empty() && positionals[0] == "help") {
    return HelpCommand(positionals, commands);
  }
  const CommandHelp* command =
      positionals.empty() ? nullptr : FindCommand(commands, positionals[0]);
  if (!positionals.empty() && !command && !help) {
    return UnknownCommand(positionals[0], commands);
  }
  if (help) {
    request.kind = command ? HelpRequest::kCommand : HelpRequest::kOverview;
    if (command) request.command = command->name;
    return request;
  }
  if (!unknown.empty()) return UnknownFlag(unknown[0], command, commands);
  if (!command) {
    request.kind = HelpRequest::kNoCommand;
    return request;
  }
  if (positionals.size() > 1) {
    return UsageError("unexpected argument '" + positionals[1] +
                      "' (flags are --name=value); see 'pfdm " + command->name +
                      " --help'");
  }
  request.command = command->name;
  return request;
}

std::string OverviewText(const std::vector<CommandHelp>& commands) {
  std::string text =
      "pfdm " + std::string(PfdmVersion()) +
      ": fits deformable models with parameter functions (Park, Metaxas\n"
      "and Young, CVPR 1994) to tracked tags or contours of the left "
      "ventricle.\n\nusage: pfdm <command> [--flag=value ...]\n\ncommands:\n";
  for (const CommandHelp& command : commands) {
    std::string head = "  " + command.name;
    head += std::string(std::max<int>(1, 18 - head.size()), ' ');
    text += head + command.summary + "\n";
  }
  return text +
         "\n'pfdm help <command>' or 'pfdm <command> --help' lists a "
         "command's flags; 'pfdm --version' the version.\n";
}

std::string CommandText(const CommandHelp& command) {
  std::string text = "usage: pfdm " + command.name + " " + command.usage +
                     "\n\n" + command.summary +
                     ".\n\nflags (default after =):\n";
  std::vector<std::string> flags = command.flags;
  std::sort(flags.begin(), flags.end());
  for (const std::string& flag : flags) text += FlagLine(flag);
  return text;
}

std::string VersionText() {
  return "pfdm " + std::string(PfdmVersion()) + " (" + PFDM_BUILD_TYPE +
         " build, " + kCompiler + __VERSION__ +
         ", Ceres " CERES_VERSION_STRING + ", Eigen " +
         std::to_string(EIGEN_WORLD_VERSION) + "." +
         std::to_string(EIGEN_MAJOR_VERSION) + "." +
         std::to_string(EIGEN_MINOR_VERSION) + ")\n";
}

}  // namespace pfdm
