#include "pfdm/batch/batch_summary.h"

#include <cmath>
#include <string>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

constexpr const char* kFitJson = R"({
  "ejection_fraction": {"ratio": 0.6, "ed_frame": 0, "es_frame": 1,
                        "edv_ml": 150.0, "esv_ml": 60.0},
  "frames": [
    {"rms_mm": 0.5, "clinical": {"net_twist_deg": 0.0,
      "longitudinal_shortening_percent": 0.0,
      "radial_contraction_percent": 0.0}},
    {"rms_mm": 1.25, "clinical": {"net_twist_deg": 12.5,
      "longitudinal_shortening_percent": 15.0,
      "radial_contraction_percent": 25.0}},
    {"rms_mm": 0.75, "clinical": {"net_twist_deg": 3.0,
      "longitudinal_shortening_percent": 5.0,
      "radial_contraction_percent": 5.0}}],
  "strain": {"peak_gcs_percent": -18.5, "peak_gcs_frame": 1,
             "peak_gls_percent": -14.25, "peak_gls_frame": 1}})";

TEST(BatchSummaryTest, ReadsTheNumbersAtEndSystoleFromFitJson) {
  const CaseSummary s = SummaryFromFitJson("p1", kFitJson, "p1/fit.json");
  EXPECT_EQ(s.status, "done");
  EXPECT_EQ(s.frames, 3);
  EXPECT_EQ(s.max_rms_mm, 1.25);
  EXPECT_EQ(s.es_frame, 1);
  EXPECT_EQ(s.ejection_fraction, 0.6);
  EXPECT_EQ(s.net_twist_deg, 12.5);
  EXPECT_EQ(s.longitudinal_shortening_percent, 15.0);
  EXPECT_EQ(s.radial_contraction_percent, 25.0);
  EXPECT_TRUE(s.has_strain);
  EXPECT_EQ(s.peak_gcs_percent, -18.5);
  EXPECT_EQ(s.peak_gls_percent, -14.25);
  EXPECT_THROW(SummaryFromFitJson("p1", "{\"frames\": []}", "p1/fit.json"),
               InputError);
}

TEST(BatchSummaryTest, CsvRowsQuoteWhatNeedsIt) {
  CaseSummary done = SummaryFromFitJson("p1", kFitJson, "x");
  // A fit.json from before strain was reported: empty strain columns.
  std::string old_json = kFitJson;
  old_json = old_json.substr(0, old_json.find(",\n  \"strain\"")) + "}";
  CaseSummary old = SummaryFromFitJson("p0", old_json, "x");
  EXPECT_FALSE(old.has_strain);
  CaseSummary failed;
  failed.name = "p2";
  failed.status = "failed";
  failed.error = "p2.csv:3: column 'x' is not a \"number\", sorry";
  CaseSummary pending;
  pending.name = "p3";
  pending.status = "pending";
  EXPECT_EQ(SummaryCsv({old, done, failed, pending}),
            "case,status,quality,frames,max_rms_mm,volume_surface,"
            "ed_volume_ml,es_volume_ml,es_frame,ejection_fraction,lv_mass_g,"
            "wall_thickening_at_es_percent,net_twist_at_es_deg,"
            "longitudinal_shortening_at_es_percent,"
            "radial_contraction_at_es_percent,peak_gcs_percent,"
            "peak_gls_percent,quality_reasons,error\n"
            "p0,done,,3,1.25,cavity,150,60,1,0.6,,,12.5,15,25,,,,\n"
            "p1,done,,3,1.25,cavity,150,60,1,0.6,,,12.5,15,25,-18.5,-14.25,,"
            "\n"
            "p2,failed,,,,,,,,,,,,,,,,,\"p2.csv:3: column 'x' is not a "
            "\"\"number\"\", sorry\"\n"
            "p3,pending,,,,,,,,,,,,,,,,,\n");
}

