#include "pfdm/phantom/lv_truth_json.h"

#include "nlohmann/json.hpp"

namespace pfdm {
namespace {

using Json = nlohmann::ordered_json;

Json RingsJson(const LvLayerRings& rings) {
  return {{"rotation_deg", rings.rotation_deg},
          {"radial_contraction_percent", rings.radial_contraction_percent}};
}

Json FrameJson(const LvFrameTruth& truth) {
  Json frame;
  frame["frame"] = truth.frame;
  frame["progress"] = truth.progress;
  frame["rigid"] = {{"axial_shift_mm", truth.rigid.axial_shift_mm},
                    {"lateral_shift_mm", truth.rigid.lateral_shift_mm},
                    {"tilt_deg", truth.rigid.tilt_deg},
                    {"spin_deg", truth.rigid.spin_deg}};
  Json matrix = Json::array();
  for (int row = 0; row < 4; ++row) {
    Json values = Json::array();
    for (int col = 0; col < 4; ++col) {
      values.push_back(truth.world_from_body.matrix()(row, col));
    }
    matrix.push_back(values);
  }
  frame["world_from_body"] = matrix;
  frame["length_mm"] = truth.length_mm;
  frame["longitudinal_shortening_percent"] =
      truth.longitudinal_shortening_percent;
  frame["apex_rotation_deg"] = truth.apex_rotation_deg;
  frame["base_rotation_deg"] = truth.base_rotation_deg;
  frame["net_twist_deg"] = truth.net_twist_deg;
  frame["mean_radial_contraction_percent"] =
      truth.mean_radial_contraction_percent;
  frame["volume_ml"] = truth.volume_ml;
  frame["endo_volume_ml"] = truth.endo_volume_ml;
  frame["epi_volume_ml"] = truth.epi_volume_ml;
  frame["myocardial_volume_ml"] = truth.myocardial_volume_ml;
  frame["rings"] = {{"midwall", RingsJson(truth.midwall)},
                    {"endo", RingsJson(truth.endo)},
                    {"epi", RingsJson(truth.epi)}};
  Json segments = Json::array();
  for (const LvSegmentTruth& segment : truth.segments) {
    segments.push_back(
        {{"segment", segment.segment},
         {"name", segment.name},
         {"rotation_deg", segment.rotation_deg},
         {"radial_contraction_percent", segment.radial_contraction_percent}});
  }
  frame["segments"] = segments;
  frame["outlier_ids"] = truth.outlier_ids;
  return frame;
}

}  // namespace

std::string LvTruthJson(const LvPhantom& phantom) {
  const LvPhantomOptions& options = phantom.options;
  const LvShape shape(options.shape);
  const LvDeformation& design = options.deformation;
  Json json;
  json["phantom"] = "lv";
  json["kinematics"] = LvKinematicsName(options.kinematics);
  json["tags"] = LvTagLayerName(options.tags);
  json["lesion"] = design.lesion;
  json["breathing"] = options.breathing;
  json["num_frames"] = options.num_frames;
  json["num_tags"] = options.num_tags;
  json["region"] = LvRegionName(options.region);
  json["region_heights"] = {LvRegionHeights(options.region).low,
                            LvRegionHeights(options.region).high};
  json["sampling"] = LvSamplingName(options.sampling);
  json["shell"] = LvGeometryName(options.geometry);
  json["thickening"] = LvThickeningLawName(options.law);
  if (options.sampling == LvSampling::kSaxSlices) {
    json["slice_heights"] = LvSliceHeights(options);
  }
  json["noise_mm"] = options.noise_mm;
  json["outlier_fraction"] = options.outlier_fraction;
  json["outlier_mm"] = {options.outlier_min_mm, options.outlier_max_mm};
  json["seed"] = options.seed;
  json["geometry"] = {{"length_mm", options.shape.length_mm},
                      {"radius_mm", options.shape.radius_mm},
                      {"wall_mm", options.shape.wall_mm},
                      {"base_nu_deg", options.shape.base_nu_deg},
                      {"focal_mm", shape.focal_mm()},
                      {"mu_mid", shape.mu_mid()},
                      {"dmu", shape.dmu()}};
  json["design"] = {{"longitudinal_shortening", design.longitudinal_shortening},
                    {"radial_apex", design.radial_apex},
                    {"radial_base", design.radial_base},
                    {"radial_endo_extra", design.radial_endo_extra},
                    {"radial_epi_less", design.radial_epi_less},
                    {"apex_rotation_deg", design.apex_rotation_deg},
                    {"base_rotation_deg", design.base_rotation_deg},
                    {"lesion_loss", design.lesion_loss},
                    {"lesion_edge_h", design.lesion_edge_h},
                    {"lesion_edge_deg", design.lesion_edge_deg},
                    {"lesion_center_deg", design.lesion_center_deg},
                    {"lesion_outer_w", design.lesion_outer_w},
                    {"lesion_edge_w", design.lesion_edge_w}};
  json["ring_heights"] = LvRingHeights();
  const Eigen::Vector3d& a = phantom.rv_anterior;
  const Eigen::Vector3d& b = phantom.rv_inferior;
  json["rv_insertion"] = {
      {"anterior", {a.x(), a.y(), a.z()}},
      {"inferior", {b.x(), b.y(), b.z()}},
      {"body_longitude_deg",
       {kLvAnteriorInsertionDeg, kLvInferiorInsertionDeg}},
      {"height_fraction", kLvInsertionHeight},
      {"definition",
       "frame 0's world positions of the RV insertion points (mid-wall): "
       "pfdm fit --rv_insertion anterior,inferior places the AHA segments "
       "by them; the default lesion lies in segment 8, mid anteroseptal"}};
  int es = 0;
  for (size_t t = 0; t < phantom.truth.size(); ++t) {
    if (phantom.truth[t].endo_volume_ml < phantom.truth[es].endo_volume_ml) {
      es = static_cast<int>(t);
    }
  }
  const double edv = phantom.truth.front().endo_volume_ml;
  const double esv = phantom.truth[es].endo_volume_ml;
  json["summary"] = {{"edv_ml", edv},
                     {"esv_ml", esv},
                     {"es_frame", es},
                     {"ejection_fraction", (edv - esv) / edv}};
  Json frames = Json::array();
  for (const LvFrameTruth& truth : phantom.truth) {
    frames.push_back(FrameJson(truth));
  }
  json["frames"] = frames;
  return json.dump(1) + "\n";
}

}  // namespace pfdm
