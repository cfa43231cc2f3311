// fit.json: the settings, model and numbers of one fit, the file whose
// presence marks a complete output set (io/fit_output.h).
#ifndef PFDM_IO_FIT_JSON_H_
#define PFDM_IO_FIT_JSON_H_

#include <string>

#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// Settings, model, gauge convention, per-frame errors, clinical summary and
// cavity volume; ejection fraction and regional wall motion.
std::string FitJson(const PointSequence& points, const SequenceFit& fit,
                    const FitOptions& options, const FitAnalysis& analysis);
std::string FitJson(const PointSequence& points, const SequenceFit& fit,
                    const FitOptions& options);

}  // namespace pfdm

#endif  // PFDM_IO_FIT_JSON_H_
