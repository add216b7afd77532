#pragma once
// `bounce fit --batch MANIFEST [--checkpoint DIR]` (docs/fitting.md): the experiments of a
// manifest fitted, their grids cut into blocks spread over the MPI ranks (one process
// without MPI), finished blocks kept in DIR so that a killed batch continues where it was.

#include <optional>
#include <string>

#include "bounce/core/record.hpp"

namespace bounce::cli {

struct BatchResult {
  Record record;        ///< {manifest, experiments: [fit Record with its name]}; rank 0's alone
  bool printer = true;  ///< this process prints (rank 0); the others exit 0, quietly
};

/// Runs the batch on every rank (MPI_Init / MPI_Finalize inside when built with MPI). Rank 0
/// raises the errors of every rank (InvalidArgument naming the manifest's key, ...; an error
/// met on another rank alone is raised by rank 0 as the same kind, with the same message);
/// the other ranks stay quiet and return with printer = false, so that mpirun's exit code is
/// rank 0's.
BatchResult run_batch(const std::string& manifest, const std::optional<std::string>& checkpoint, bool progress);

}  // namespace bounce::cli
