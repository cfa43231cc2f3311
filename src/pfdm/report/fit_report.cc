#include "pfdm/report/fit_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/cycle_charts.h"
#include "pfdm/report/interval_text.h"
#include "pfdm/report/key_numbers.h"
#include "pfdm/report/layer_table.h"
#include "pfdm/report/report_text.h"
#include "pfdm/report/segment_curves.h"
#include "pfdm/report/surface_view.h"
#include "pfdm/report/verdict_box.h"
#include "pfdm/util/markup_escape.h"
#include "pfdm/util/verdict.h"
#include "pfdm/util/version.h"

namespace pfdm {
namespace {

// For data whose frame 0 has no tracked points, where no turn about the
// axis is seen.
constexpr const char* kUntrackedNote =
    "<p class=\"note\"><b>No tracked points:</b> frame 0, the reference of "
    "every rotation, has no points whose ids recur in later frames "
    "(contours, not tags), so no rotation about the axis is seen: rotation, "
    "twist, torsion and shear (and Ecl) are n/a in every frame and left out "
    "of the plots. In frames without tracked points the fit holds twist at "
    "0, and a1..a3 and bending describe the shape of each frame rather than "
    "the motion of material points. Volumes and contraction of the shape "
    "still hold.</p>\n";

// Where rotation is measured in some frames but not all (FitAnalysis::
// rotation_measured): which frames read n/a, and why; "" otherwise.
std::string UntrackedNote(const FitAnalysis& analysis) {
  const std::vector<bool>& measured = analysis.rotation_measured;
  if (std::none_of(measured.begin(), measured.end(),
                   [](bool m) { return m; })) {
    return measured.empty() ? "" : kUntrackedNote;
  }
  std::ostringstream frames;
  int count = 0;
  for (size_t t = 0; t < measured.size(); ++t) {
    if (!measured[t]) frames << (count++ ? ", " : "") << t;
  }
  if (count == 0) return "";
  std::ostringstream h;
  h << "<p class=\"note\"><b>Frames without tracked points:</b> "
    << (count == 1 ? "frame " : "frames ") << frames.str()
    << ", where no point keeps a material point from an earlier frame "
       "(contours), so rotation about the axis cannot be seen and the fit "
       "holds twist: their rotation, twist, torsion and shear (and Ecl) are "
       "n/a and left out of the plots.</p>\n";
  return h.str();
}

// "frame 3" or "frames 1, 2".
std::string FrameList(const std::vector<size_t>& frames) {
  std::ostringstream text;
  text << (frames.size() == 1 ? "frame " : "frames ");
  for (size_t i = 0; i < frames.size(); ++i)
    text << (i ? ", " : "") << frames[i];
  return text.str();
}

// What the frames without a volume lack, each group with its own reason:
// those whose data span too little of the axis (volume_measured), then
// those with nothing that places the walls (walls_measured); a frame
// short of both is named once, with the first.
std::string NoVolumeClauses(const std::vector<size_t>& short_span,
                            const std::vector<size_t>& unseen) {
  std::string clauses;
  if (!short_span.empty()) {
    clauses = FrameList(short_span) +
              (short_span.size() == 1 ? " spans" : " span") +
              " too little of the axis for a volume";
  }
  if (!unseen.empty()) {
    clauses += (clauses.empty() ? "" : "; ") + FrameList(unseen) +
               " with nothing that places the walls " +
               (unseen.size() == 1 ? "has" : "have") + " no cavity";
  }
  return clauses;
}

// How ES was found, "the frame of least <volume>, frame k", and where
// frames have no volume (FitAnalysis::volume_measured, walls_measured)
// which frames and why: a short span, or, where ES was found inside the
// mid-wall (EjectionFraction::es_by_midwall), nothing that places the
// walls.
std::string EndSystolePhrase(const FitAnalysis& analysis,
                             const std::string& volume_name) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const auto walls = [&analysis](size_t t) {
    return t >= analysis.walls_measured.size() || analysis.walls_measured[t];
  };
  std::vector<size_t> short_span, unseen;
  for (size_t t = 0; t < analysis.volume_measured.size(); ++t) {
    if (!analysis.volume_measured[t]) {
      short_span.push_back(t);
    } else if (!walls(t)) {
      unseen.push_back(t);
    }
  }
  const std::string clauses = NoVolumeClauses(short_span, unseen);
  const std::string es = ", frame " + std::to_string(ef.es_frame);
  if (clauses.empty()) return "the frame of least " + volume_name + es;
  if (!ef.es_by_midwall) {
    return "the frame of least " + volume_name + es + " of those with one (" +
           clauses + ", so ESV and the ejection fraction are n/a)";
  }
  const size_t es_frame = static_cast<size_t>(ef.es_frame);
  const bool es_without =
      !walls(es_frame) || (es_frame < analysis.volume_measured.size() &&
                           !analysis.volume_measured[es_frame]);
  const char* which = Measured(ef.ratio) ? ")"
                      : es_without ? "; ES is one of them, so ESV and the "
                                     "ejection fraction are n/a)"
                                   : "; ED is one of them, so EDV and the "
                                     "ejection fraction are n/a)";
  return "the frame of least volume inside the mid-wall, which the tags "
         "place in every frame" +
         es + " (" + clauses + which;
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:24px;color:#222;max-width:1250px}"
    "h1{font-size:22px}h2{font-size:18px;margin-top:28px}"
    "table{border-collapse:collapse;font-size:13px}"
    "td,th{border:1px solid #ccc;padding:3px 7px;text-align:right}"
    "th{background:#f0f0f0}td.l,th.l{text-align:left}"
    ".key{display:flex;gap:14px;flex-wrap:wrap}"
    ".key div{border:1px solid #ccc;border-radius:6px;padding:8px 14px}"
    ".key b{display:block;font-size:22px}"
    "p.note{font-size:13px;color:#555;max-width:1100px}"
    "svg{max-width:100%;height:auto}.charts{display:flex;flex-wrap:wrap}";

// The page's head and the paragraph that says what was fitted to what.
std::string PageHead(const PointSequence& points, const SequenceFit& fit,
                     const FitAnalysis& analysis) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const std::string volume_name = VolumeName(analysis);
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
    << "<title>pfdm fit: " << EscapeMarkup(points.source) << "</title>"
    << "<style>" << kStyle << "</style></head><body>\n"
    << "<h1>Left-ventricular motion from a parameter-function fit</h1>\n"
    << "<p>Data <code>" << EscapeMarkup(points.source) << "</code>, "
    << fit.frames.size() << " frames; model <code>"
    << EscapeMarkup(fit.config.name) << "</code> with " << fit.config.num_knots
    << " knots from apex to base. End-diastole (ED) is frame " << ef.ed_frame
    << ", end-systole (ES) " << EndSystolePhrase(analysis, volume_name)
    << ". Wall: "
    << (fit.config.Solid() ? "a solid from endocardium to epicardium"
                           : "one surface")
    << " (" << EscapeMarkup(fit.wall_reason) << ").</p>\n";
  if (!fit.left_out.empty()) {
    h << "<p class=\"note\">Left out of the fit, their slice holding the "
         "outflow tract beside the long axis, not the ventricle round it "
         "(docs/contour_sequences.md):";
    for (const LeftOutContour& c : fit.left_out) {
      h << " frame " << c.frame << " " << EscapeMarkup(c.contour) << " ("
        << c.points << " points);";
    }
    h << "</p>\n";
  }
  return h.str();
}

// How the numbers are measured, and what the volumes are of.
std::string MeasurementNote(const SequenceFit& fit,
                            const FitAnalysis& analysis) {
  const bool cavity = analysis.volume_surface == "cavity";
  std::ostringstream h;
  h << "<p class=\"note\">Every number here is measured on the fitted "
       "model's material points against ED. Rotation is about the ED long "
       "axis (apex to base), right-handed, of the material rings at 20 % "
       "(apex) and 85 % (base) of the ED length from the apex: seen from the "
       "apex a normal apex turns counter-clockwise (negative) and the base "
       "clockwise (positive), so net twist = base &minus; apex is positive, "
       "about 10&ndash;15&deg; at a normal ES; torsion is net twist over the "
       "ED distance between those rings. Radial contraction: 1 &minus; r/r"
       "<sub>ED</sub>, r the mean distance of a ring's material points from "
       "their centroid; longitudinal shortening: of the distance from the "
       "apex to the base rim's centroid. "
    << (fit.config.Solid()
            ? "Endocardial and epicardial numbers are measured likewise on "
              "each wall's material rings; wall thickness is the "
              "endocardial-to-epicardial chord of a material point along "
              "the mid-wall's normal, thickening its change against ED; the "
              "cavity is inside the endocardium and the myocardium between "
              "the walls. "
        : cavity ? ""
                 : "The data lie on one surface through the wall (tags "
                   "on a mid-wall), so the volume it encloses includes "
                   "part of the myocardium and is not the cavity: fit "
                   "tags through the wall or contours of both walls for "
                   "that. ")
    << "Volumes close the fitted surface "
    << (!analysis.base_planes.empty()
            ? "at each frame's mitral valve plane (through the MITRAL_VALVE "
              "guide points)"
        : HasSlicePlanes(analysis)
            ? "at the highest short-axis slice, both walls at the plane of "
              "the lowest wall's rim, which the fit puts there (the other "
              "wall's rim lies above it)"
            : "with a flat lid at the base rim")
    << ".</p>\n";
  return h.str();
}

// The parameter functions and the curves over the cycle, strain's where
// given.
std::string PlotSections(const std::string& parameters_svg,
                         const FitAnalysis& analysis) {
  std::ostringstream h;
  h << "<h2>Parameter functions</h2>\n"
    << InlineSvg(parameters_svg) << "\n"
    << "<p class=\"note\">a1, a2: radii along the model's x and y axes; "
       "a3: the ring's distance along the axis; each as a ratio to ED, so "
       "0.8 is 20 % contraction. Knot 0 is the apex pole, where the data "
       "cannot see a1, a2 or tau: its value is the smoothness "
       "prior's extrapolation.</p>\n";
  h << "<h2>Over the cycle</h2>\n" << CycleChartsHtml(analysis);
  if (!analysis.strain.empty()) {
    h << "<p class=\"note\">Hover over a point for its value (and its 95 % "
         "interval, where the bar shows one). Lagrangian (Green-Lagrange) "
         "strain of the "
         "fitted surface against ED, E = (F<sup>T</sup>F &minus; I)/2 with F "
         "the deformation gradient of the surface's tangent plane at each "
         "material point: Ecc along the ED circle of latitude, Ell along the "
         "ED meridian (apex to base), in percent; negative is shortening. "
         "GCS and GLS are area-weighted means over the whole surface from "
         "the apex to the base rim, the levels over their thirds of the ED "
         "axis. Green-Lagrange strain reads a little smaller in magnitude "
         "than engineering strain (&minus;20 % of length is &minus;18 % "
         "Green-Lagrange).</p>\n";
  }
  return h.str();
}

// Each frame's fit errors, volume and clinical numbers.
std::string FrameTable(const SequenceFit& fit, const FitAnalysis& analysis) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const std::string volume_name = VolumeName(analysis);
  const bool solid = fit.config.Solid();
  std::ostringstream h;
  h << "<h2>Per frame</h2>\n<table><tr><th>frame</th><th>points</th>"
    << "<th>RMS mm</th><th>mean mm</th><th>max mm</th><th>" << volume_name
    << " ml</th>"
    << "<th>net twist &deg;</th><th>apex &deg;</th><th>base &deg;</th>"
    << "<th>torsion &deg;/cm</th><th>radial %</th><th>longitudinal %</th>"
    << "<th>GCS %</th><th>GLS %</th>"
    << (solid ? "<th>myocardium &Delta; %</th>" : "")
    << "<th class=\"l\">solver</th><th class=\"l\">quality</th></tr>\n";
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    const FrameFit& f = fit.frames[t];
    const ClinicalSummary& c = analysis.clinical[t];
    auto pm = [&](double ClinicalSummary::*field, int digits, const char* key) {
      return Fixed(c.*field, digits) +
             PlusMinus(ClinicalSd(analysis, t, field), digits,
                       KeyCalibration(analysis.interval_data, key),
                       ClinicalBias(analysis, t, field));
    };
    auto strain = [&](double GlobalStrain::*field, const char* key) {
      return t < analysis.strain.size()
                 ? Fixed(analysis.strain[t].*field, 1) +
                       PlusMinus(StrainSd(analysis, t, field), 1,
                                 KeyCalibration(analysis.interval_data, key),
                                 StrainBias(analysis, t, field))
                 : "";
    };
    h << "<tr><td>" << f.frame
      << (static_cast<int>(t) == ef.es_frame ? " ES"
          : t == 0                           ? " ED"
                                             : "")
      << "</td><td>" << f.residuals.size() << "</td><td>" << Fixed(f.rms_mm, 2)
      << "</td><td>" << Fixed(f.mean_distance_mm, 2) << "</td><td>"
      << Fixed(f.max_distance_mm, 2) << "</td><td>"
      << pm(&ClinicalSummary::volume_ml, 1, "volume_ml") << "</td><td>"
      << pm(&ClinicalSummary::net_twist_deg, 1, "net_twist_deg") << "</td><td>"
      << pm(&ClinicalSummary::apex_rotation_deg, 1, "apex_rotation_deg")
      << "</td><td>"
      << pm(&ClinicalSummary::base_rotation_deg, 1, "base_rotation_deg")
      << "</td><td>"
      << pm(&ClinicalSummary::torsion_deg_per_cm, 2, "torsion_deg_per_cm")
      << "</td><td>"
      << pm(&ClinicalSummary::radial_contraction_percent, 1,
            "radial_contraction_percent")
      << "</td><td>"
      << pm(&ClinicalSummary::longitudinal_shortening_percent, 1,
            "longitudinal_shortening_percent")
      << "</td><td>" << strain(&GlobalStrain::gcs_percent, "gcs_percent")
      << "</td><td>" << strain(&GlobalStrain::gls_percent, "gls_percent")
      << (solid ? "</td><td>" + Fixed(c.myocardial_volume_change_percent, 1)
                : "")
      << "</td><td class=\"l\">"
      << EscapeMarkup(f.termination + UnsettledNote(f))
      << "</td><td class=\"l\">"
      << (t < analysis.verdicts.size()
              ? QualityName(analysis.verdicts[t].quality())
              : "")
      << "</td></tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

// One segment's motion and strain at ES, tinted, and its peak Ecc.
std::string RegionRow(const FitAnalysis& analysis, size_t r, bool solid) {
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  const WallRegion& region = analysis.regions[r];
  const size_t es = analysis.ejection_fraction.es_frame;
  const RegionMotion& motion = analysis.region_motion[es][r];
  const int peak = PeakEccFrame(analysis, r);
  const double peak_ecc = PeakRegionEcc(analysis.region_motion)[r];
  auto pm = [&](double RegionMotion::*field, const char* key, size_t t = 0) {
    return PlusMinus(RegionSd(analysis, t ? t : es, r, field), 1,
                     KeyCalibration(analysis.interval_data, key),
                     RegionBias(analysis, t ? t : es, r, field));
  };
  std::ostringstream h;
  h << "<tr><td>" << region.segment << "</td><td class=\"l\">" << region.Name()
    << "</td><td>" << Fixed(region.v_begin * kDegrees, 0) << " to "
    << Fixed(region.v_end * kDegrees, 0) << "</td><td"
    << Tint(motion.rotation_deg, 15.0) << ">" << Fixed(motion.rotation_deg, 1)
    << pm(&RegionMotion::rotation_deg, "rotation_deg") << "</td><td"
    << Tint(motion.radial_contraction_percent, 40.0) << ">"
    << Fixed(motion.radial_contraction_percent, 1)
    << pm(&RegionMotion::radial_contraction_percent,
          "radial_contraction_percent")
    << "</td><td" << Tint(-motion.ecc_percent, 30.0) << ">"
    << Fixed(motion.ecc_percent, 1)
    << pm(&RegionMotion::ecc_percent, "ecc_percent") << "</td><td"
    << Tint(-motion.ell_percent, 30.0) << ">" << Fixed(motion.ell_percent, 1)
    << pm(&RegionMotion::ell_percent, "ell_percent") << "</td><td>"
    << Fixed(motion.ecl_percent, 1)
    << pm(&RegionMotion::ecl_percent, "ecl_percent") << "</td><td"
    << Tint(-peak_ecc, 30.0) << ">" << Fixed(peak_ecc, 1)
    << (peak > 0 ? pm(&RegionMotion::ecc_percent, "peak_ecc_percent", peak)
                 : "")
    << "</td>";
  if (solid) {
    h << "<td" << Tint(motion.thickening_percent, 60.0) << ">"
      << Fixed(motion.thickening_percent, 1)
      << pm(&RegionMotion::thickening_percent, "thickening_percent") << "</td>";
  }
  h << "</tr>\n";
  return h.str();
}

// The bull's-eye maps where given and the segments' table at ES.
std::string RegionalSection(const SequenceFit& fit, const FitAnalysis& analysis,
                            const std::string& bullseye_svg) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  std::ostringstream h;
  h << "<h2>Regional wall motion at ES (frame " << ef.es_frame << ")</h2>\n";
  if (!bullseye_svg.empty()) {
    h << InlineSvg(bullseye_svg) << "\n"
      << "<p class=\"note\">Bull's-eye maps in the AHA layout: basal ring "
         "outside, mid, apical, the apex (17) in the centre; segment number "
         "above its value; segment 1 (and 7, 13) at the top, numbers "
         "counter-clockwise on the page. "
      << (analysis.layout.anatomical
              ? "The segments are anatomical (" +
                    EscapeMarkup(analysis.layout.anchor) +
                    "): the map is the LV seen from its apex, anterior at "
                    "the top, the septum on the left. "
              : "<b>The segments are not anatomical</b> (" +
                    EscapeMarkup(analysis.layout.anchor) +
                    "): sector 1 starts at the model's &minus;x axis and "
                    "sectors run counter-clockwise about the long axis seen "
                    "from the base, so the map is the LV seen from its base "
                    "and its numbers depend on the case. ")
      << "Peak Ecc and Ell: the most negative over the frames (red is "
         "shortening); radial contraction and a solid's thickening (red is "
         "inward, thicker) "
      << (Measured(analysis.clinical[ef.es_frame].net_twist_deg)
              ? "and rotation (green counter-clockwise seen from the base) "
                "at ES"
              : "at ES; rotation is n/a there (no tracked points), and has "
                "no map")
      << ". Each scale is symmetric about 0.</p>\n";
  }
  if (analysis.regional_limit != RegionalLimit::kNone) {
    h << "<p class=\"note\"><b>Through the wall:</b> "
      << EscapeMarkup(RegionalLimitNote(analysis.regional_limit)) << "</p>\n";
  }
  h << "<table><tr><th>segment</th><th class=\"l\">region</th>"
    << "<th>longitude v, &deg;</th><th>rotation &deg;</th>"
    << "<th>radial contraction %</th><th>Ecc %</th><th>Ell %</th>"
    << "<th>Ecl %</th><th>peak Ecc %</th>"
    << (fit.config.Solid() ? "<th>thickening %</th>" : "") << "</tr>\n";
  for (size_t r = 0; r < analysis.regions.size(); ++r) {
    h << RegionRow(analysis, r, fit.config.Solid());
  }
  h << "</table>\n<p class=\"note\">Segments: thirds of the ED axis (basal, "
       "mid, apical) cut into "
    << analysis.layout.basal_sectors << ", " << analysis.layout.mid_sectors
    << " and " << analysis.layout.apical_sectors
    << " sectors of longitude, and the apex cap (17, the lowest "
    << Fixed(100 * analysis.layout.apex_cap_fraction, 0) << " % of the axis"
    << (analysis.apex_cap_measured ? ""
                                   : "; n/a here: the data do not reach the "
                                     "apex")
    << "). "
    << (analysis.layout.anatomical
            ? "Anatomical, the AHA's: basal and mid sectors of 60&deg; from "
              "the anterior RV insertion (the border of anterior and "
              "anteroseptal) through the septum to the inferior wall; the "
              "apical septal sector centred on the basal septum."
            : "Not anatomical: counted counter-clockwise seen from the base "
              "from the model's &minus;x axis, which the fit takes from the "
              "data; give --rv_insertion (or guide points with RV_INSERT) "
              "for the AHA's.")
    << " Rotation: mean turn of the segment's material points about "
       "the ED long axis; radial contraction: mean of 1 &minus; "
       "r/r<sub>ED</sub>, r a material point's distance from its ring's "
       "centroid; Ecc, Ell, Ecl: the segment's mean Green-Lagrange strains "
       "at ES, peak Ecc the most negative over the frames.</p>\n";
  return h.str();
}

