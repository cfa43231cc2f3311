// --labels: which label value is the LV cavity, the myocardium and the RV.
#ifndef PFDM_IO_LABEL_MAP_H_
#define PFDM_IO_LABEL_MAP_H_

#include <string>

#include "pfdm/segmentation/label_volume.h"

namespace pfdm {

// "acdc" (lv=3,myo=2,rv=1, ACDC's), "mnms" (lv=1,myo=2,rv=3, M&Ms'), or
// "lv=N,myo=N[,rv=N|none]" with whole numbers 1 to 65535, all different.
// Throws InputError naming --labels and what is wrong.
LabelMap ParseLabelMap(const std::string& text);

}  // namespace pfdm

#endif  // PFDM_IO_LABEL_MAP_H_
