#include "pfdm/report/plausibility.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// ED 120 ml, ES 46 ml, a solid of 130 g that keeps its myocardium.
std::vector<ClinicalSummary> NormalCycle() {
  std::vector<ClinicalSummary> frames(3);
  const double volumes[] = {120.0, 80.0, 46.0};
  for (int t = 0; t < 3; ++t) {
    frames[t].frame = t;
    frames[t].volume_ml = volumes[t];
    frames[t].solid = true;
    frames[t].myocardial_volume_ml = 124.0;
    frames[t].lv_mass_g = 130.0;
  }
  return frames;
}

EjectionFraction Ejection(const std::vector<ClinicalSummary>& frames) {
  return {0, 2, frames[0].volume_ml, frames[2].volume_ml,
          1.0 - frames[2].volume_ml / frames[0].volume_ml};
}

std::string Codes(const std::vector<ClinicalSummary>& frames, size_t t,
                  const std::string& surface = "cavity", bool slab = false) {
  const Verdict verdict =
      JudgeClinical(frames, Ejection(frames), surface, t, slab);
  std::string codes;
  for (const VerdictReason& reason : verdict.reasons()) {
    codes += (codes.empty() ? "" : ",") + reason.code + "/" +
             QualityName(reason.severity);
  }
  return codes;
}

TEST(PlausibilityTest, ANormalHeartPasses) {
  const std::vector<ClinicalSummary> frames = NormalCycle();
  for (size_t t = 0; t < frames.size(); ++t) EXPECT_EQ(Codes(frames, t), "");
}

// Data in metres: every volume a billionth of a millilitre.
TEST(PlausibilityTest, FailsVolumesNoHeartHas) {
  std::vector<ClinicalSummary> frames = NormalCycle();
  for (ClinicalSummary& c : frames) {
    c.volume_ml *= 1e-9;
    c.myocardial_volume_ml *= 1e-9;
    c.lv_mass_g *= 1e-9;
  }
  EXPECT_EQ(Codes(frames, 0), "volume_range/failed,mass/failed");
  const Verdict verdict = JudgeClinical(frames, Ejection(frames), "cavity", 0);
  EXPECT_EQ(verdict.reasons()[0].text,
            "cavity volume 1.2e-07 ml is outside 2-1500 ml (are the data in "
            "mm?)");
  frames = NormalCycle();
  frames[1].volume_ml = 3.6e12;
  EXPECT_EQ(Codes(frames, 1, "midwall"),
            "volume_range/failed,frame_motion/failed");
}

TEST(PlausibilityTest, FailsANegativeMassAndAMyocardiumThatGrows) {
  std::vector<ClinicalSummary> frames = NormalCycle();
  frames[1].lv_mass_g = -12.4;
  frames[1].myocardial_volume_ml = -11.8;
  EXPECT_EQ(Codes(frames, 1), "mass/failed,myocardium/failed");
  frames = NormalCycle();
  frames[2].myocardial_volume_ml = 124.0 * 1.12;  // +12 %: a warning.
  frames[2].lv_mass_g = 130.0 * 1.12;
  EXPECT_EQ(Codes(frames, 2), "myocardium/warning");
}

// Contours between fixed image planes: their slab's muscle grows at ES (as
// the truth's does on the LV phantom's mid-ventricular slices), a warning
// that says why, never a failure; the mass still fails when the walls
// cross.
TEST(PlausibilityTest, ASlabsMyocardiumMayChange) {
  std::vector<ClinicalSummary> frames = NormalCycle();
  frames[2].myocardial_volume_ml = 124.0 * 1.3;
  EXPECT_EQ(Codes(frames, 2), "myocardium/failed");
  EXPECT_EQ(Codes(frames, 2, "cavity", true), "myocardium/warning");
  const Verdict verdict =
      JudgeClinical(frames, Ejection(frames), "cavity", 2, true);
  EXPECT_NE(verdict.reasons()[0].text.find("image planes"), std::string::npos);
  frames[2].myocardial_volume_ml = 124.0 * 1.05;
  EXPECT_EQ(Codes(frames, 2, "cavity", true), "");
  frames[1].lv_mass_g = -12.4;
  EXPECT_EQ(Codes(frames, 1, "cavity", true), "mass/failed");
}

// Ids scrambled between frames: the cavity goes from 180 to 3.9 ml.
TEST(PlausibilityTest, FailsMotionNoHeartMakes) {
  std::vector<ClinicalSummary> frames = NormalCycle();
  frames[1].volume_ml = 120.0 / 9.0;
  frames[2].volume_ml = 15.0;
  EXPECT_EQ(Codes(frames, 1), "frame_motion/failed");
  EXPECT_EQ(Codes(frames, 2), "");  // 13 ml to 15 ml is a heart's step.
}

// A random cloud's EF of 0.96.
TEST(PlausibilityTest, FailsAnEjectionFractionAboveAnyHearts) {
  std::vector<ClinicalSummary> frames = NormalCycle();
  frames[1].volume_ml = 30.0;
  frames[2].volume_ml = 4.8;
  EXPECT_EQ(Codes(frames, 2), "ejection/failed");
  EXPECT_EQ(Codes(frames, 2, "midwall"), "");  // Not an ejection fraction.
}

}  // namespace
}  // namespace pfdm
