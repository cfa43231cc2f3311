#include "pfdm/report/fit_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/verdict_box.h"
#include "pfdm/util/markup_escape.h"
#include "pfdm/util/verdict.h"

namespace pfdm {
namespace {

// "n/a" for a number the data cannot determine (kNotMeasured).
std::string Fixed(double value, int digits) {
  if (!Measured(value)) return "n/a";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  // "-0.0" from a value that rounds to zero reads as a sign that is not
  // there (frame 0's strains, say).
  const std::string out = text;
  if (out[0] == '-' && out.find_first_not_of("-0.") == std::string::npos) {
    return out.substr(1);
  }
  return out;
}

// A background tint for a value in [-scale, scale]: orange for positive,
// blue for negative, white at zero, so a table reads like a map.
std::string Tint(double value, double scale) {
  if (!Measured(value)) return "";
  const double x = std::clamp(value / scale, -1.0, 1.0);
  const int fade = static_cast<int>(std::lround(255 - 110 * std::abs(x)));
  char style[64];
  if (x >= 0) {
    std::snprintf(style, sizeof(style), " style=\"background:#ff%02x%02x\"",
                  std::min(255, fade + 40), fade);
  } else {
    std::snprintf(style, sizeof(style), " style=\"background:#%02x%02xff\"",
                  fade, std::min(255, fade + 40));
  }
  return style;
}

// A value and its unit ("&deg;", " %"), or "n/a" alone.
std::string WithUnit(double value, int digits, const char* unit) {
  return Measured(value) ? Fixed(value, digits) + unit : "n/a";
}

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
    "svg{max-width:100%;height:auto}";

// What the volumes are of, as the page names them.
std::string VolumeName(const FitAnalysis& analysis) {
  return analysis.volume_surface == "cavity" ? "cavity volume"
         : analysis.volume_surface == "epicardial"
             ? "volume inside the epicardium"
             : "mid-wall enclosed volume";
}

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
    << ", end-systole (ES) the frame of least " << volume_name << ", frame "
    << ef.es_frame << ". Wall: "
    << (fit.config.Solid() ? "a solid from endocardium to epicardium"
                           : "one surface")
    << " (" << EscapeMarkup(fit.wall_reason) << ").</p>\n";
  return h.str();
}

// The ejection fraction where the volumes are the cavity's, else the
// volumes under what they are of.
std::string VolumeCard(const FitAnalysis& analysis) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  std::ostringstream h;
  if (analysis.volume_surface == "cavity") {
    h << "<div>ejection fraction<b>" << Fixed(100 * ef.ratio, 1) << " %</b>"
      << "EDV " << Fixed(ef.edv_ml, 1) << " ml, ESV " << Fixed(ef.esv_ml, 1)
      << " ml</div>";
  } else {
    h << "<div>" << VolumeName(analysis) << "<b>" << Fixed(ef.edv_ml, 1)
      << " ml</b>"
      << "at ED, " << Fixed(ef.esv_ml, 1)
      << " ml at ES: not the cavity, no ejection fraction</div>";
  }
  return h.str();
}

// A solid's mass, wall thickening and endocardial and epicardial motion.
std::string SolidCards(const ClinicalSummary& ed, const ClinicalSummary& es) {
  std::ostringstream h;
  h << "<div>LV mass at ED<b>" << Fixed(ed.lv_mass_g, 0) << " g</b>"
    << "myocardium " << Fixed(ed.myocardial_volume_ml, 0)
    << " ml at 1.05 g/ml</div>"
    << "<div>wall thickening at ES<b>" << Fixed(es.wall_thickening_percent, 1)
    << " %</b>" << Fixed(ed.wall_thickness_mm, 1) << " to "
    << Fixed(es.wall_thickness_mm, 1) << " mm</div>"
    << "<div>endo / epi net twist at ES<b>"
    << (Measured(es.endo_net_twist_deg)
            ? Fixed(es.endo_net_twist_deg, 1) + " / " +
                  Fixed(es.epi_net_twist_deg, 1) + "&deg;"
            : "n/a")
    << "</b>radial contraction " << Fixed(es.endo_radial_contraction_percent, 1)
    << " / " << Fixed(es.epi_radial_contraction_percent, 1) << " %</div>";
  return h.str();
}

