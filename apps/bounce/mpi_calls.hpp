#pragma once
// The MPI calls of the CLI's sweeps (mpi.hpp), as a table: in a shared build the module
// lib/bounce/mpi.so (mpi_module.cpp) holds them and is opened only when an MPI launcher started
// the process, so that no other command loads Open MPI's libraries at start-up
// (docs/benchmarks.md); in a static build they are linked in.

#include <string>

namespace bounce::cli {

struct MpiCalls {
  bool (*start)(int& rank, int& size);  ///< MPI_Init unless done; true if this call did it
  void (*finish)();
  int (*min)(int value);
  long (*sum)(long value);
  void (*send)(const std::string& text, int tag);
  std::string (*receive)(int source, int tag);
  std::string (*allgather)(const std::string& mine, int size);
};

}  // namespace bounce::cli

/// The module's entry point, looked up by name.
extern "C" const bounce::cli::MpiCalls* bounce_mpi_calls();
