// Inputs as they come (issue 31): a mesh of the endocardium gets a cavity
// and an ejection fraction, trigger times and --ed_frame reach fit.json and
// the curves, a GPFile without its header line fits like the file.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// Half a spheroid, apex at z = 0 and rim at z = c, radius a at the rim, as
// OBJ text: the apex vertex and 12 rings of 24 (the same vertices in every
// frame).  Closed by a flat lid it holds 2/3 pi a^2 c.
std::string HalfSpheroid(double a, double c) {
  constexpr int kRings = 12, kAround = 24;
  std::ostringstream obj;
  obj.precision(10);
  obj << "v 0 0 0\n";
  for (int i = 1; i <= kRings; ++i) {
    const double theta = 0.5 * kPi * i / kRings;
    for (int j = 0; j < kAround; ++j) {
      const double phi = 2.0 * kPi * j / kAround;
      obj << "v " << a * std::sin(theta) * std::cos(phi) << ' '
          << a * std::sin(theta) * std::sin(phi) << ' '
          << c * (1.0 - std::cos(theta)) << '\n';
    }
  }
  auto at = [&](int ring, int j) {  // 1-based OBJ index.
    return 2 + (ring - 1) * kAround + (j % kAround);
  };
  for (int j = 0; j < kAround; ++j) {
    obj << "f 1 " << at(1, j + 1) << ' ' << at(1, j) << '\n';
  }
  for (int i = 1; i < kRings; ++i) {
    for (int j = 0; j < kAround; ++j) {
      obj << "f " << at(i, j) << ' ' << at(i, j + 1) << ' ' << at(i + 1, j + 1)
          << '\n'
          << "f " << at(i, j) << ' ' << at(i + 1, j + 1) << ' ' << at(i + 1, j)
          << '\n';
    }
  }
  return obj.str();
}

double HalfSpheroidMl(double a, double c) {
  return 2.0 / 3.0 * kPi * a * a * c / 1000.0;
}

// mesh-points' per-frame volumes, from its table.
std::vector<double> MeshVolumes(const std::string& output) {
  std::vector<double> volumes;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    int frame;
    double volume;
    if (std::sscanf(line.c_str(), "%d %lf", &frame, &volume) == 2) {
      volumes.push_back(volume);
    }
  }
  return volumes;
}

nlohmann::json FitJsonAt(const std::string& dir) {
  return nlohmann::json::parse(ReadText(dir + "/fit.json"));
}

// Two frames of an endocardium, 65.4 ml then 28.5 ml (EF 0.565), named as
// biv-me names its endocardial meshes: mesh-points labels the points, the
// fit takes them for the endocardium and reports the cavity and the
// ejection fraction, the volumes matching those of the meshes themselves.
class EndocardialMeshTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = ScratchDirectory("endo_mesh");
    std::filesystem::create_directories(dir_ + "/obj");
    WriteText(dir_ + "/obj/case_LV_ENDOCARDIAL_000.obj", HalfSpheroid(25, 50));
    WriteText(dir_ + "/obj/case_LV_ENDOCARDIAL_001.obj", HalfSpheroid(18, 42));
    const CommandResult run = RunPfdm("mesh-points --mesh " + dir_ +
                                      "/obj --out " + dir_ + "/points.csv");
    ASSERT_EQ(run.exit_code, 0) << run.error;
    EXPECT_NE(run.output.find("surface: endo (from the names"),
              std::string::npos)
        << run.output;
    mesh_ml_ = MeshVolumes(run.output);
    ASSERT_EQ(mesh_ml_.size(), 2u) << run.output;
  }

  std::string dir_;
  std::vector<double> mesh_ml_;
};