// The key numbers, a card each, at ES unless said otherwise.
std::string KeyNumbers(const SequenceFit& fit, const FitAnalysis& analysis) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const StrainPeak gcs = PeakGcs(analysis.strain);
  const StrainPeak gls = PeakGls(analysis.strain);
  const ClinicalSummary& es = analysis.clinical[ef.es_frame];
  const ClinicalSummary& ed = analysis.clinical[ef.ed_frame];
  std::ostringstream h;
  h << "<div class=\"key\">" << VolumeCard(analysis);
  if (fit.config.Solid()) h << SolidCards(ed, es);
  h << "<div>net twist at ES<b>" << WithUnit(es.net_twist_deg, 1, "&deg;")
    << "</b>"
    << (Measured(es.net_twist_deg)
            ? "apex " + Fixed(es.apex_rotation_deg, 1) + "&deg;, base " +
                  Fixed(es.base_rotation_deg, 1) + "&deg;"
            : "no tracked points at ES")
    << "</div><div>torsion at ES<b>"
    << WithUnit(es.torsion_deg_per_cm, 2, "&deg;/cm") << "</b>shear angle "
    << WithUnit(es.shear_angle_deg, 1, "&deg;") << "</div>"
    << "<div>radial contraction at ES<b>"
    << Fixed(es.radial_contraction_percent, 1) << " %</b>"
    << "mean over ten rings</div>"
    << "<div>longitudinal shortening at ES<b>"
    << Fixed(es.longitudinal_shortening_percent, 1) << " %</b>"
    << "apex to base-rim centroid</div>"
    << "<div>peak GCS<b>" << Fixed(gcs.percent, 1) << " %</b>frame "
    << gcs.frame << ", circumferential</div>"
    << "<div>peak GLS<b>" << Fixed(gls.percent, 1) << " %</b>frame "
    << gls.frame << ", longitudinal</div></div>\n";
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
    << (analysis.base_planes.empty()
            ? "with a flat lid at the base rim"
            : "at each frame's mitral valve plane (through the MITRAL_VALVE "
              "guide points)")
    << ".</p>\n";
  return h.str();
}