// What made the report and when (FitAnalysis::made_by, made_utc).
std::string Footer(const FitAnalysis& analysis) {
  if (analysis.made_by.empty()) return "";
  return "<footer class=\"note\">Made by pfdm " + std::string(PfdmVersion()) +
         (analysis.made_utc.empty() ? "" : " on " + analysis.made_utc) +
         ": <code>" + EscapeMarkup(analysis.made_by) + "</code></footer>\n";
}

}  // namespace

std::string InlineSvg(const std::string& svg_document) {
  const size_t start = svg_document.find("<svg");
  return start == std::string::npos ? "" : svg_document.substr(start);
}

std::string FitReportHtml(const PointSequence& points, const SequenceFit& fit,
                          const FitAnalysis& analysis,
                          const std::string& parameters_svg,
                          const std::string& bullseye_svg,
                          const std::string& slices_svg) {
  std::ostringstream h;
  h << PageHead(points, fit, analysis) << VerdictBoxHtml(fit, analysis)
    << KeyNumbersHtml(fit, analysis) << IntervalNoteHtml(analysis)
    << MeasurementNote(fit, analysis);
  h << UntrackedNote(analysis);
  if (!slices_svg.empty()) {
    h << "<h2>The segmentation and the fit</h2>\n"
      << InlineSvg(slices_svg) << "\n"
      << "<p class=\"note\">Short-axis slices of the mask (cavity red, "
         "myocardium green, RV blue) at ED and ES, with the fitted "
         "endocardium (yellow) and epicardium (white) where they cut each "
         "slice's plane.</p>\n";
  }
  h << SurfaceViewHtml(points, fit, analysis)
    << PlotSections(parameters_svg, analysis) << FrameTable(fit, analysis)
    << RegionalSection(fit, analysis, bullseye_svg) << LayerTableHtml(analysis)
    << SegmentCurvesHtml(analysis) << Footer(analysis) << "</body></html>\n";
  return h.str();
}

}  // namespace pfdm
