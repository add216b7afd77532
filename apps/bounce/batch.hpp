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
  bool printer = true;  ///< this process prints (rank 0)
  int exit_code = 0;    ///< the other ranks' exit code when the batch failed (rank 0 raised)
};

/// Runs the batch on every rank (MPI_Init / MPI_Finalize inside when built with MPI). Rank 0
/// raises the errors of every command (InvalidArgument naming the manifest's key, ...; an
/// error met on another rank alone as a NumericalError quoting it); the other ranks stay
/// quiet and return with printer = false and the exit code.
BatchResult run_batch(const std::string& manifest, const std::optional<std::string>& checkpoint, bool progress);

}  // namespace bounce::cli
