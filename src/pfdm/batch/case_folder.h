// A case's folder under pfdm batch's output, DIR/<case>: whether it is
// pfdm's to write, and what state its files say the case is in.
#ifndef PFDM_BATCH_CASE_FOLDER_H_
#define PFDM_BATCH_CASE_FOLDER_H_

#include <string>

#include "pfdm/batch/batch_summary.h"

namespace pfdm {

// Why pfdm batch must not write into dir, or "" when it may: when dir is
// absent, an empty folder, or a folder holding kOutputMarker
// (io/fit_output.h) as a plain file, which pfdm leaves beside every fit.
// A link (to anything), a plain file, or a folder of files pfdm did not
// mark is refused: its files are someone else's.  One line naming dir.
std::string CaseFolderRefusal(const std::string& dir);

// Makes dir a case folder of pfdm's own: creates it if absent (its parent
// must exist) and leaves the marker in it.  Throws InputError naming dir,
// with the refusal for a folder that is not pfdm's.
void ClaimCaseFolder(const std::string& dir);

// The state of case `name` from its folder dir: refused (failed, with the
// refusal as its error), done (the numbers of its fit.json), failed (its
// error.txt, or a fit.json that cannot be read), or pending.  Files are
// read only if they are plain files, never through a link.
CaseSummary CaseStatus(const std::string& dir, const std::string& name);

}  // namespace pfdm

#endif  // PFDM_BATCH_CASE_FOLDER_H_
