#include "pfdm/io/vtk_output.h"

#include <string>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(VtkOutputTest, DefaultIsOneBinaryFloatVtpPerFrame) {
  const VtkOutput output = VtkOutputFromNames("vtp", "float");
  EXPECT_EQ(output.files, VtkFiles::kVtp);
  EXPECT_EQ(output.format, VtkFormat::kBinary);
  EXPECT_EQ(output.precision, VtkPrecision::kFloat);
  EXPECT_TRUE(output.Vtp());
  EXPECT_FALSE(output.Vtk());
}

TEST(VtkOutputTest, FilesAndEncodingCombine) {
  const VtkOutput both = VtkOutputFromNames("both,ascii", "double");
  EXPECT_TRUE(both.Vtp());
  EXPECT_TRUE(both.Vtk());
  EXPECT_EQ(both.format, VtkFormat::kAscii);
  EXPECT_EQ(both.precision, VtkPrecision::kDouble);
  const VtkOutput legacy = VtkOutputFromNames("binary,vtk", "float");
  EXPECT_FALSE(legacy.Vtp());
  EXPECT_TRUE(legacy.Vtk());
  EXPECT_EQ(legacy.format, VtkFormat::kBinary);
  // The older values alone name the encoding of the default .vtp.
  const VtkOutput ascii = VtkOutputFromNames("ascii", "float");
  EXPECT_EQ(ascii.files, VtkFiles::kVtp);
  EXPECT_EQ(ascii.format, VtkFormat::kAscii);
}

TEST(VtkOutputTest, UnknownOrContradictoryWordsAreRefused) {
  const auto message = [](const std::string& format,
                          const std::string& precision) {
    try {
      VtkOutputFromNames(format, precision);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  const std::string expected =
      " (expected vtp, vtk or both, and binary or ascii, comma-separated)";
  EXPECT_EQ(message("vtu", "float"),
            "--vtk_format 'vtu': unknown word 'vtu'" + expected);
  EXPECT_EQ(message("vtp,vtk", "float"),
            "--vtk_format 'vtp,vtk': 'vtk' contradicts or repeats another "
            "word" +
                expected);
  EXPECT_EQ(message("ascii,binary", "float"),
            "--vtk_format 'ascii,binary': 'binary' contradicts or repeats "
            "another word" +
                expected);
  EXPECT_EQ(message("vtp,", "float"),
            "--vtk_format 'vtp,': unknown word ''" + expected);
  EXPECT_EQ(message("", "float"), "--vtk_format '': empty" + expected);
  EXPECT_EQ(message("vtp", "half"),
            "unknown --vtk_precision 'half' (expected float or double)");
}

}  // namespace
}  // namespace pfdm
