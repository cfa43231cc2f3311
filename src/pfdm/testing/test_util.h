// Helpers shared by the tests: scratch folders and running the pfdm binary.
#ifndef PFDM_TESTING_TEST_UTIL_H_
#define PFDM_TESTING_TEST_UTIL_H_

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pfdm {

// A fresh empty folder, <temp dir>/pfdm_tests/<Suite.Test>/<name>_<n>,
// unique per call within a test; kept after the test so that its files
// (plots, reports, meshes) can be looked at, replaced when the test reruns.
std::string ScratchDirectory(const std::string& name);

void WriteText(const std::string& path, const std::string& text);
// How often `what` occurs in text (overlaps counted).
int CountOf(const std::string& text, const std::string& what);
// A page without its scripts' text (report.html's 3D view bundle and scene
// JSON, where "nan" is a word of three.js), for checks of its own words.
std::string WithoutScripts(std::string html);
std::string ReadText(const std::string& path);
// The message of the InputError that run throws, or "" if it throws none.
std::string InputErrorOf(const std::function<void()>& run);

struct CommandResult {
  int exit_code = 0;
  std::string output;  // stdout
  std::string error;   // stderr
};

// Runs the built pfdm binary with the given arguments (shell-quoted by the
// caller where needed).
CommandResult RunPfdm(const std::string& arguments);

// The arrays of a VTK XML file written with appended raw data (header_type
// UInt64), read back independently of the writer: keyed by section and
// name ("PointData/u", "Points", "Polys/connectivity"), Float64 and
// Float32 arrays in float64, Int64 and Int32 ones in int64, each array's
// VTK type in types.  Fails the test on a malformed file.
struct VtkXmlArrays {
  std::map<std::string, std::vector<double>> float64;
  std::map<std::string, std::vector<std::int64_t>> int64;
  std::map<std::string, std::string> types;
};
VtkXmlArrays ReadAppendedRawVtkXml(const std::string& xml);

// Expects a and b equal to the bit (NaN where the other is NaN), naming
// `what` and the index of each that differs.
void ExpectSameBits(const std::vector<double>& a, const std::vector<double>& b,
                    const std::string& what);

// ../shared/data beside the source tree, or "" when it is absent.
std::string SharedDataDirectory();

}  // namespace pfdm

#endif  // PFDM_TESTING_TEST_UTIL_H_
