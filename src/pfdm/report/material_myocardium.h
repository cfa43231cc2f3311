// The myocardium as material: the volume of a solid's wall between two
// material rings, which an incompressible myocardium keeps (issue 32).
#ifndef PFDM_REPORT_MATERIAL_MYOCARDIUM_H_
#define PFDM_REPORT_MATERIAL_MYOCARDIUM_H_

#include "pfdm/model/model.h"

namespace pfdm {

// Volume (ml) of the solid's material with u_low <= u <= u_high, every v
// and -1 <= w <= 1: the closed surface of the endocardium, the epicardium
// and the two transmural strips at u_low and u_high, triangulated (48 steps
// of u, 72 of v, 8 of w) and summed by the divergence theorem.  Unlike the
// myocardium closed by a base plane (epicardial minus endocardial volume)
// it holds the same material points in every frame, so its change is the
// myocardium's compression; it ignores the orientation the model gives the
// surface.  u_low == u_min closes the strip at the apex pole to a line.
double MaterialMyocardiumMl(const Model& model, double u_low, double u_high);

}  // namespace pfdm

#endif  // PFDM_REPORT_MATERIAL_MYOCARDIUM_H_
