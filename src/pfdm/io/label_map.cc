#include "pfdm/io/label_map.h"

#include <cstdlib>
#include <map>
#include <sstream>

#include "pfdm/util/error.h"

namespace pfdm {

namespace {

[[noreturn]] void Refuse(const std::string& text, const std::string& why) {
  throw InputError("--labels '" + text + "': " + why +
                   " (expected acdc, mnms or lv=3,myo=2,rv=1)");
}

int LabelValue(const std::string& text, const std::string& key,
               const std::string& value) {
  if (key == "rv" && value == "none") return -1;
  char* end = nullptr;
  const long v = std::strtol(value.c_str(), &end, 10);
  if (value.empty() || *end != '\0' || v < 1 || v > 65535) {
    Refuse(text, key + "=" + value + " is not a label (1 to 65535)");
  }
  return static_cast<int>(v);
}

}  // namespace

LabelMap ParseLabelMap(const std::string& text) {
  if (text == "acdc") return LabelMap{3, 2, 1};
  if (text == "mnms") return LabelMap{1, 2, 3};
  std::map<std::string, int> values;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const size_t eq = item.find('=');
    const std::string key = item.substr(0, eq);
    if (eq == std::string::npos ||
        (key != "lv" && key != "myo" && key != "rv")) {
      Refuse(text, "'" + item + "' is not lv=, myo= or rv=");
    }
    if (values.count(key) > 0) Refuse(text, key + " given twice");
    values[key] = LabelValue(text, key, item.substr(eq + 1));
  }
  if (values.count("lv") == 0 || values.count("myo") == 0) {
    Refuse(text, "lv and myo are needed");
  }
  const LabelMap map{values["lv"], values["myo"],
                     values.count("rv") > 0 ? values["rv"] : -1};
  if (map.lv == map.myo || map.lv == map.rv || map.myo == map.rv) {
    Refuse(text, "two structures share a label");
  }
  return map;
}

}  // namespace pfdm
