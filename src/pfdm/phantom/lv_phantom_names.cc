#include "pfdm/phantom/lv_phantom_names.h"

#include "pfdm/phantom/lv_cylinder.h"
#include "pfdm/phantom/lv_motion.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

void Check(bool known, const std::string& prefix, const char* name,
           const std::string& value, const char* choices) {
  if (known) return;
  throw InputError("unknown " + prefix + name + " '" + value + "' (" + choices +
                   ")");
}

}  // namespace

void SetLvPhantomNames(const LvPhantomNames& names, const std::string& prefix,
                       LvPhantomOptions* options) {
  Check(ParseLvKinematics(names.kinematics, &options->kinematics), prefix,
        "kinematics", names.kinematics,
        "systole, cycle, rigid-axial, rigid-lateral, rigid-tilt, rigid-spin, "
        "static");
  Check(ParseLvTagLayer(names.wall_tags, &options->tags), prefix, "wall_tags",
        names.wall_tags, "midwall, wall, endo, epi");
  Check(ParseLvRegion(names.region, &options->region), prefix, "region",
        names.region, "full, midventricular");
  Check(ParseLvSampling(names.sampling, &options->sampling), prefix, "sampling",
        names.sampling, "tags, sax-slices");
  Check(ParseLvGeometry(names.geometry, &options->geometry), prefix, "geometry",
        names.geometry, "prolate, cylinder");
  Check(ParseLvThickeningLaw(names.thickening, &options->law), prefix,
        "thickening", names.thickening, "designed, incompressible");
}

}  // namespace pfdm
