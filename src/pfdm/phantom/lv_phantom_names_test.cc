#include "pfdm/phantom/lv_phantom_names.h"

#include <string>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

std::string ErrorOf(const LvPhantomNames& names, const std::string& prefix) {
  LvPhantomOptions options;
  try {
    SetLvPhantomNames(names, prefix, &options);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(LvPhantomNamesTest, SetsEveryChoiceByName) {
  LvPhantomNames names;
  names.kinematics = "cycle";
  names.wall_tags = "wall";
  names.region = "midventricular";
  names.sampling = "sax-slices";
  names.geometry = "cylinder";
  names.thickening = "incompressible";
  LvPhantomOptions options;
  SetLvPhantomNames(names, "--", &options);
  EXPECT_EQ(options.kinematics, LvKinematics::kCycle);
  EXPECT_EQ(options.tags, LvTagLayer::kWall);
  EXPECT_EQ(options.region, LvRegion::kMidventricular);
  EXPECT_EQ(options.sampling, LvSampling::kSaxSlices);
  EXPECT_EQ(options.geometry, LvGeometry::kCylinder);
  EXPECT_EQ(options.law, LvThickeningLaw::kIncompressible);
  names.wall_tags = "endo";
  SetLvPhantomNames(names, "--", &options);
  EXPECT_EQ(options.tags, LvTagLayer::kEndocardium);
  EXPECT_EQ(LvTagLayerName(options.tags), "endo");
  names.wall_tags = "epi";
  SetLvPhantomNames(names, "--", &options);
  EXPECT_EQ(options.tags, LvTagLayer::kEpicardium);
  EXPECT_EQ(LvTagLayerName(options.tags), "epi");
}

TEST(LvPhantomNamesTest, UnknownNamesAreNamedWithTheirChoices) {
  LvPhantomNames names;
  names.region = "apical";
  EXPECT_EQ(ErrorOf(names, "--"),
            "unknown --region 'apical' (full, midventricular)");
  EXPECT_EQ(ErrorOf(names, ""),
            "unknown region 'apical' (full, midventricular)");
  EXPECT_EQ(ErrorOf(LvPhantomNames(), ""), "no error");
}

}  // namespace
}  // namespace pfdm