TEST_F(EndocardialMeshTest, GetsTheCavityAndAnEjectionFraction) {
  // The faceted meshes hold 1.1 % less than the spheroids.
  EXPECT_NEAR(mesh_ml_[0] / HalfSpheroidMl(25, 50), 0.989, 0.005);
  EXPECT_NEAR(mesh_ml_[1] / HalfSpheroidMl(18, 42), 0.989, 0.005);
  const CommandResult fit =
      RunPfdm("fit --points " + dir_ + "/points.csv --out " + dir_ + "/fit");
  ASSERT_EQ(fit.exit_code, 0) << fit.error;
  EXPECT_NE(fit.output.find("cavity volume: ED "), std::string::npos)
      << fit.output;
  const nlohmann::json json = FitJsonAt(dir_ + "/fit");
  EXPECT_EQ(json["settings"]["surface"], "auto");
  // Not a flag, but it shapes untracked frames' radii (docs/gauge.md).
  EXPECT_EQ(json["settings"]["untracked_prior_covered_radii_scale"], 0.3);
  EXPECT_EQ(json["model"]["wall_reason"],
            "tracked points of the endocardium only");
  EXPECT_EQ(json["model"]["volume_surface"], "cavity");
  const double truth_ef = 1.0 - HalfSpheroidMl(18, 42) / HalfSpheroidMl(25, 50);
  const double mesh_ef = 1.0 - mesh_ml_[1] / mesh_ml_[0];
  const double ef = json["ejection_fraction"]["ratio"].get<double>();
  EXPECT_NEAR(truth_ef, 0.5645, 1e-4);
  EXPECT_NEAR(ef, truth_ef, 0.01);
  EXPECT_NEAR(ef, mesh_ef, 0.01);
  for (int t = 0; t < 2; ++t) {
    const double fitted = json["frames"][t]["cavity_volume_ml"].get<double>();
    EXPECT_NEAR(fitted / mesh_ml_[t], 1.0, 0.03) << t;
  }
  EXPECT_FALSE(json["frames"][0].contains("time_ms"));
}

// Said explicitly, the mid-wall is what it was before: no ejection
// fraction, and the same volumes.
TEST_F(EndocardialMeshTest, SurfaceMidwallOverridesTheLabel) {
  const CommandResult fit =
      RunPfdm("fit --points " + dir_ + "/points.csv --surface midwall --out " +
              dir_ + "/fit");
  ASSERT_EQ(fit.exit_code, 0) << fit.error;
  EXPECT_NE(fit.output.find("midwall volume: ED "), std::string::npos);
  EXPECT_NE(fit.output.find("not the cavity, so no ejection fraction"),
            std::string::npos);
  const nlohmann::json json = FitJsonAt(dir_ + "/fit");
  EXPECT_EQ(json["settings"]["surface"], "midwall");
  EXPECT_EQ(json["model"]["wall_reason"], "--surface midwall");
  EXPECT_FALSE(json.contains("ejection_fraction"));
  EXPECT_NEAR(json["midwall_volume_fraction"]["ratio"].get<double>(),
              1.0 - mesh_ml_[1] / mesh_ml_[0], 0.01);
}

// Trigger times from a time_ms column reach fit.json and the curves; with
// the frames in the order ES, ED, --ed_frame 1 gives the same ejection
// fraction.
TEST_F(EndocardialMeshTest, TriggerTimesAndEndDiastoleFrame) {
  std::istringstream in(ReadText(dir_ + "/points.csv"));
  std::string line, timed, swapped;
  std::getline(in, line);
  ASSERT_EQ(line, "frame,id,x,y,z,surface");
  timed = swapped = "frame,id,x,y,z,time_ms,surface\n";
  while (std::getline(in, line)) {
    const int frame = line[0] - '0';
    const std::string rest = line.substr(1, line.rfind(',') - 1);
    timed +=
        line.substr(0, line.rfind(',')) + (frame ? ",310" : ",25") + ",endo\n";
    swapped +=
        std::to_string(1 - frame) + rest + (frame ? ",25" : ",310") + ",endo\n";
  }
  WriteText(dir_ + "/timed.csv", timed);
  WriteText(dir_ + "/swapped.csv", swapped);
  ASSERT_EQ(
      RunPfdm("fit --points " + dir_ + "/timed.csv --out " + dir_ + "/timed")
          .exit_code,
      0);
  const CommandResult run =
      RunPfdm("fit --points " + dir_ + "/swapped.csv --ed_frame 1 --out " +
              dir_ + "/swapped");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_NE(run.output.find("(frame 1), ES "), std::string::npos) << run.output;
  const nlohmann::json timed_json = FitJsonAt(dir_ + "/timed");
  const nlohmann::json swapped_json = FitJsonAt(dir_ + "/swapped");
  EXPECT_EQ(timed_json["frames"][0]["time_ms"].get<double>(), 25.0);
  EXPECT_EQ(timed_json["frames"][1]["time_ms"].get<double>(), 310.0);
  EXPECT_EQ(swapped_json["settings"]["ed_frame"], 1);
  EXPECT_EQ(swapped_json["ejection_fraction"]["ed_frame"], 1);
  EXPECT_EQ(swapped_json["ejection_fraction"]["es_frame"], 0);
  EXPECT_NEAR(swapped_json["ejection_fraction"]["ratio"].get<double>(),
              timed_json["ejection_fraction"]["ratio"].get<double>(), 0.01);
  // ED is the clinical numbers' reference: its own shortening is 0, ES's
  // that of the sequence in order.
  const auto shortening = [](const nlohmann::json& json, int t) {
    return json["frames"][t]["clinical"]["longitudinal_shortening_percent"]
        .get<double>();
  };
  EXPECT_EQ(shortening(swapped_json, 1), 0.0);
  EXPECT_GT(shortening(timed_json, 1), 10.0);
  EXPECT_NEAR(shortening(swapped_json, 0), shortening(timed_json, 1), 1.0);
  const std::string report = ReadText(dir_ + "/timed/report.html");
  EXPECT_NE(report.find("time from the trigger (ms)"), std::string::npos);
  EXPECT_NE(ReadText(dir_ + "/timed/fit.pvd").find("timestep=\"310"),
            std::string::npos);
}

