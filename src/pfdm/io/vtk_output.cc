#include "pfdm/io/vtk_output.h"

#include <sstream>

#include "pfdm/util/error.h"

namespace pfdm {

VtkOutput VtkOutputFromNames(const std::string& format,
                             const std::string& precision) {
  VtkOutput output;
  output.precision = VtkPrecisionFromName(precision);
  bool files_named = false, encoding_named = false;
  std::istringstream words(format);
  std::string word;
  const auto refuse = [&format](const std::string& why) {
    throw InputError("--vtk_format '" + format + "': " + why +
                     " (expected vtp, vtk or both, and binary or ascii, "
                     "comma-separated)");
  };
  if (format.empty()) refuse("empty");
  while (std::getline(words, word, ',')) {
    bool* named = &files_named;
    if (word == "vtp") {
      output.files = VtkFiles::kVtp;
    } else if (word == "vtk") {
      output.files = VtkFiles::kVtk;
    } else if (word == "both") {
      output.files = VtkFiles::kBoth;
    } else if (word == "binary" || word == "ascii") {
      output.format = VtkFormatFromName(word);
      named = &encoding_named;
    } else {
      refuse("unknown word '" + word + "'");
    }
    if (*named) refuse("'" + word + "' contradicts or repeats another word");
    *named = true;
  }
  if (format.back() == ',') refuse("unknown word ''");
  return output;
}

}  // namespace pfdm
