/* A stop inside a run on one rank (LAMMPS's error->one) whose message reaches the user: LAMMPS
   2021 (20220106) writes it to stdout and its main() calls MPI_Abort without flushing, so that a
   redirected stdout lost it (only Open MPI's abort notice was left). Flushed here before the
   exception leaves; newer LAMMPS flushes too (a second flush is harmless). */

#ifndef BOUNCE_LAMMPS_STOP_H
#define BOUNCE_LAMMPS_STOP_H

#include <cstdio>
#include <stdexcept>
#include <string>

#include "error.h"
#include "lammps.h"

namespace bounce::lammps {

[[noreturn]] inline void stop_one(LAMMPS_NS::LAMMPS *lmp, const std::string &message)
{
  try {
    lmp->error->one(FLERR, message);
  } catch (...) {
    if (lmp->screen) std::fflush(lmp->screen);
    if (lmp->logfile) std::fflush(lmp->logfile);
    throw;
  }
  throw std::logic_error("error->one returned");  // it does not
}

}  // namespace bounce::lammps

#endif
