// The case list of a cohort run (pfdm batch) and its split into shards.
#ifndef PFDM_BATCH_BATCH_MANIFEST_H_
#define PFDM_BATCH_BATCH_MANIFEST_H_

#include <string>
#include <vector>

namespace pfdm {

struct BatchCase {
  std::string name;      // Folder name under the output folder.
  std::string points;    // Resolved against the manifest's folder.
  std::string contours;  // Empty: the command's default.
  int line = 0;          // In the manifest, for messages.
};

// CSV with a header naming case and points, optionally contours (any order,
// other columns ignored).  Case names must be unique and plain folder names
// (letters, digits, '.', '_', '-', not starting with '.').  Throws
// InputError "PATH:LINE: ...".
std::vector<BatchCase> ReadManifest(const std::string& path);

// "i/n" with 0 <= i < n: this run takes every case whose row index r
// (0-based) has r % n == i, so n runs with i = 0..n-1 (a Slurm array's
// task ids) cover the manifest once.
struct Shard {
  int index = 0;
  int count = 1;
};
Shard ParseShard(const std::string& text);
std::vector<BatchCase> CasesOfShard(const std::vector<BatchCase>& cases,
                                    const Shard& shard);

}  // namespace pfdm

#endif  // PFDM_BATCH_BATCH_MANIFEST_H_
