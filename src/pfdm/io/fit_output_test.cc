#include "pfdm/io/fit_output.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/io/vtp_writer.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/testing/small_phantom_fit.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

TEST(FitOutputTest, SurfaceCarriesTwistInDegreesAtEachVertex) {
  const FittedPhantom& f = SmallPhantomFit();
  const Model model = f.fit.ModelAt(2);
  const VtkPolyData data =
      FramePolyData(model, f.phantom.points.frames[2], f.fit.frames[2]);
  ASSERT_EQ(data.point_scalars.size(), 5u);
  EXPECT_EQ(data.point_scalars[2].first, "w");
  for (double w : data.point_scalars[2].second) EXPECT_EQ(w, 0.0);
  EXPECT_EQ(data.point_scalars[3].first, "twist_deg");
  const auto& u = data.point_scalars[0].second;
  const auto& twist = data.point_scalars[3].second;
  ASSERT_EQ(twist.size(), data.points.size());
  EXPECT_EQ(data.vertices.size(), 600u);
  for (size_t i = 0; i < twist.size(); i += 97) {
    EXPECT_NEAR(twist[i],
                model.FunctionAt(kTau, u[i]) * 180.0 / 3.14159265358979323846,
                1e-9);
  }
  // The phantom's apex turns -5 degrees by frame 4, so about -2.5 by 2.
  EXPECT_LT(*std::min_element(twist.begin(), twist.end()), -1.5);
}

// a_i's sd in mm is a0 times a_i's relative one (a0 held: the paper's
// scale gauge); a3's takes the length's relative error besides, a1's not.
TEST(FitOutputTest, OnlyA3sSdCarriesTheLengthsError) {
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = 40.0;
  values[kA1] = 0.5;
  values[kA3] = 1.5;
  const Model model = Model::Uniform(ModelConfig::Paper(17), values);
  FrameCovariance covariance;
  covariance.computed = true;
  covariance.entries = {{CovarianceEntry::Kind::kKnot, 4, kA1},
                        {CovarianceEntry::Kind::kKnot, 4, kA3}};
  covariance.covariance = Eigen::Vector2d(1e-4, 4e-4).asDiagonal();
  EXPECT_NEAR(ReportedSd(model, covariance, kA1, 4), 0.4, 1e-12);
  EXPECT_NEAR(ReportedSd(model, covariance, kA1, 4, 1e-4), 0.4, 1e-12);
  EXPECT_NEAR(ReportedSd(model, covariance, kA3, 4), 0.8, 1e-12);
  // sqrt(0.8^2 + (40 x 1.5)^2 x 1e-4) = sqrt(0.64 + 0.36).
  EXPECT_NEAR(ReportedSd(model, covariance, kA3, 4, 1e-4), 1.0, 1e-12);
  EXPECT_EQ(ReportedSd(model, covariance, kA2, 4, 1e-4), 0.0);
}

// A fit with a loss gives its points' weights as loss_weight, 1 on the
// surface; without one there is no such array.
TEST(FitOutputTest, PointsCarryTheirLossWeights) {
  const FittedPhantom& f = SmallPhantomFit();
  FrameFit frame = f.fit.frames[1];
  for (size_t i = 0; i < frame.residuals.size(); ++i) {
    frame.loss_weights.push_back(1.0 / (1.0 + i));
  }
  const VtkPolyData data =
      FramePolyData(f.fit.ModelAt(1), f.phantom.points.frames[1], frame);
  ASSERT_EQ(data.point_scalars.size(), 6u);
  EXPECT_EQ(data.point_scalars[5].first, "loss_weight");
  const std::vector<double>& weights = data.point_scalars[5].second;
  ASSERT_EQ(weights.size(), data.points.size());
  const size_t surface = data.points.size() - frame.residuals.size();
  for (size_t i = 0; i < weights.size(); ++i) {
    EXPECT_EQ(weights[i], i < surface ? 1.0 : 1.0 / (1.0 + (i - surface)));
  }
  EXPECT_NE(ToLegacyVtk(data, "t").find("SCALARS loss_weight"),
            std::string::npos);
  EXPECT_NE(
      ToVtkXmlPolyData(data, VtkFormat::kAscii).find("Name=\"loss_weight\""),
      std::string::npos);
}

