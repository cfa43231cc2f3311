// Each frame's time from the trigger, as a points file's rows give it.
#ifndef PFDM_IO_FRAME_TIMES_H_
#define PFDM_IO_FRAME_TIMES_H_

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace pfdm {

// Collects a time_ms column row by row: every row of a frame gives the same
// time, from 0 ms, and later frames later times.  Each throws InputError
// naming the file and line.
class FrameTimes {
 public:
  // ms: the row's value, already read as a finite number.
  // "PATH:LINE: time_ms 40 differs from frame 1's 33 (line 5)",
  // "PATH:LINE: time_ms -3 is negative".
  void Add(const std::string& path, unsigned line, long long frame, double ms);

  // Per frame 0..F-1 (every frame the reader kept has rows here), or empty
  // when no row gave a time.  "PATH:LINE: frame 3's time_ms 120 is not after
  // frame 2's 150".
  std::vector<double> Times(const std::string& path) const;

 private:
  std::map<long long, std::pair<double, unsigned>> first_;  // ms, line.
};

}  // namespace pfdm

#endif  // PFDM_IO_FRAME_TIMES_H_