// fit.json's verdict: the overall quality and the frames' distinct
// reasons, each once, in the order they first appear.
TEST(BatchSummaryTest, ReadsTheQualityAndItsReasons) {
  std::string json = kFitJson;
  json.insert(1, R"("quality": {"overall": "warning"},)");
  const std::string frame = "{\"rms_mm\": 0.5,";
  const std::string reasons =
      R"("quality_reasons": [{"severity": "warning", "code": "unsettled",
      "text": "closest points still moving"}, {"severity": "warning",
      "code": "solver", "text": "NO_CONVERGENCE"}],)";
  json.replace(json.find(frame), frame.size(), frame + reasons);
  const CaseSummary s = SummaryFromFitJson("q", json, "q/fit.json");
  EXPECT_EQ(s.quality, "warning");
  EXPECT_EQ(s.quality_reasons,
            (std::vector<std::string>{"unsettled", "solver"}));
  const std::string csv = SummaryCsv({s});
  EXPECT_NE(csv.find("\nq,done,warning,3,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",unsettled;solver,\n"), std::string::npos) << csv;
}

// A null net twist at ES (no tracked points there: contours) is an empty
// column, as every number that does not apply; the others stay.
TEST(BatchSummaryTest, TwistNotMeasuredIsAnEmptyColumn) {
  EXPECT_TRUE(SummaryFromFitJson("t", kFitJson, "x").twist_measured);
  std::string contours = kFitJson;
  const std::string twist = "\"net_twist_deg\": 12.5";
  contours.replace(contours.find(twist), twist.size(),
                   "\"net_twist_deg\": null");
  const CaseSummary c = SummaryFromFitJson("c", contours, "c/fit.json");
  EXPECT_FALSE(c.twist_measured);
  EXPECT_EQ(c.longitudinal_shortening_percent, 15.0);
  EXPECT_EQ(SummaryCsv({c}).substr(SummaryCsv({c}).find('\n') + 1),
            "c,done,,3,1.25,cavity,150,60,1,0.6,,,,15,25,-18.5,-14.25,,\n");
  // Null elsewhere than at ES does not matter.
  std::string elsewhere = kFitJson;
  const std::string frame0 = "\"net_twist_deg\": 0.0";
  elsewhere.replace(elsewhere.find(frame0), frame0.size(),
                    "\"net_twist_deg\": null");
  const CaseSummary e = SummaryFromFitJson("e", elsewhere, "e/fit.json");
  EXPECT_TRUE(e.twist_measured);
  EXPECT_EQ(e.net_twist_deg, 12.5);
}

// A frame without a volume (its data span too little of the axis): null
// ESV and ratio in fit.json are empty columns, not a failed case.
TEST(BatchSummaryTest, NullVolumesAreEmptyColumns) {
  std::string json = kFitJson;
  for (const std::string number : {"\"ratio\": 0.6", "\"esv_ml\": 60.0"}) {
    const std::string key = number.substr(0, number.find(':'));
    json.replace(json.find(number), number.size(), key + ": null");
  }
  const CaseSummary c = SummaryFromFitJson("s", json, "s/fit.json");
  EXPECT_TRUE(std::isnan(c.esv_ml));
  EXPECT_TRUE(std::isnan(c.ejection_fraction));
  EXPECT_EQ(c.edv_ml, 150.0);
  EXPECT_EQ(SummaryCsv({c}).substr(SummaryCsv({c}).find('\n') + 1),
            "s,done,,3,1.25,cavity,150,,1,,,,12.5,15,25,-18.5,-14.25,,\n");
}

// A solid's fit.json: the cavity's ejection fraction, the LV mass at ED
// and the thickening at ES; a mid-wall surface's: no ejection fraction.
TEST(BatchSummaryTest, NamesWhatTheVolumesEnclose) {
  std::string solid = kFitJson;
  solid.insert(1, R"("model": {"wall": "solid", "volume_surface": "cavity"},)");
  const std::string es = "\"radial_contraction_percent\": 25.0";
  solid.replace(solid.find(es), es.size(),
                es + ", \"wall_thickening_percent\": 41.5");
  const std::string ed = "{\"rms_mm\": 0.5,";
  solid.replace(solid.find(ed), ed.size(), ed + " \"lv_mass_g\": 120.5,");
  const CaseSummary s = SummaryFromFitJson("s", solid, "s/fit.json");
  EXPECT_TRUE(s.solid);
  EXPECT_EQ(s.lv_mass_g, 120.5);
  EXPECT_EQ(s.wall_thickening_percent, 41.5);
  std::string midwall = kFitJson;
  midwall.replace(midwall.find("\"ejection_fraction\""), 19,
                  "\"midwall_volume_fraction\"");
  midwall.insert(1, R"("model": {"wall": "midwall",
                                 "volume_surface": "midwall"},)");
  const CaseSummary m = SummaryFromFitJson("m", midwall, "m/fit.json");
  EXPECT_EQ(m.volume_surface, "midwall");
  const std::string csv = SummaryCsv({s, m});
  EXPECT_NE(csv.find("\ns,done,,3,1.25,cavity,150,60,1,0.6,120.5,41.5,12.5,"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\nm,done,,3,1.25,midwall,150,60,1,,,,12.5,"),
            std::string::npos)
      << csv;
}

// With --uncertainty on: the half-widths of fit.json's intervals in
// columns of their own after the others, empty for a case without.
TEST(BatchSummaryTest, HalfWidthColumnsWhenACaseHasIntervals) {
  std::string text = kFitJson;
  text.replace(text.find("\"edv_ml\": 150.0"), 15,
               "\"edv_ml\": 150.0, \"edv_ml_ci95\": [146.0, 154.0]");
  text.replace(text.find("\"peak_gcs_frame\""), 16,
               "\"peak_gcs_percent_ci95\": [-19.5, -17.5], \"peak_gcs_frame\"");
  text.insert(1, "\"uncertainty_definition\": \"...\", ");
  const CaseSummary with = SummaryFromFitJson("a", text, "a/fit.json");
  EXPECT_TRUE(with.has_intervals);
  ASSERT_EQ(with.half_widths.size(), 10u);
  EXPECT_EQ(with.half_widths[0], 4.0);
  EXPECT_EQ(with.half_widths[8], 1.0);
  EXPECT_TRUE(std::isnan(with.half_widths[1]));
  const CaseSummary without = SummaryFromFitJson("b", kFitJson, "b/fit.json");
  EXPECT_FALSE(without.has_intervals);
  const std::string csv = SummaryCsv({with, without});
  EXPECT_NE(csv.find("error,ed_volume_ml_hw95,es_volume_ml_hw95,"),
            std::string::npos);
  EXPECT_NE(csv.find(",4,,,,,,,,1,\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nb,done"), std::string::npos);
  // Without any intervals the columns are not there.
  EXPECT_EQ(SummaryCsv({without}).find("_hw95"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
