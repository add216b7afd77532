/* The mass of each owned atom's rigid body (0 for an atom in none), from a fix rigid's
   "body" and "masstotal", as pair granular takes it: pair_style bounce and fix wall/bounce
   use the body's mass as the grain's in m_eff. */

#ifndef BOUNCE_LAMMPS_RIGID_MASSES_H
#define BOUNCE_LAMMPS_RIGID_MASSES_H

#include "atom.h"
#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "memory.h"

namespace bounce::lammps {

/* Fills mass[0, nlocal) from `rigid`, growing mass (capacity nmax) to atom->nmax; `who` names
   the caller in the error, `name` the array for LAMMPS's memory accounting. */
inline void rigid_masses(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *rigid, double *&mass, int &nmax, const char *who,
                         const char *name)
{
  int unused = 0;
  const int *body = static_cast<const int *>(rigid->extract("body", unused));
  const double *mass_body = static_cast<const double *>(rigid->extract("masstotal", unused));
  if (!body || !mass_body) lmp->error->all(FLERR, "{}: fix {} gives no bodies' masses", who, rigid->style);
  if (lmp->atom->nmax > nmax) {
    lmp->memory->destroy(mass);
    nmax = lmp->atom->nmax;
    lmp->memory->create(mass, nmax, name);
  }
  for (int i = 0; i < lmp->atom->nlocal; i++) mass[i] = body[i] >= 0 ? mass_body[body[i]] : 0.0;
}

}  // namespace bounce::lammps

#endif
