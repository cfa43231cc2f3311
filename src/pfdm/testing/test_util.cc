#include "pfdm/testing/test_util.h"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {

std::string ScratchDirectory(const std::string& name) {
  static int counter = 0;
  // Named by the test, not the process: a rerun replaces its predecessor's
  // files (disk use stays bounded) and what a test wrote is easy to find
  // and look at afterwards, while tests running in parallel never share.
  std::string test = "no_test";
  if (const testing::TestInfo* info =
          testing::UnitTest::GetInstance()->current_test_info()) {
    test = std::string(info->test_suite_name()) + "." + info->name();
    std::replace(test.begin(), test.end(), '/', '_');
  }
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) /
                                    "pfdm_tests" / test /
                                    (name + "_" + std::to_string(counter++));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string WithoutScripts(std::string html) {
  for (size_t at = html.find("<script"); at != std::string::npos;
       at = html.find("<script", at + 1)) {
    const size_t end = html.find("</script>", at);
    html.erase(at, end == std::string::npos ? end : end - at);
  }
  return html;
}

int CountOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos;
       at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string InputErrorOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

CommandResult RunPfdm(const std::string& arguments) {
  const std::string dir = ScratchDirectory("run");
  const std::string out = dir + "/stdout", err = dir + "/stderr";
  const std::string command =
      std::string(PFDM_BINARY) + " " + arguments + " > " + out + " 2> " + err;
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.output = ReadText(out);
  result.error = ReadText(err);
  return result;
}

std::string SharedDataDirectory() {
  const std::string dir = PFDM_SHARED_DATA_DIR;
  return std::filesystem::is_directory(dir) ? dir : "";
}

namespace {

// The value of attribute name="..." in one XML tag, "" when absent.
std::string Attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const size_t at = tag.find(key);
  if (at == std::string::npos) return "";
  const size_t begin = at + key.size();
  return tag.substr(begin, tag.find('"', begin) - begin);
}

}  // namespace

VtkXmlArrays ReadAppendedRawVtkXml(const std::string& xml) {
  VtkXmlArrays arrays;
  const std::string opening = "<AppendedData encoding=\"raw\">";
  const size_t appended = xml.find(opening);
  EXPECT_NE(appended, std::string::npos);
  if (appended == std::string::npos) return arrays;
  const size_t data = xml.find('_', appended + opening.size()) + 1;
  const std::string header = xml.substr(0, appended);
  EXPECT_NE(header.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(header.find("byte_order=\"LittleEndian\""), std::string::npos);
  std::string section;
  for (size_t at = header.find('<'); at != std::string::npos;
       at = header.find('<', at + 1)) {
    const std::string tag = header.substr(at, header.find('>', at) - at + 1);
    for (const char* name : {"PointData", "Points", "Verts", "Polys"}) {
      if (tag == std::string("<") + name + ">") section = name;
    }
    if (tag.rfind("<DataArray ", 0) != 0) continue;
    EXPECT_EQ(Attribute(tag, "format"), "appended") << tag;
    const size_t offset = std::stoull(Attribute(tag, "offset"));
    std::uint64_t size = 0;
    EXPECT_LE(data + offset + sizeof(size), xml.size()) << tag;
    if (data + offset + sizeof(size) > xml.size()) break;
    std::memcpy(&size, xml.data() + data + offset, sizeof(size));
    const char* bytes = xml.data() + data + offset + sizeof(size);
    EXPECT_LE(data + offset + sizeof(size) + size, xml.size()) << tag;
    const std::string name = Attribute(tag, "Name");
    const std::string key = name.empty() ? section : section + "/" + name;
    const std::string type = Attribute(tag, "type");
    arrays.types[key] = type;
    if (type == "Float64") {
      std::vector<double>& values = arrays.float64[key];
      values.resize(size / sizeof(double));
      std::memcpy(values.data(), bytes, size);
    } else if (type == "Float32") {
      std::vector<float> values(size / sizeof(float));
      std::memcpy(values.data(), bytes, size);
      arrays.float64[key].assign(values.begin(), values.end());
    } else if (type == "Int32") {
      std::vector<std::int32_t> values(size / sizeof(std::int32_t));
      std::memcpy(values.data(), bytes, size);
      arrays.int64[key].assign(values.begin(), values.end());
    } else {
      EXPECT_EQ(type, "Int64") << tag;
      std::vector<std::int64_t>& values = arrays.int64[key];
      values.resize(size / sizeof(std::int64_t));
      std::memcpy(values.data(), bytes, size);
    }
  }
  return arrays;
}

void ExpectSameBits(const std::vector<double>& a, const std::vector<double>& b,
                    const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i])) {
      EXPECT_TRUE(std::isnan(b[i])) << what << " " << i;
    } else {
      EXPECT_EQ(a[i], b[i]) << what << " " << i;
    }
  }
}

}  // namespace pfdm
