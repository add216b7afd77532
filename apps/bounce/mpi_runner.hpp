#pragma once
// The atlas build over MPI ranks (docs/atlas.md, "MPI"): each batch of independent jobs is split
// round-robin among the ranks (each on its threads), and every rank then receives every rank's
// results, so all take the same next step. Without MPI (or on one rank) the jobs run on threads.

#include <memory>

#include "bounce/analysis/atlas.hpp"

namespace bounce::cli {

class MpiRunner {
 public:
  MpiRunner();
  ~MpiRunner();
  MpiRunner(const MpiRunner&) = delete;
  MpiRunner& operator=(const MpiRunner&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// The runner for build_atlas: rank 0 keeps the cache file.
  analysis::AtlasRunner runner(unsigned threads) const;

 private:
  struct Shared;
  std::shared_ptr<Shared> shared_;  // the MPI session and a job's error, shared with the runner's functions
  int rank_ = 0, size_ = 1;
};

}  // namespace bounce::cli
