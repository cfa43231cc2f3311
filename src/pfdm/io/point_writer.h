// Writes points in the CSV that ReadPointsCsv reads.
#ifndef PFDM_IO_POINT_WRITER_H_
#define PFDM_IO_POINT_WRITER_H_

#include <string>

#include "pfdm/util/point_data.h"

namespace pfdm {

// Header frame,id,x,y,z, then time_ms when the sequence has times and
// surface (endo, epi or empty) when a point names its wall; numbers with
// enough digits to round-trip.
std::string ToPointsCsv(const PointSequence& sequence);

}  // namespace pfdm

#endif  // PFDM_IO_POINT_WRITER_H_
