#include "pfdm/batch/batch_manifest.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

std::string ErrorOf(const std::string& path) {
  return InputErrorOf([&] { ReadManifest(path); });
}

TEST(BatchManifestTest, ReadsCasesResolvingPathsAgainstTheManifest) {
  const std::string dir = ScratchDirectory("manifest");
  WriteText(dir + "/cases.csv",
            "points,case,site\n"
            "data/a.csv,case-a,x\n"
            "\n"  // Blank lines are skipped.
            "/abs/b.csv,case_b.2,y\n\n");
  const std::vector<BatchCase> cases = ReadManifest(dir + "/cases.csv");
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[0].name, "case-a");
  EXPECT_EQ(cases[0].points, dir + "/data/a.csv");
  EXPECT_EQ(cases[0].contours, "");
  EXPECT_EQ(cases[0].line, 2);
  EXPECT_EQ(cases[1].points, "/abs/b.csv");

  WriteText(dir + "/gp.csv",
            "case,points,contours\np1,gp,\"lv-endo,lv-epi\"\n");
  EXPECT_EQ(ReadManifest(dir + "/gp.csv")[0].contours, "lv-endo,lv-epi");
}

TEST(BatchManifestTest, BadManifestsSayWhereInOneLine) {
  const std::string dir = ScratchDirectory("manifest");
  const std::string path = dir + "/cases.csv";
  WriteText(path, "case,file\na,x.csv\n");
  EXPECT_EQ(ErrorOf(path), path + ": missing column 'points'");
  WriteText(path, "case,points\na,x.csv\nb/c,y.csv\n");
  EXPECT_EQ(ErrorOf(path),
            path +
                ":3: case 'b/c' is not a plain folder name (letters, "
                "digits, '.', '_', '-'; not summary.csv or *.tmp.*)");
  // Issue 14: the batch's own files beside the cases, and a folder read as
  // an empty file.
  for (const char* name : {"summary.csv", "summary.csv.tmp.7", "a.tmp.1"}) {
    WriteText(path, "case,points\n" + std::string(name) + ",x.csv\n");
    EXPECT_EQ(ErrorOf(path).rfind(path + ":2: case '" + name + "' is not", 0),
              0u)
        << name;
  }
  EXPECT_EQ(ErrorOf(dir), dir + ": is a folder, not a file");
  WriteText(path, "case,points\n..,x.csv\n");
  EXPECT_EQ(ErrorOf(path).rfind(path + ":2: case '..' is not", 0), 0u);
  WriteText(path, "case,points\na,x.csv\na,y.csv\n");
  EXPECT_EQ(ErrorOf(path), path + ":3: case 'a' appears twice");
  WriteText(path, "case,points\na,\n");
  EXPECT_EQ(ErrorOf(path), path + ":2: case 'a' has no points");
  WriteText(path, "case,points\n");
  EXPECT_EQ(ErrorOf(path), path + ": no cases");
  EXPECT_EQ(ErrorOf(dir + "/none.csv"),
            dir + "/none.csv: cannot open the file");
}

TEST(BatchManifestTest, ShardsPartitionTheCases) {
  EXPECT_EQ(ParseShard("2/5").index, 2);
  EXPECT_EQ(ParseShard("2/5").count, 5);
  EXPECT_EQ(ParseShard("0/1").count, 1);
  // Issue 29: a stream read ' 0/1' and '+0/1' as 0/1.
  for (const char* bad :
       {"5/5", "-1/3", "1", "1/0", "a/b", "1/2x", " 0/1", "+0/1", "0/+1",
        "0/ 1", "0/1 ", "0//1", "/1", "0/", "9999999999/1"}) {
    EXPECT_THROW(ParseShard(bad), InputError) << bad;
  }
  std::vector<BatchCase> cases(7);
  for (int i = 0; i < 7; ++i) cases[i].name = "c" + std::to_string(i);
  std::vector<std::string> seen;
  for (int i = 0; i < 3; ++i) {
    for (const BatchCase& c : CasesOfShard(cases, {i, 3}))
      seen.push_back(c.name);
  }
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(seen.size(), 7u);
  EXPECT_EQ(std::unique(seen.begin(), seen.end()), seen.end());
  EXPECT_EQ(CasesOfShard(cases, {1, 3}).size(), 2u);  // c1, c4.
  EXPECT_EQ(CasesOfShard(cases, {1, 3})[1].name, "c4");
}

}  // namespace
}  // namespace pfdm
