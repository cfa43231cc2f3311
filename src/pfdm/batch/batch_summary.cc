#include "pfdm/batch/batch_summary.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>

#include "nlohmann/json.hpp"
#include "pfdm/util/error.h"

namespace pfdm {

const char* const kHalfWidthColumns[10] = {
    "ed_volume_ml",
    "es_volume_ml",
    "ejection_fraction",
    "lv_mass_g",
    "wall_thickening_at_es_percent",
    "net_twist_at_es_deg",
    "longitudinal_shortening_at_es_percent",
    "radial_contraction_at_es_percent",
    "peak_gcs_percent",
    "peak_gls_percent"};

namespace {

// A number of fit.json, NaN where it is null (what the data cannot
// determine).
double NumberOrNaN(const nlohmann::json& value) {
  return value.is_null() ? std::numeric_limits<double>::quiet_NaN()
                         : value.get<double>();
}

// A CSV field: empty for NaN, as for every number that does not apply.
std::string Field(double value) {
  if (std::isnan(value)) return "";
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

// Half the width of object[key + "_ci95"], NaN without one.
double HalfWidth(const nlohmann::json& object, const std::string& key) {
  const auto it = object.find(key + "_ci95");
  if (it == object.end() || !it->is_array() || it->size() != 2) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return 0.5 * ((*it)[1].get<double>() - (*it)[0].get<double>());
}

// The intervals' half-widths, in kHalfWidthColumns' order.
void ReadHalfWidths(const nlohmann::json& fit, const nlohmann::json& ef,
                    CaseSummary* summary) {
  const nlohmann::json& frames = fit.at("frames");
  const nlohmann::json& es = frames.at(summary->es_frame).at("clinical");
  const nlohmann::json strain = fit.value("strain", nlohmann::json::object());
  summary->half_widths = {HalfWidth(ef, "edv_ml"),
                          HalfWidth(ef, "esv_ml"),
                          HalfWidth(ef, "ratio"),
                          HalfWidth(frames.at(0), "lv_mass_g"),
                          HalfWidth(es, "wall_thickening_percent"),
                          HalfWidth(es, "net_twist_deg"),
                          HalfWidth(es, "longitudinal_shortening_percent"),
                          HalfWidth(es, "radial_contraction_percent"),
                          HalfWidth(strain, "peak_gcs_percent"),
                          HalfWidth(strain, "peak_gls_percent")};
  summary->has_intervals = fit.contains("uncertainty_definition");
}

// ",hw,hw,..." for the case (empty fields where it has none).
std::string HalfWidthFields(const CaseSummary& c) {
  std::string out;
  for (size_t i = 0; i < std::size(kHalfWidthColumns); ++i) {
    out += ',';
    if (i < c.half_widths.size() && (i != 2 || c.volume_surface == "cavity")) {
      out += Field(c.half_widths[i]);
    }
  }
  return out;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return quoted + "\"";
}

// fit.json's overall quality and its frames' distinct reason codes.
void ReadQuality(const nlohmann::json& fit, CaseSummary* summary) {
  if (!fit.contains("quality")) return;
  summary->quality = fit["quality"].at("overall").get<std::string>();
  for (const auto& frame : fit.at("frames")) {
    for (const auto& reason :
         frame.value("quality_reasons", nlohmann::json::array())) {
      const std::string code = reason.at("code").get<std::string>();
      std::vector<std::string>& codes = summary->quality_reasons;
      if (std::find(codes.begin(), codes.end(), code) == codes.end()) {
        codes.push_back(code);
      }
    }
  }
}

std::string Joined(const std::vector<std::string>& items) {
  std::string joined;
  for (const std::string& item : items) {
    joined += (joined.empty() ? "" : ";") + item;
  }
  return joined;
}

}  // namespace

CaseSummary SummaryFromFitJson(const std::string& name,
                               const std::string& json_text,
                               const std::string& where) {
  CaseSummary summary;
  summary.name = name;
  summary.status = "done";
  try {
    const nlohmann::json fit = nlohmann::json::parse(json_text);
    const nlohmann::json& frames = fit.at("frames");
    // fit.json from before the wall model: the volume was the cavity's.
    const nlohmann::json model = fit.value("model", nlohmann::json::object());
    summary.volume_surface =
        model.value("volume_surface", std::string("cavity"));
    const bool cavity = summary.volume_surface == "cavity";
    const nlohmann::json& ef =
        fit.at(cavity ? "ejection_fraction"
                      : summary.volume_surface + "_volume_fraction");
    summary.frames = static_cast<int>(frames.size());
    for (const auto& frame : frames) {
      summary.max_rms_mm =
          std::max(summary.max_rms_mm, frame.at("rms_mm").get<double>());
    }
    summary.edv_ml = NumberOrNaN(ef.at("edv_ml"));
    summary.esv_ml = NumberOrNaN(ef.at("esv_ml"));
    summary.es_frame = ef.at("es_frame").get<int>();
    summary.ejection_fraction = NumberOrNaN(ef.at("ratio"));
    const nlohmann::json& es = frames.at(summary.es_frame).at("clinical");
    const nlohmann::json& twist = es.at("net_twist_deg");
    summary.twist_measured = !twist.is_null();
    if (summary.twist_measured) summary.net_twist_deg = twist.get<double>();
    summary.longitudinal_shortening_percent =
        NumberOrNaN(es.at("longitudinal_shortening_percent"));
    summary.radial_contraction_percent =
        NumberOrNaN(es.at("radial_contraction_percent"));
    summary.solid = model.value("wall", std::string()) == "solid";
    if (summary.solid) {
      summary.lv_mass_g = NumberOrNaN(frames.at(0).at("lv_mass_g"));
      summary.wall_thickening_percent =
          NumberOrNaN(es.at("wall_thickening_percent"));
    }
    ReadQuality(fit, &summary);
    ReadHalfWidths(fit, ef, &summary);
    if (fit.contains("strain")) {
      summary.has_strain = true;
      summary.peak_gcs_percent =
          NumberOrNaN(fit["strain"].at("peak_gcs_percent"));
      summary.peak_gls_percent =
          NumberOrNaN(fit["strain"].at("peak_gls_percent"));
    }
  } catch (const nlohmann::json::exception& error) {
    throw InputError(where + ": not a pfdm fit.json: " + error.what());
  }
  return summary;
}

std::string SummaryCsv(const std::vector<CaseSummary>& cases) {
  std::ostringstream out;
  out.precision(6);
  out << "case,status,quality,frames,max_rms_mm,volume_surface,ed_volume_ml,"
         "es_volume_ml,es_frame,ejection_fraction,lv_mass_g,"
         "wall_thickening_at_es_percent,net_twist_at_es_deg,"
         "longitudinal_shortening_at_es_percent,"
         "radial_contraction_at_es_percent,peak_gcs_percent,"
         "peak_gls_percent,quality_reasons,error";
  const bool intervals =
      std::any_of(cases.begin(), cases.end(),
                  [](const CaseSummary& c) { return c.has_intervals; });
  for (const char* column : kHalfWidthColumns) {
    if (intervals) out << ',' << column << "_hw95";
  }
  out << '\n';
  for (const CaseSummary& c : cases) {
    out << CsvField(c.name) << ',' << c.status << ',' << c.quality << ',';
    if (c.status == "done") {
      out << c.frames << ',' << c.max_rms_mm << ',' << c.volume_surface << ','
          << Field(c.edv_ml) << ',' << Field(c.esv_ml) << ',' << c.es_frame
          << ',';
      if (c.volume_surface == "cavity") out << Field(c.ejection_fraction);
      out << ',';
      if (c.solid)
        out << Field(c.lv_mass_g) << ',' << Field(c.wall_thickening_percent);
      else
        out << ',';
      out << ',';
      if (c.twist_measured) out << c.net_twist_deg;
      out << ',' << Field(c.longitudinal_shortening_percent) << ','
          << Field(c.radial_contraction_percent) << ',';
      if (c.has_strain) {
        out << Field(c.peak_gcs_percent) << ',' << Field(c.peak_gls_percent)
            << ',';
      } else {
        out << ",,";
      }
      out << Joined(c.quality_reasons) << ',';
    } else {
      out << ",,,,,,,,,,,,,,,";
    }
    out << CsvField(c.error);
    if (intervals) out << HalfWidthFields(c);
    out << '\n';
  }
  return out.str();
}

}  // namespace pfdm
