#include "pfdm/io/point_writer.h"

#include <sstream>

namespace pfdm {
namespace {

const char* SurfaceWord(WallLayer layer) {
  return layer == WallLayer::kEndocardium  ? "endo"
         : layer == WallLayer::kEpicardium ? "epi"
                                           : "";
}

}  // namespace

std::string ToPointsCsv(const PointSequence& sequence) {
  bool labelled = false;
  for (const Frame& frame : sequence.frames) {
    for (const DataPoint& p : frame.points) {
      labelled = labelled || p.layer != WallLayer::kAnywhere;
    }
  }
  const bool timed = sequence.time_ms.size() == sequence.frames.size() &&
                     !sequence.frames.empty();
  std::ostringstream out;
  out.precision(17);
  out << "frame,id,x,y,z" << (timed ? ",time_ms" : "")
      << (labelled ? ",surface" : "") << '\n';
  for (const Frame& frame : sequence.frames) {
    for (const DataPoint& p : frame.points) {
      out << frame.index << ',' << p.id << ',' << p.position.x() << ','
          << p.position.y() << ',' << p.position.z();
      if (timed) out << ',' << sequence.time_ms[frame.index];
      if (labelled) out << ',' << SurfaceWord(p.layer);
      out << '\n';
    }
  }
  return out.str();
}

}  // namespace pfdm
