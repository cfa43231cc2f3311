#include "pfdm/report/number_sd.h"

namespace pfdm {

std::vector<double*> ClinicalFields(ClinicalSummary* c) {
  return {&c->apex_rotation_deg,
          &c->base_rotation_deg,
          &c->net_twist_deg,
          &c->torsion_deg_per_cm,
          &c->shear_angle_deg,
          &c->radial_contraction_percent,
          &c->longitudinal_shortening_percent,
          &c->volume_ml,
          &c->endo_apex_rotation_deg,
          &c->endo_base_rotation_deg,
          &c->endo_net_twist_deg,
          &c->epi_apex_rotation_deg,
          &c->epi_base_rotation_deg,
          &c->epi_net_twist_deg,
          &c->endo_radial_contraction_percent,
          &c->epi_radial_contraction_percent,
          &c->wall_thickness_mm,
          &c->wall_thickening_percent,
          &c->myocardial_volume_ml,
          &c->lv_mass_g};
}

std::vector<double*> RegionFields(RegionMotion* m) {
  return {&m->rotation_deg, &m->radial_contraction_percent,
          &m->ecc_percent,  &m->ell_percent,
          &m->ecl_percent,  &m->thickening_percent};
}

std::vector<double*> StrainFields(GlobalStrain* s) {
  return {&s->gcs_percent,          &s->gls_percent,
          &s->gcl_percent,          &s->level_ecc_percent[0],
          &s->level_ecc_percent[1], &s->level_ecc_percent[2],
          &s->level_ell_percent[0], &s->level_ell_percent[1],
          &s->level_ell_percent[2]};
}

const std::vector<std::string>& ClinicalFieldNames() {
  static const std::vector<std::string> names = {
      "apex_rotation_deg",
      "base_rotation_deg",
      "net_twist_deg",
      "torsion_deg_per_cm",
      "shear_angle_deg",
      "radial_contraction_percent",
      "longitudinal_shortening_percent",
      "volume_ml",
      "endo_apex_rotation_deg",
      "endo_base_rotation_deg",
      "endo_net_twist_deg",
      "epi_apex_rotation_deg",
      "epi_base_rotation_deg",
      "epi_net_twist_deg",
      "endo_radial_contraction_percent",
      "epi_radial_contraction_percent",
      "wall_thickness_mm",
      "wall_thickening_percent",
      "myocardial_volume_ml",
      "lv_mass_g"};
  return names;
}

const std::vector<std::string>& RegionFieldNames() {
  static const std::vector<std::string> names = {
      "rotation_deg", "radial_contraction_percent",
      "ecc_percent",  "ell_percent",
      "ecl_percent",  "thickening_percent"};
  return names;
}

const std::vector<std::string>& StrainFieldNames() {
  static const std::vector<std::string> names = {
      "gcs_percent",       "gls_percent",     "gcl_percent",
      "basal_ecc_percent", "mid_ecc_percent", "apical_ecc_percent",
      "basal_ell_percent", "mid_ell_percent", "apical_ell_percent"};
  return names;
}

}  // namespace pfdm
