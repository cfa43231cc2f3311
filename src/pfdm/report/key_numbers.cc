#include "pfdm/report/key_numbers.h"

#include <sstream>

#include "pfdm/report/global_strain.h"
#include "pfdm/report/interval_text.h"
#include "pfdm/report/report_text.h"

namespace pfdm {
namespace {

Calibration Cal(const FitAnalysis& analysis, const char* key) {
  return KeyCalibration(analysis.interval_data, key);
}

// The ejection fraction where the volumes are the cavity's, else the
// volumes under what they are of.
std::string VolumeCard(const FitAnalysis& analysis) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const EjectionFraction& sd = analysis.sd.ejection_fraction;
  const bool with_sd = analysis.sd.computed;
  std::ostringstream h;
  if (analysis.volume_surface == "cavity") {
    h << "<div>ejection fraction<b>" << Fixed(100 * ef.ratio, 1)
      << (with_sd ? PlusMinus(100 * sd.ratio, 1, Cal(analysis, "ratio")) : "")
      << (Measured(ef.ratio) ? " %" : "") << "</b>"
      << "EDV " << Fixed(ef.edv_ml, 1)
      << (with_sd ? PlusMinus(sd.edv_ml, 1, Cal(analysis, "edv_ml")) : "")
      << " ml, ESV " << Fixed(ef.esv_ml, 1)
      << (with_sd ? PlusMinus(sd.esv_ml, 1, Cal(analysis, "esv_ml")) : "")
      << (Measured(ef.esv_ml) ? " ml" : "") << "</div>";
  } else {
    h << "<div>" << VolumeName(analysis) << "<b>" << Fixed(ef.edv_ml, 1)
      << (with_sd ? PlusMinus(sd.edv_ml, 1, Cal(analysis, "edv_ml")) : "")
      << " ml</b>"
      << "at ED, " << Fixed(ef.esv_ml, 1)
      << (with_sd ? PlusMinus(sd.esv_ml, 1, Cal(analysis, "esv_ml")) : "")
      << " ml at ES: not the cavity, no ejection fraction</div>";
  }
  return h.str();
}

// A solid's mass, wall thickening and endocardial and epicardial motion.
std::string SolidCards(const FitAnalysis& a) {
  const size_t ed_frame = a.ejection_fraction.ed_frame;
  const size_t es_frame = a.ejection_fraction.es_frame;
  const ClinicalSummary& ed = a.clinical[ed_frame];
  const ClinicalSummary& es = a.clinical[es_frame];
  std::ostringstream h;
  h << "<div>LV mass at ED<b>" << Fixed(ed.lv_mass_g, 0)
    << PlusMinus(ClinicalSd(a, ed_frame, &ClinicalSummary::lv_mass_g), 0,
                 Cal(a, "lv_mass_g"))
    << " g</b>"
    << "myocardium " << Fixed(ed.myocardial_volume_ml, 0)
    << " ml at 1.05 g/ml</div>"
    << "<div>wall thickening at ES<b>" << Fixed(es.wall_thickening_percent, 1)
    << PlusMinus(
           ClinicalSd(a, es_frame, &ClinicalSummary::wall_thickening_percent),
           1, Cal(a, "wall_thickening_percent"))
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

}  // namespace

std::string KeyNumbersHtml(const SequenceFit& fit,
                           const FitAnalysis& analysis) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const StrainPeak gcs = PeakGcs(analysis.strain);
  const StrainPeak gls = PeakGls(analysis.strain);
  const ClinicalSummary& es = analysis.clinical[ef.es_frame];
  const size_t e = ef.es_frame;
  auto pm = [&](double ClinicalSummary::*field, int digits, const char* key) {
    return PlusMinus(ClinicalSd(analysis, e, field), digits, Cal(analysis, key),
                     ClinicalBias(analysis, e, field));
  };
  std::ostringstream h;
  h << "<div class=\"key\">" << VolumeCard(analysis);
  if (fit.config.Solid()) h << SolidCards(analysis);
  h << "<div>net twist at ES<b>"
    << WithUnit(
           es.net_twist_deg, 1,
           (pm(&ClinicalSummary::net_twist_deg, 1, "net_twist_deg") + "&deg;")
               .c_str())
    << "</b>"
    << (Measured(es.net_twist_deg)
            ? "apex " + Fixed(es.apex_rotation_deg, 1) + "&deg;, base " +
                  Fixed(es.base_rotation_deg, 1) + "&deg;"
            : "no tracked points at ES")
    << "</div><div>torsion at ES<b>"
    << WithUnit(
           es.torsion_deg_per_cm, 2,
           (pm(&ClinicalSummary::torsion_deg_per_cm, 2, "torsion_deg_per_cm") +
            "&deg;/cm")
               .c_str())
    << "</b>shear angle " << WithUnit(es.shear_angle_deg, 1, "&deg;")
    << "</div>"
    << "<div>radial contraction at ES<b>"
    << Fixed(es.radial_contraction_percent, 1)
    << pm(&ClinicalSummary::radial_contraction_percent, 1,
          "radial_contraction_percent")
    << " %</b>"
    << "mean over ten rings</div>"
    << "<div>longitudinal shortening at ES<b>"
    << Fixed(es.longitudinal_shortening_percent, 1)
    << pm(&ClinicalSummary::longitudinal_shortening_percent, 1,
          "longitudinal_shortening_percent")
    << " %</b>"
    << "apex to base-rim centroid</div>"
    << "<div>peak GCS<b>" << Fixed(gcs.percent, 1)
    << PlusMinus(StrainSd(analysis, gcs.frame, &GlobalStrain::gcs_percent), 1,
                 Cal(analysis, "peak_gcs_percent"),
                 StrainBias(analysis, gcs.frame, &GlobalStrain::gcs_percent))
    << " %</b>frame " << gcs.frame << ", circumferential</div>"
    << "<div>peak GLS<b>" << Fixed(gls.percent, 1)
    << PlusMinus(StrainSd(analysis, gls.frame, &GlobalStrain::gls_percent), 1,
                 Cal(analysis, "peak_gls_percent"),
                 StrainBias(analysis, gls.frame, &GlobalStrain::gls_percent))
    << " %</b>frame " << gls.frame << ", longitudinal</div></div>\n";
  return h.str();
}

}  // namespace pfdm
