#include "pfdm/solvers/damping_groups.h"

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include "pfdm/util/error.h"

namespace pfdm {

double DampingGroups::Of(Function f) const {
  switch (f) {
    case kTau:
    case kDtau:
      return twist;
    case kB0:
    case kB1:
    case kB2:
    case kB3:
      return bending;
    case kE1o:
    case kE2o:
    case kE3o:
      return offsets;
    default:
      return shape;
  }
}

DampingGroups DampingGroupsFromText(const std::string& text) {
  DampingGroups groups;
  const std::map<std::string, double*> by_name = {{"pose", &groups.pose},
                                                  {"shape", &groups.shape},
                                                  {"twist", &groups.twist},
                                                  {"bending", &groups.bending},
                                                  {"offsets", &groups.offsets}};
  std::istringstream entries(text);
  std::string entry;
  while (std::getline(entries, entry, ',')) {
    const size_t equals = entry.find('=');
    const auto group = by_name.find(entry.substr(0, equals));
    double value = 0.0;
    const char* first = entry.data() + equals + 1;
    const char* last = entry.data() + entry.size();
    const bool parsed = equals != std::string::npos &&
                        std::from_chars(first, last, value).ptr == last &&
                        first != last;
    if (group == by_name.end() || !parsed || !(value > 0.0) ||
        !std::isfinite(value)) {
      throw InputError("--damping_scale entry '" + entry +
                       "' is not group=value with a positive value and group "
                       "one of pose, shape, twist, bending, offsets");
    }
    *group->second = value;
  }
  return groups;
}

}  // namespace pfdm