// The README's CAP example: the mean ED and ES endocardium, named by
// --cap_surfaces, is the cavity.  Its EF read a second way: from the
// volumes the meshes themselves enclose (mesh-points).
TEST(CliInputsTest, CapMeanEndocardiumGetsItsEjectionFraction) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string dir = ScratchDirectory("cap_mean");
  const CommandResult points =
      RunPfdm("mesh-points --mesh " + shared +
              "/cap-lv-mean/mean_shape.csv --cap_surfaces ED-endo,ES-endo "
              "--out " +
              dir + "/points.csv");
  ASSERT_EQ(points.exit_code, 0) << points.error;
  const std::vector<double> mesh_ml = MeshVolumes(points.output);
  ASSERT_EQ(mesh_ml.size(), 2u);
  EXPECT_NEAR(mesh_ml[0], 128.0, 0.1);
  EXPECT_NEAR(mesh_ml[1], 49.5, 0.1);
  const CommandResult fit =
      RunPfdm("fit --points " + dir + "/points.csv --out " + dir + "/fit");
  ASSERT_EQ(fit.exit_code, 0) << fit.error;
  const nlohmann::json json = FitJsonAt(dir + "/fit");
  const double ef = json["ejection_fraction"]["ratio"].get<double>();
  std::printf(
      "CAP mean: cavity %.1f -> %.1f ml, EF %.3f; meshes %.1f -> "
      "%.1f ml, EF %.3f\n",
      json["frames"][0]["cavity_volume_ml"].get<double>(),
      json["frames"][1]["cavity_volume_ml"].get<double>(), ef, mesh_ml[0],
      mesh_ml[1], 1.0 - mesh_ml[1] / mesh_ml[0]);
  EXPECT_NE(fit.output.find("ejection fraction 0.6"), std::string::npos)
      << fit.output;
  EXPECT_NEAR(ef, 1.0 - mesh_ml[1] / mesh_ml[0], 0.02);
  // The fit reads ES 3.9 % above the mesh (51.5 against 49.5 ml).
  for (int t = 0; t < 2; ++t) {
    EXPECT_NEAR(
        json["frames"][t]["cavity_volume_ml"].get<double>() / mesh_ml[t], 1.0,
        0.05)
        << t;
  }
}

