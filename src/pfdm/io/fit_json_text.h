// The definitions and conventions fit.json carries beside its numbers, so
// that the file says what each number means (fit_json.cc).
#ifndef PFDM_IO_FIT_JSON_TEXT_H_
#define PFDM_IO_FIT_JSON_TEXT_H_

namespace pfdm::fit_json_text {

inline constexpr char kGaugeConvention[] =
    "a0 (scale) is set on frame 0 so that the model, a3 = 0.8 there, spans "
    "the data from its fitted apex to the highest point along the axis, and "
    "is held afterwards; frame 0 fits the pose with tau = 0 and no bending, "
    "and with tags its spin about the long axis is pulled weakly (1e-3 a "
    "point) toward the start's, whose x axis is the data's widest direction "
    "across the axis, where a round section leaves it free, and where no "
    "data lie near the start's apex its apex is pulled as weakly toward the "
    "start's height along the axis; "
    "in every frame the axis is the least-squares line of the ring centres "
    "(offsets e1o, e2o with zero mean and zero linear trend over the knots; "
    "e3o = 0), so translation and tilt are the pose's; later frames fit the "
    "pose but not its spin about frame 0's long axis, so tau(u, t) is "
    "rotation about the LV axis relative to frame 0; bending has zero mean "
    "over every ring, so a ring's axial position is a3's and the pose's; b1 "
    "and b3 are shifted by multiples of 2 (negating b0 or b2 for odd ones, "
    "the same bend) until their knot means lie in [0, 2).";

inline constexpr char kEjectionDefinition[] =
    "(EDV - ESV) / EDV; ED is settings.ed_frame (--ed_frame, frame 0 unless "
    "given), ES the frame of least volume; the "
    "volumes are the frames' cavity_volume_ml, closed as cavity_closure "
    "says.  esv_ml and the ratio are null when a frame has no volume "
    "(not_measured.short_span).  Where frames have no cavity because "
    "nothing places their walls (not_measured.walls_unseen), ES is the "
    "frame of least volume inside the mid-wall, which their tags place "
    "(es_by_midwall true), and esv_ml and the ratio are null when it is "
    "one of them.";

inline constexpr char kVolumeFractionDefinition[] =
    "(V_ED - V_ES) / V_ED of the volume the fitted surface encloses, which "
    "is not the cavity (volume_surface says what it is: a surface through "
    "the middle of the wall encloses the cavity and about half the "
    "myocardium), so this is not the ejection fraction: fit tags through "
    "the wall or contours of both walls (--wall solid), or points of the "
    "endocardium (--surface endo), for that; ED is settings.ed_frame, ES the "
    "frame of least volume.";

inline constexpr char kLayersDefinition[] =
    "A solid's regions hold err_percent, the radial strain across the wall: "
    "the Green-Lagrange strain ((L / L0)^2 - 1) / 2 of the chord from each "
    "material point's endocardium (w = -1) to its epicardium (w = +1), "
    "area-weighted over the segment; and layers: for the endocardium, the "
    "mid-wall and the epicardium, ecc_percent and ell_percent, the surface "
    "w = -1, 0, +1's Green-Lagrange strains in its own tangent plane (as the "
    "mid-wall's), and thickening_percent, the thickening of the wall's inner, "
    "middle and outer third (w -1 to -1/3, -1/3 to 1/3, 1/3 to 1) along the "
    "mid-wall's normal.  Against the LV phantom's truth, tags through the "
    "wall (docs/report.md, "
    "Strain per layer): Ecc and Ell within about 3.5 points, Err within 10, "
    "a third's thickening only within 17; the thirds are null in frames "
    "without tracked points (contours place no layer inside the wall).  A "
    "mid-wall fit has no wall: no layers.";
inline constexpr char kWallDefinition[] =
    "A solid (model.wall): x(u, v, w) with w from -1 (endocardium) to +1 "
    "(epicardium), the layer w = 0 displaced along the ellipsoid normal n by "
    "w h / 2 + w^2 shift, the twist tau + w dtau / 2; tags get their w from "
    "their rank across the wall in every frame (docs/gauge.md, The wall).  "
    "cavity_volume_ml is inside the endocardium, myocardial_volume_ml "
    "between the walls (each closed as cavity_closure says), lv_mass_g at "
    "1.05 g/ml; endo_* and epi_* rotations and radial contraction are "
    "measured like the mid-wall's on each wall's rings in the same frame-0 "
    "short-axis planes; wall_thickness_mm is the endocardial-to-epicardial "
    "vector of a material point along the mid-wall's normal, the mean over "
    "the ten contraction rings, and wall_thickening_percent the mean of "
    "100 (T / T0 - 1) over them (per segment: regions' "
    "thickening_percent).";

inline constexpr char kQualityDefinition[] =
    "each frame's quality is the worst of its reasons' severities: ok (no "
    "reason), warning (a number may be off: read the reasons) or failed "
    "(the fit is implausible; pfdm exits 3). Reasons measure one thing "
    "against a stated bound: the solver's termination, closest points still "
    "moving, the RMS against the other frames and the data's size, the "
    "regularizer's share of the final cost, shape functions at their "
    "bounds, empty knot spans, a fit that never left its start, flat data, "
    "and the clinical numbers against what a heart in mm can have (volume, "
    "mass, the myocardium's volume, motion between frames, ejection "
    "fraction): docs/verdict.md";

inline constexpr char kRegionsConvention[] =
    "segments 1-17 as \"segments\" places them (anatomical or not), each "
    "with its name and its range of longitude v on frame 0's model; per "
    "frame, rotation_deg is the mean turn of the segment's material points "
    "about frame 0's long axis (about their ring's centroid) and "
    "radial_contraction_percent the mean of 1 - r / r(frame 0), r a "
    "material point's distance from its ring's centroid; null where not "
    "measured (segment 17 without data near the apex).";

inline constexpr char kStrainDefinition[] =
    "Lagrangian (Green-Lagrange) surface strain of the fitted model's "
    "material points against frame 0, percent: at each material point the "
    "surface deformation gradient F maps frame 0's tangent plane to frame "
    "t's, E = (F^T F - I) / 2 in frame 0's orthonormal basis e_c (along the "
    "circle of latitude, v increasing) and e_l (in the plane, perpendicular "
    "to e_c, apex to base): Ecc, Ell, Ecl.  Regions: area-weighted means "
    "over each segment (frame 0's area).  gcs_percent and gls_percent (per "
    "frame in clinical): area-weighted means of Ecc and Ell over the whole "
    "surface from the apex pole to the base rim; the peaks are the most "
    "negative over the frames; levels: the same means over each third.";

inline constexpr char kClinicalDefinition[] =
    "Measured on the fitted model's material points against frame 0's, "
    "whatever share of the motion the pose and the functions carry: "
    "apex_rotation_deg and base_rotation_deg, the mean turn about frame 0's "
    "long axis (right-handed, apex to base) of the material rings at 0.2 and "
    "0.85 of frame 0's length from the apex pole to the base rim; "
    "net_twist_deg = base - apex; torsion_deg_per_cm, net twist over frame "
    "0's distance between the two rings; shear_angle_deg, the "
    "circumferential-longitudinal shear angle atan(twist (r_apex + r_base) / "
    "(2 D)) on frame 0's geometry; radial_contraction_percent, the mean over "
    "ten rings (0.05 to 0.95 of the length) of 1 - r / r0, r the mean "
    "distance of a ring's material points from their centroid; "
    "longitudinal_shortening_percent, 1 - L / L0, L from the apex pole to the "
    "centroid of the base rim's material points.  The *_per_knot ratios are "
    "a1, a2, a3 against frame 0 (the paper's Fig. 5).";

}  // namespace pfdm::fit_json_text

#endif  // PFDM_IO_FIT_JSON_TEXT_H_
