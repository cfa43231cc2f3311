#include "pfdm/io/point_writer.h"

#include <sstream>

namespace pfdm {

std::string ToPointsCsv(const PointSequence& sequence) {
  std::ostringstream out;
  out.precision(17);
  out << "frame,id,x,y,z\n";
  for (const Frame& frame : sequence.frames) {
    for (const DataPoint& p : frame.points) {
      out << frame.index << ',' << p.id << ',' << p.position.x() << ','
          << p.position.y() << ',' << p.position.z() << '\n';
    }
  }
  return out.str();
}

}  // namespace pfdm
