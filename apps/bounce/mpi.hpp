#pragma once
// MPI for the CLI's long sweeps (`fit --batch`, `atlas build`): started only when an MPI
// launcher started the process, a no-op otherwise (one rank). The calls are mpi_calls.hpp's.

#include <cstdlib>
#include <string>

#ifdef BOUNCE_HAVE_MPI
#include "mpi_calls.hpp"
#ifdef BOUNCE_MPI_MODULE
#include "bounce/core/module.hpp"
#endif
#endif

namespace bounce::cli {

#ifdef BOUNCE_HAVE_MPI
// Whether an MPI launcher (mpirun/mpiexec of Open MPI, MPICH, PMIx) started this process.
inline bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

inline const MpiCalls& mpi_calls() {
#ifdef BOUNCE_MPI_MODULE
  static const MpiCalls* calls = module_table<MpiCalls>("mpi.so", "bounce_mpi_calls");
#else
  static const MpiCalls* calls = bounce_mpi_calls();
#endif
  return *calls;
}
#endif

struct Mpi {
  int rank = 0, size = 1;
#ifdef BOUNCE_HAVE_MPI
  bool started = false, active = false;
  // A plain `bounce fit --batch` is one rank without MPI: a singleton MPI_Init starts Open MPI's
  // orted for nothing, and its allocations are reported as leaks under LeakSanitizer.
  Mpi() {
    if (!launched_by_mpi()) return;
    started = mpi_calls().start(rank, size);
    active = true;
  }
  ~Mpi() {
    if (started) mpi_calls().finish();
  }
  int min(int value) const { return active ? mpi_calls().min(value) : value; }
  long sum(long value) const { return active ? mpi_calls().sum(value) : value; }
  void send(const std::string& text, int tag) const { mpi_calls().send(text, tag); }
  std::string receive(int source, int tag) const { return mpi_calls().receive(source, tag); }
  /// Every rank's text, concatenated in rank order, on every rank.
  std::string allgather(const std::string& mine) const { return active ? mpi_calls().allgather(mine, size) : mine; }
#else
  Mpi() = default;
  int min(int value) const { return value; }
  std::string allgather(const std::string& mine) const { return mine; }
  long sum(long value) const { return value; }
#endif
  Mpi(const Mpi&) = delete;
  Mpi& operator=(const Mpi&) = delete;
};

}  // namespace bounce::cli