TEST(FitOutputTest, WritesEveryFileWholeWithACollectionOfTheFrames) {
  const FittedPhantom& f = SmallPhantomFit();
  const std::string dir = ScratchDirectory("fit_output") + "/out";
  WriteFitOutputs(dir, f.phantom.points, f.fit, FitOptions());
  for (const char* name :
       {"fit.json", "parameters.csv", "parameters.svg", "report.html",
        "fit.pvd", "frame_000.vtp", "frame_001.vtp", "frame_002.vtp"}) {
    EXPECT_TRUE(fs::exists(dir + "/" + name)) << name;
  }
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos);
    ++files;
  }
  EXPECT_EQ(files, 9);  // The eight above and the marker: no legacy .vtk.
  EXPECT_EQ(ReadText(dir + "/" + kOutputMarker), kOutputMarkerText);
  const std::string pvd = ReadText(dir + "/fit.pvd");
  for (const char* frame :
       {"frame_000.vtp", "frame_001.vtp", "frame_002.vtp"}) {
    EXPECT_NE(pvd.find(frame), std::string::npos) << frame;
  }
  const std::string svg = ReadText(dir + "/parameters.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("twist tau (degrees)"), std::string::npos);
  const std::string html = ReadText(dir + "/report.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("ejection fraction"), std::string::npos);
}

// The default .vtp files are appended raw binary; in double precision, read
// back, they hold the fitted model's surface points and the frame's data
// points bit for bit, the flag is_data as Float32 and the cells as Int32.
TEST(FitOutputTest, BinaryFramesHoldTheModelsPointsExactlyInDouble) {
  const FittedPhantom& f = SmallPhantomFit();
  const std::string dir = ScratchDirectory("fit_output") + "/out";
  VtkOutput exact;
  exact.files = VtkFiles::kBoth;
  exact.precision = VtkPrecision::kDouble;
  WriteFitOutputs(dir, f.phantom.points, f.fit, FitOptions(), {}, exact);
  const Model model = f.fit.ModelAt(2);
  const ModelSurface surface =
      MakeModelSurface(model, kSurfaceRings, kSurfaceMeridians);
  const VtkXmlArrays arrays =
      ReadAppendedRawVtkXml(ReadText(dir + "/frame_002.vtp"));
  const std::vector<double>& points = arrays.float64.at("Points");
  ASSERT_EQ(points.size(), 3 * (surface.mesh.points.size() +
                                f.phantom.points.frames[2].points.size()));
  for (size_t i = 0; i < surface.mesh.points.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(points[3 * i + k], surface.mesh.points[i][k]) << i;
    }
  }
  const size_t first_data = surface.mesh.points.size();
  for (size_t i = 0; i < f.phantom.points.frames[2].points.size(); ++i) {
    const Eigen::Vector3d& p = f.phantom.points.frames[2].points[i].position;
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(points[3 * (first_data + i) + k], p[k]) << i;
    }
    ASSERT_EQ(arrays.float64.at("PointData/u")[first_data + i],
              f.fit.frames[2].material[i].u);
  }
  // The model's own twist in degrees at each surface vertex's u, as a
  // float: it is for display.
  const std::vector<double>& u = arrays.float64.at("PointData/u");
  const std::vector<double>& twist = arrays.float64.at("PointData/twist_deg");
  for (size_t i = 0; i < first_data; i += 37) {
    EXPECT_EQ(u[i], surface.u[i]);
    EXPECT_EQ(twist[i], static_cast<float>(model.FunctionAt(kTau, u[i]) *
                                           (180.0 / M_PI)));
  }
  EXPECT_EQ(arrays.types.at("Points"), "Float64");
  EXPECT_EQ(arrays.types.at("PointData/u"), "Float64");
  EXPECT_EQ(arrays.types.at("PointData/is_data"), "Float32");
  EXPECT_EQ(arrays.types.at("Polys/connectivity"), "Int32");
  EXPECT_EQ(arrays.int64.at("Polys/connectivity").size(),
            3 * surface.mesh.triangles.size());
  EXPECT_EQ(
      arrays.int64.at("Verts/offsets").back(),
      static_cast<std::int64_t>(f.phantom.points.frames[2].points.size()));
  EXPECT_EQ(ReadText(dir + "/frame_002.vtk").find("BINARY\nDATASET POLYDATA"),
            std::string("# vtk DataFile Version 3.0\npfdm frame_002\n").size());
}

