// Where the RV insertion comes from: --rv_insertion x,y,z[,x,y,z] (anterior,
// inferior; for points.csv and meshes, which do not carry it) or the
// RV_INSERT points of biv-me guide points' frame 0.
#ifndef PFDM_IO_RV_INSERTION_SOURCE_H_
#define PFDM_IO_RV_INSERTION_SOURCE_H_

#include <optional>
#include <string>

#include "pfdm/report/rv_insertion.h"

namespace pfdm {

// The flag's text as an insertion (source "--rv_insertion"): 3 numbers (the
// anterior insertion) or 6 (anterior, then inferior), mm, frame 0's world
// coordinates.  nullopt for an empty text; throws InputError naming the
// flag otherwise.
std::optional<RvInsertion> ParseRvInsertion(const std::string& text);

// The flag's insertion when given; else frame 0's RV_INSERT points of the
// guide points at `points` (a folder of GPFile_*.txt or one GPFile*),
// unlabelled, source "RV_INSERT points (frame 0's GPFile_000.txt)";
// nullopt when they have none or are not guide points.
std::optional<RvInsertion> RvInsertionFrom(const std::string& flag_text,
                                           const std::string& points);

}  // namespace pfdm

#endif  // PFDM_IO_RV_INSERTION_SOURCE_H_
