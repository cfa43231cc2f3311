// The LV phantom's choices by name, as `pfdm simulate --phantom lv` and
// Python's simulate(phantom="lv") take them: one parser, one message.
#ifndef PFDM_PHANTOM_LV_PHANTOM_NAMES_H_
#define PFDM_PHANTOM_LV_PHANTOM_NAMES_H_

#include <string>

#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {

struct LvPhantomNames {
  std::string kinematics = "systole";
  std::string wall_tags = "midwall";
  std::string region = "full";
  std::string sampling = "tags";
  std::string geometry = "prolate";
  std::string thickening = "designed";
};

// Sets `options`' kinematics, tags, region, sampling, geometry and law from
// the names.  Throws InputError "unknown <prefix>kinematics 'x' (systole,
// ...)" for a name it does not know; prefix "--" for the CLI's flags, ""
// for Python's keywords.
void SetLvPhantomNames(const LvPhantomNames& names, const std::string& prefix,
                       LvPhantomOptions* options);

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_PHANTOM_NAMES_H_