// By default every real is float32: the points within a float's rounding
// (6e-8 relative: under 0.01 um on a heart) of the model's, in a file of
// under 70 % of the double one's bytes (66 %: the cells are Int32 in both).
TEST(FitOutputTest, DefaultFramesAreFloat32WithinItsRounding) {
  const FittedPhantom& f = SmallPhantomFit();
  const std::string dir = ScratchDirectory("fit_output");
  WriteFitOutputs(dir + "/single", f.phantom.points, f.fit, FitOptions());
  VtkOutput exact;
  exact.precision = VtkPrecision::kDouble;
  WriteFitOutputs(dir + "/double", f.phantom.points, f.fit, FitOptions(), {},
                  exact);
  const VtkXmlArrays single =
      ReadAppendedRawVtkXml(ReadText(dir + "/single/frame_002.vtp"));
  const VtkXmlArrays doubles =
      ReadAppendedRawVtkXml(ReadText(dir + "/double/frame_002.vtp"));
  for (const auto& [key, type] : single.types) {
    EXPECT_TRUE(type == "Float32" || type == "Int32") << key << " " << type;
  }
  const std::vector<double>& rounded = single.float64.at("Points");
  const std::vector<double>& points = doubles.float64.at("Points");
  ASSERT_EQ(rounded.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    ASSERT_NEAR(rounded[i], points[i], 6e-8 * std::abs(points[i])) << i;
  }
  EXPECT_LT(fs::file_size(dir + "/single/frame_002.vtp"),
            0.7 * fs::file_size(dir + "/double/frame_002.vtp"));
  EXPECT_FALSE(fs::exists(dir + "/single/frame_002.vtk"));
}

// --vtk_format both,ascii: text that a person or a text tool can read, the
// same arrays.
TEST(FitOutputTest, AsciiFramesOnRequest) {
  const FittedPhantom& f = SmallPhantomFit();
  const std::string dir = ScratchDirectory("fit_output") + "/out";
  WriteFitOutputs(dir, f.phantom.points, f.fit, FitOptions(), {},
                  VtkOutputFromNames("both,ascii", "float"));
  const std::string vtp = ReadText(dir + "/frame_001.vtp");
  EXPECT_EQ(vtp.find("AppendedData"), std::string::npos);
  EXPECT_NE(vtp.find("type=\"Float32\" Name=\"twist_deg\" format=\"ascii\""),
            std::string::npos);
  EXPECT_NE(ReadText(dir + "/frame_001.vtk").find("\nASCII\n"),
            std::string::npos);
}

TEST(FitOutputTest, NothingIsWrittenWhenAnOutputCannotBeMade) {
  // The output folder is a file: one InputError, the file untouched.
  const FittedPhantom& f = SmallPhantomFit();
  const std::string dir = ScratchDirectory("fit_output");
  WriteText(dir + "/taken", "a file");
  EXPECT_THROW(
      WriteFitOutputs(dir + "/taken", f.phantom.points, f.fit, FitOptions()),
      InputError);
  EXPECT_EQ(ReadText(dir + "/taken"), "a file");
}

// The first two frames of the phantom fit: a shorter set to write over it.
std::pair<PointSequence, SequenceFit> FirstTwoFrames() {
  const FittedPhantom& f = SmallPhantomFit();
  std::pair<PointSequence, SequenceFit> two{f.phantom.points, f.fit};
  two.first.frames.resize(2);
  two.second.frames.resize(2);
  return two;
}

std::vector<std::string> Names(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A refit with fewer frames left the older frame_002 files beside the new
// set, and a killed run's temporaries stayed for good (issue 14).
TEST(FitOutputTest, ARefitReplacesTheWholeSetAndItsTemporaries) {
  const FittedPhantom& f = SmallPhantomFit();
  const std::string dir = ScratchDirectory("fit_output") + "/out";
  VtkOutput both;
  both.files = VtkFiles::kBoth;
  WriteFitOutputs(dir, f.phantom.points, f.fit, FitOptions(), {}, both);
  WriteText(dir + "/report.html.tmp.99999", "<html>half");
  WriteText(dir + "/fit.json.tmp.12", "{");
  WriteText(dir + "/frame_001.vtp.tmp.otherhost.4321.AbCd0123", "<Vtk");
  WriteText(dir + "/notes.txt", "the user's own");
  const auto [points, fit] = FirstTwoFrames();
  WriteFitOutputs(dir, points, fit, FitOptions());
  EXPECT_EQ(Names(dir), (std::vector<std::string>{
                            ".pfdm-fit", "fit.json", "fit.pvd", "frame_000.vtp",
                            "frame_001.vtp", "notes.txt", "parameters.csv",
                            "parameters.svg", "report.html"}));
  EXPECT_EQ(nlohmann::json::parse(ReadText(dir + "/fit.json"))["frames"].size(),
            2u);
  EXPECT_EQ(ReadText(dir + "/fit.pvd").find("frame_002"), std::string::npos);
}

// A failed write left the older fit.json beside new files: a folder that
// looked complete (issue 14).  A folder in the way now stops the write
// before anything is touched.
TEST(FitOutputTest, AFolderInTheWayStopsTheWriteBeforeItStarts) {
  const FittedPhantom& f = SmallPhantomFit();
  const std::string dir = ScratchDirectory("fit_output") + "/out";
  WriteFitOutputs(dir, f.phantom.points, f.fit, FitOptions());
  fs::create_directory(dir + "/frame_007.vtp");
  const std::vector<std::string> before = Names(dir);
  const std::string json = ReadText(dir + "/fit.json");
  const auto [points, fit] = FirstTwoFrames();
  try {
    WriteFitOutputs(dir, points, fit, FitOptions());
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir + "/frame_007.vtp: is a folder where pfdm writes a file");
  }
  EXPECT_EQ(Names(dir), before);
  EXPECT_EQ(ReadText(dir + "/fit.json"), json);
}