// The parameter functions and the curves over the cycle, strain's where
// given.
std::string PlotSections(const std::string& parameters_svg,
                         const std::string& cycle_svg,
                         const std::string& strain_svg) {
  std::ostringstream h;
  h << "<h2>Parameter functions</h2>\n"
    << InlineSvg(parameters_svg) << "\n"
    << "<p class=\"note\">a1, a2: radii along the model's x and y axes; "
       "a3: the ring's distance along the axis; each as a ratio to ED, so "
       "0.8 is 20 % contraction. Knot 0 is the apex pole, where the data "
       "cannot see a1, a2 or tau: its value is the smoothness "
       "prior's extrapolation.</p>\n";
  h << "<h2>Over the cycle</h2>\n" << InlineSvg(cycle_svg) << "\n";
  if (!strain_svg.empty()) {
    h << InlineSvg(strain_svg) << "\n"
      << "<p class=\"note\">Lagrangian (Green-Lagrange) strain of the "
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
  std::ostringstream h;
  h << "<h2>Per frame</h2>\n<table><tr><th>frame</th><th>points</th>"
    << "<th>RMS mm</th><th>mean mm</th><th>max mm</th><th>" << volume_name
    << " ml</th>"
    << "<th>net twist &deg;</th><th>apex &deg;</th><th>base &deg;</th>"
    << "<th>torsion &deg;/cm</th><th>radial %</th><th>longitudinal %</th>"
    << "<th>GCS %</th><th>GLS %</th>"
    << "<th class=\"l\">solver</th><th class=\"l\">quality</th></tr>\n";
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    const FrameFit& f = fit.frames[t];
    const ClinicalSummary& c = analysis.clinical[t];
    h << "<tr><td>" << f.frame
      << (static_cast<int>(t) == ef.es_frame ? " ES"
          : t == 0                           ? " ED"
                                             : "")
      << "</td><td>" << f.residuals.size() << "</td><td>" << Fixed(f.rms_mm, 2)
      << "</td><td>" << Fixed(f.mean_distance_mm, 2) << "</td><td>"
      << Fixed(f.max_distance_mm, 2) << "</td><td>" << Fixed(c.volume_ml, 1)
      << "</td><td>" << Fixed(c.net_twist_deg, 1) << "</td><td>"
      << Fixed(c.apex_rotation_deg, 1) << "</td><td>"
      << Fixed(c.base_rotation_deg, 1) << "</td><td>"
      << Fixed(c.torsion_deg_per_cm, 2) << "</td><td>"
      << Fixed(c.radial_contraction_percent, 1) << "</td><td>"
      << Fixed(c.longitudinal_shortening_percent, 1) << "</td><td>"
      << (t < analysis.strain.size() ? Fixed(analysis.strain[t].gcs_percent, 1)
                                     : "")
      << "</td><td>"
      << (t < analysis.strain.size() ? Fixed(analysis.strain[t].gls_percent, 1)
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
std::string RegionRow(const WallRegion& region, const RegionMotion& motion,
                      double peak_ecc, bool solid) {
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  std::ostringstream h;
  h << "<tr><td>" << region.segment << "</td><td class=\"l\">" << region.Name()
    << "</td><td>" << Fixed(region.v_begin * kDegrees, 0) << " to "
    << Fixed(region.v_end * kDegrees, 0) << "</td><td"
    << Tint(motion.rotation_deg, 15.0) << ">" << Fixed(motion.rotation_deg, 1)
    << "</td><td" << Tint(motion.radial_contraction_percent, 40.0) << ">"
    << Fixed(motion.radial_contraction_percent, 1) << "</td><td"
    << Tint(-motion.ecc_percent, 30.0) << ">" << Fixed(motion.ecc_percent, 1)
    << "</td><td" << Tint(-motion.ell_percent, 30.0) << ">"
    << Fixed(motion.ell_percent, 1) << "</td><td>"
    << Fixed(motion.ecl_percent, 1) << "</td><td" << Tint(-peak_ecc, 30.0)
    << ">" << Fixed(peak_ecc, 1) << "</td>";
  if (solid) {
    h << "<td" << Tint(motion.thickening_percent, 60.0) << ">"
      << Fixed(motion.thickening_percent, 1) << "</td>";
  }
  h << "</tr>\n";
  return h.str();
}

// The bull's-eye maps where given and the segments' table at ES.
std::string RegionalSection(const SequenceFit& fit, const FitAnalysis& analysis,
                            const std::string& bullseye_svg) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const std::vector<RegionMotion>& motion = analysis.region_motion[ef.es_frame];
  const std::vector<double> peak_ecc = PeakRegionEcc(analysis.region_motion);
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
      << "Peak Ecc: the most "
         "negative over the frames (red is shortening); radial contraction "
         "(red is inward) "
      << (Measured(analysis.clinical[ef.es_frame].net_twist_deg)
              ? "and rotation (green counter-clockwise seen from the base) "
                "at ES"
              : "at ES; rotation is n/a there (no tracked points), and has "
                "no map")
      << ". Each scale is symmetric about 0.</p>\n";
  }
  h << "<table><tr><th>segment</th><th class=\"l\">region</th>"
    << "<th>longitude v, &deg;</th><th>rotation &deg;</th>"
    << "<th>radial contraction %</th><th>Ecc %</th><th>Ell %</th>"
    << "<th>Ecl %</th><th>peak Ecc %</th>"
    << (fit.config.Solid() ? "<th>thickening %</th>" : "") << "</tr>\n";
  for (size_t r = 0; r < analysis.regions.size(); ++r) {
    h << RegionRow(analysis.regions[r], motion[r], peak_ecc[r],
                   fit.config.Solid());
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

}  // namespace

std::string InlineSvg(const std::string& svg_document) {
  const size_t start = svg_document.find("<svg");
  return start == std::string::npos ? "" : svg_document.substr(start);
}

std::string FitReportHtml(const PointSequence& points, const SequenceFit& fit,
                          const FitAnalysis& analysis,
                          const std::string& parameters_svg,
                          const std::string& cycle_svg,
                          const std::string& strain_svg,
                          const std::string& bullseye_svg) {
  std::ostringstream h;
  h << PageHead(points, fit, analysis) << VerdictBoxHtml(fit, analysis)
    << KeyNumbers(fit, analysis) << MeasurementNote(fit, analysis);
  h << UntrackedNote(analysis);
  h << PlotSections(parameters_svg, cycle_svg, strain_svg)
    << FrameTable(fit, analysis) << RegionalSection(fit, analysis, bullseye_svg)
    << "</body></html>\n";
  return h.str();
}

}  // namespace pfdm
