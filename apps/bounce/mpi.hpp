#pragma once
// MPI for the CLI's long sweeps (`fit --batch`, `atlas build`): initialised only when an MPI
// launcher started the process, a no-op otherwise (one rank).

#include <cstdlib>
#include <string>
#include <vector>

#ifdef BOUNCE_HAVE_MPI
#include <mpi.h>
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
#endif

struct Mpi {
  int rank = 0, size = 1;
#ifdef BOUNCE_HAVE_MPI
  bool started = false, active = false;
  // A plain `bounce fit --batch` is one rank without MPI: a singleton MPI_Init starts Open MPI's
  // orted for nothing, and its allocations are reported as leaks under LeakSanitizer.
  Mpi() {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised && !launched_by_mpi()) return;
    if (!initialised) {
      MPI_Init(nullptr, nullptr);
      started = true;
    }
    active = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
  }
  ~Mpi() {
    if (started) MPI_Finalize();
  }
  int min(int value) const {
    if (!active) return value;
    int out = 0;
    MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return out;
  }
  long sum(long value) const {
    if (!active) return value;
    long out = 0;
    MPI_Allreduce(&value, &out, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    return out;
  }
  void send(const std::string& text, int tag) const {
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, tag, MPI_COMM_WORLD);
  }
  std::string receive(int source, int tag) const {
    MPI_Status status;
    MPI_Probe(source, tag, MPI_COMM_WORLD, &status);
    int n = 0;
    MPI_Get_count(&status, MPI_CHAR, &n);
    std::string text(static_cast<std::size_t>(n), '\0');
    MPI_Recv(text.data(), n, MPI_CHAR, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return text;
  }
  /// Every rank's text, concatenated in rank order, on every rank.
  std::string allgather(const std::string& mine) const {
    if (!active) return mine;
    const int n = static_cast<int>(mine.size());
    std::vector<int> counts(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
    MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (std::size_t i = 0; i < counts.size(); ++i) {
      offsets[i] = total;
      total += counts[i];
    }
    std::string all(static_cast<std::size_t>(total), '\0');
    MPI_Allgatherv(mine.data(), n, MPI_CHAR, all.data(), counts.data(), offsets.data(), MPI_CHAR, MPI_COMM_WORLD);
    return all;
  }
#else
  int min(int value) const { return value; }
  std::string allgather(const std::string& mine) const { return mine; }
  long sum(long value) const { return value; }
#endif
  Mpi(const Mpi&) = delete;
  Mpi& operator=(const Mpi&) = delete;
};

}  // namespace bounce::cli