// biv-me's LV endocardial meshes of patient 1 (frames 0 and 9, ED and ES)
// through mesh-points: the cavity and its EF, the volumes 2.8 % (ED) and
// 5.3 % (ES) above those of the meshes themselves.
// Frame 0's closest points end unsettled (10.9 mm in the last search) with
// or without the surface column, so its verdict fails (exit 3, outputs
// written); that is the correspondence's, not this test's.
TEST(CliInputsTest, BivMeEndocardialMeshesGetTheirEjectionFraction) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string dir = ScratchDirectory("biv_me_endo");
  std::filesystem::create_directories(dir + "/obj");
  for (const char* frame : {"000", "009"}) {
    const std::string name =
        std::string("patient1_LV_ENDOCARDIAL_") + frame + ".obj";
    std::filesystem::copy_file(shared + "/biv-me-patient1/obj/" + name,
                               dir + "/obj/" + name);
  }
  const CommandResult points = RunPfdm("mesh-points --mesh " + dir +
                                       "/obj --out " + dir + "/points.csv");
  ASSERT_EQ(points.exit_code, 0) << points.error;
  const std::vector<double> mesh_ml = MeshVolumes(points.output);
  ASSERT_EQ(mesh_ml.size(), 2u);
  const CommandResult fit =
      RunPfdm("fit --points " + dir + "/points.csv --out " + dir + "/fit");
  ASSERT_TRUE(fit.exit_code == 0 || fit.exit_code == 3) << fit.error;
  const nlohmann::json json = FitJsonAt(dir + "/fit");
  const double ef = json["ejection_fraction"]["ratio"].get<double>();
  std::printf(
      "biv-me frames 0, 9: cavity %.1f -> %.1f ml, EF %.3f; meshes "
      "%.1f -> %.1f ml, EF %.3f\n",
      json["frames"][0]["cavity_volume_ml"].get<double>(),
      json["frames"][1]["cavity_volume_ml"].get<double>(), ef, mesh_ml[0],
      mesh_ml[1], 1.0 - mesh_ml[1] / mesh_ml[0]);
  EXPECT_NEAR(ef, 1.0 - mesh_ml[1] / mesh_ml[0], 0.03);
  for (int t = 0; t < 2; ++t) {
    EXPECT_NEAR(
        json["frames"][t]["cavity_volume_ml"].get<double>() / mesh_ml[t], 1.0,
        0.06)
        << t;
  }
}

// A GPFile without its header line fits like the file with it (one frame
// of biv-me's patient 1, LV endocardium).
TEST(CliInputsTest, HeaderlessBivMeGpFileFitsLikeTheFile) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string dir = ScratchDirectory("headerless");
  const std::string text =
      ReadText(shared + "/biv-me-patient1/guidepoints/GPFile_000.txt");
  std::filesystem::create_directories(dir + "/with");
  std::filesystem::create_directories(dir + "/without");
  WriteText(dir + "/with/GPFile_000.txt", text);
  WriteText(dir + "/without/GPFile_000.txt", text.substr(text.find('\n') + 1));
  double rms[2], volume[2];
  for (int i = 0; i < 2; ++i) {
    const std::string in = dir + (i ? "/without" : "/with");
    const CommandResult fit =
        RunPfdm("fit --points " + in + "/GPFile_000.txt --out " + in + "/fit");
    ASSERT_EQ(fit.exit_code, 0) << fit.error;
    const nlohmann::json json = FitJsonAt(in + "/fit");
    EXPECT_EQ(json["frames"][0]["n_points"], 443) << i;
    rms[i] = json["frames"][0]["rms_mm"].get<double>();
    volume[i] = json["frames"][0]["cavity_volume_ml"].get<double>();
  }
  EXPECT_EQ(rms[0], rms[1]);
  EXPECT_EQ(volume[0], volume[1]);
  EXPECT_GT(volume[0], 120.0);
}

TEST(CliInputsTest, BadSurfaceOrEndDiastoleIsOneLine) {
  const std::string dir = ScratchDirectory("inputs_bad");
  ASSERT_EQ(RunPfdm("simulate --frames 2 --tags 200 --out " + dir + "/p.csv")
                .exit_code,
            0);
  CommandResult run =
      RunPfdm("fit --points " + dir + "/p.csv --surface endocardium --out " +
              dir + "/fit");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error,
            "pfdm: error: --surface must be auto, endo, midwall or epi, got "
            "'endocardium'\n");
  run = RunPfdm("fit --points " + dir + "/p.csv --ed_frame 2 --out " + dir +
                "/fit");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error, "pfdm: error: --ed_frame 2 is not a frame of " + dir +
                           "/p.csv (frames 0 to 1)\n");
  run = RunPfdm("fit --points " + dir + "/p.csv --surface endo --wall solid " +
                "--out " + dir + "/fit");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error,
            "pfdm: error: --surface endo declares one surface; --wall solid "
            "fits two\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/fit/fit.json"));
}

}  // namespace
}  // namespace pfdm
