#include "pfdm/batch/case_folder.h"

#include <filesystem>
#include <string>

#include "gtest/gtest.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFitJson = R"({
  "ejection_fraction": {"ratio": 0.5, "ed_frame": 0, "es_frame": 1,
                        "edv_ml": 120.0, "esv_ml": 60.0},
  "frames": [
    {"rms_mm": 0.5, "clinical": {"net_twist_deg": 0.0,
      "longitudinal_shortening_percent": 0.0,
      "radial_contraction_percent": 0.0}},
    {"rms_mm": 0.75, "clinical": {"net_twist_deg": 10.0,
      "longitudinal_shortening_percent": 15.0,
      "radial_contraction_percent": 20.0}}]})";

std::string Marked(const std::string& dir) {
  fs::create_directories(dir);
  WriteText(dir + "/" + kOutputMarker, "");
  return dir;
}

TEST(CaseFolderTest, OnlyNewEmptyOrMarkedFoldersArePfdms) {
  const std::string out = ScratchDirectory("case_folder");
  EXPECT_EQ(CaseFolderRefusal(out + "/new"), "");
  fs::create_directories(out + "/empty");
  EXPECT_EQ(CaseFolderRefusal(out + "/empty"), "");
  WriteText(Marked(out + "/marked") + "/fit.json", "{}");
  EXPECT_EQ(CaseFolderRefusal(out + "/marked"), "");

  WriteText(out + "/plain", "x");
  EXPECT_EQ(CaseFolderRefusal(out + "/plain"),
            out +
                "/plain: is a file, not a case folder; pfdm batch leaves it "
                "alone");
  fs::create_directory_symlink(out + "/marked", out + "/link");
  EXPECT_EQ(CaseFolderRefusal(out + "/link"),
            out +
                "/link: is a link, not a case folder of pfdm's; pfdm batch "
                "does not write through it");
  fs::create_directories(out + "/theirs");
  WriteText(out + "/theirs/fit.json", kFitJson);
  EXPECT_EQ(CaseFolderRefusal(out + "/theirs"),
            out +
                "/theirs: holds files pfdm did not mark as its own (no "
                ".pfdm-fit); pfdm batch leaves it alone: move them, or "
                "create that file if an older pfdm wrote them");
  // A marker that is not a plain file marks nothing.
  fs::create_directories(out + "/linked_marker");
  fs::create_symlink(out + "/marked/.pfdm-fit",
                     out + "/linked_marker/.pfdm-fit");
  EXPECT_EQ(CaseFolderRefusal(out + "/linked_marker"),
            out + "/linked_marker/.pfdm-fit: is not a plain file, so " + out +
                "/linked_marker is not a case folder of pfdm's; pfdm batch "
                "leaves it alone");
  fs::create_directories(out + "/folder_marker/.pfdm-fit");
  EXPECT_NE(CaseFolderRefusal(out + "/folder_marker"), "");
}

TEST(CaseFolderTest, ClaimingMakesAndMarksButNeverTakesAnothersFolder) {
  const std::string out = ScratchDirectory("case_folder");
  ClaimCaseFolder(out + "/new");
  EXPECT_EQ(ReadText(out + "/new/.pfdm-fit"), kOutputMarkerText);
  ClaimCaseFolder(out + "/new");  // Already pfdm's: fine.
  fs::create_directories(out + "/empty");
  ClaimCaseFolder(out + "/empty");
  EXPECT_TRUE(fs::is_regular_file(out + "/empty/.pfdm-fit"));

  fs::create_directories(out + "/elsewhere");
  fs::create_directory_symlink(out + "/elsewhere", out + "/link");
  EXPECT_EQ(InputErrorOf([&] { ClaimCaseFolder(out + "/link"); }),
            CaseFolderRefusal(out + "/link"));
  EXPECT_TRUE(fs::is_empty(out + "/elsewhere"));
  // Not its parents: the output folder is made by the batch itself.
  EXPECT_EQ(InputErrorOf([&] { ClaimCaseFolder(out + "/a/b"); }),
            out + "/a/b: cannot create folder: No such file or directory");
  fs::create_directory_symlink(out + "/nowhere", out + "/dangling");
  EXPECT_NE(InputErrorOf([&] { ClaimCaseFolder(out + "/dangling"); }), "");
  EXPECT_FALSE(fs::exists(out + "/nowhere"));
}

TEST(CaseFolderTest, StatusFromTheFolderItself) {
  const std::string out = ScratchDirectory("case_folder");
  EXPECT_EQ(CaseStatus(out + "/absent", "a").status, "pending");
  EXPECT_EQ(CaseStatus(Marked(out + "/started"), "a").status, "pending");

  WriteText(Marked(out + "/failed") + "/error.txt", "p.csv: no rows\n\n");
  CaseSummary s = CaseStatus(out + "/failed", "a");
  EXPECT_EQ(s.status, "failed");
  EXPECT_EQ(s.error, "p.csv: no rows");

  WriteText(Marked(out + "/done") + "/fit.json", kFitJson);
  s = CaseStatus(out + "/done", "a");
  EXPECT_EQ(s.name, "a");
  EXPECT_EQ(s.status, "done");
  EXPECT_EQ(s.frames, 2);
  EXPECT_EQ(s.max_rms_mm, 0.75);
  EXPECT_EQ(s.ejection_fraction, 0.5);

  // The same fit.json in a folder pfdm did not mark is not a result.
  fs::create_directories(out + "/theirs");
  WriteText(out + "/theirs/fit.json", kFitJson);
  s = CaseStatus(out + "/theirs", "a");
  EXPECT_EQ(s.status, "failed");
  EXPECT_EQ(s.error, CaseFolderRefusal(out + "/theirs"));
  EXPECT_EQ(s.frames, 0);

  // A link at fit.json or error.txt is named, not read.
  fs::create_symlink(out + "/done/fit.json",
                     Marked(out + "/linked") + "/fit.json");
  s = CaseStatus(out + "/linked", "a");
  EXPECT_EQ(s.status, "failed");
  EXPECT_EQ(s.error,
            out + "/linked/fit.json: is a link, not a file pfdm wrote");
  fs::create_symlink(out + "/failed/error.txt",
                     Marked(out + "/linked_error") + "/error.txt");
  EXPECT_EQ(CaseStatus(out + "/linked_error", "a").error,
            out + "/linked_error/error.txt: is a link, not a file pfdm wrote");
  fs::create_directories(Marked(out + "/folder") + "/fit.json");
  EXPECT_EQ(CaseStatus(out + "/folder", "a").error,
            out + "/folder/fit.json: is not a plain file");
}

}  // namespace
}  // namespace pfdm