TEST(FitOutputTest, OutputNamesAreTheSetAndItsTemporaries) {
  for (const char* name :
       {"fit.json", "parameters.csv", "parameters.svg", "report.html",
        "fit.pvd", "frame_000.vtk", "frame_1234.vtp", "fit.json.tmp.77",
        "report.html.tmp.node-7.4321.AbCd0123"}) {
    EXPECT_TRUE(IsFitOutputName(name)) << name;
  }
  for (const char* name :
       {"points.csv", "fit.json.bak", "frame_.vtk", "error.txt",
        "frame_001.vtk.tmp.", "xfit.json", ".pfdm-fit", "fit.json.tmp.a/b"}) {
    EXPECT_FALSE(IsFitOutputName(name)) << name;
  }
}

TEST(FitOutputTest, TheFolderIsCheckedBeforeTheFitAndLeftAsItWas) {
  const std::string dir = ScratchDirectory("fit_output");
  // Absent: made, written to, and removed again.
  CheckFitOutputFolder(dir + "/new/out", dir + "/points.csv");
  EXPECT_FALSE(fs::exists(dir + "/new"));
  WriteText(dir + "/file", "x");
  EXPECT_THROW(CheckFitOutputFolder(dir + "/file/out", ""), InputError);
  fs::create_directories(dir + "/out/report.html");
  try {
    CheckFitOutputFolder(dir + "/out", "");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir +
                  "/out/report.html: is a folder or other non-file where "
                  "pfdm writes a file");
  }
  // The input would be removed with the older set.
  fs::create_directory(dir + "/in");
  WriteText(dir + "/in/parameters.csv", "frame,id,x,y,z\n");
  try {
    CheckFitOutputFolder(dir + "/in", dir + "/in/../in/parameters.csv");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir +
                  "/in/../in/parameters.csv: the input is one of the "
                  "outputs " +
                  dir +
                  "/in would be given; choose another "
                  "--out");
  }
  EXPECT_EQ(Names(dir + "/in"), std::vector<std::string>{"parameters.csv"});
}

// Issue 29: the folder probe and every file went through NAME.tmp.<pid>,
// opened through whatever was there.  Links planted at each of those
// names, and at each final name, now leave their targets as they were.
TEST(FitOutputTest, LinksPlantedAtEveryNameLeaveTheirTargetsUntouched) {
  const FittedPhantom& f = SmallPhantomFit();
  const std::string dir = ScratchDirectory("fit_output");
  const std::string out = dir + "/out";
  fs::create_directories(out);
  const std::string pid = std::to_string(getpid());
  int planted = 0;
  for (const char* name :
       {"fit.json", "parameters.csv", "parameters.svg", "report.html",
        "fit.pvd", "frame_000.vtk", "frame_000.vtp", "frame_001.vtk",
        "frame_001.vtp", "frame_002.vtk", "frame_002.vtp"}) {
    for (const std::string& at :
         {std::string(name), std::string(name) + ".tmp." + pid}) {
      const std::string victim = dir + "/victim_" + std::to_string(planted++);
      WriteText(victim, "precious");
      fs::create_symlink(victim, out + "/" + at);
    }
  }
  // A dangling link at the marker: not followed to make its target.
  fs::create_symlink(dir + "/made_through_the_marker",
                     out + "/" + kOutputMarker);
  CheckFitOutputFolder(out, dir + "/points.csv");
  WriteFitOutputs(out, f.phantom.points, f.fit, FitOptions());
  for (int i = 0; i < planted; ++i) {
    EXPECT_EQ(ReadText(dir + "/victim_" + std::to_string(i)), "precious") << i;
  }
  EXPECT_FALSE(fs::exists(dir + "/made_through_the_marker"));
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(out + "/fit.json")));
  EXPECT_EQ(nlohmann::json::parse(ReadText(out + "/fit.json"))["frames"].size(),
            3u);
  for (const std::string& name : Names(out)) {
    EXPECT_EQ(name.find(".tmp."), std::string::npos) << name;
  }
}

}  // namespace
}  // namespace pfdm
