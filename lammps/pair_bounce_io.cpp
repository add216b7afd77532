/* pair_style bounce (docs/lammps.md): what it writes to a restart file and reads back (the
   integration setting and every pair_coeff as typed; the contacts' history is FixNeighHistory's,
   per atom), single() for computes that ask for one pair's force (compute pair/local, compute
   fabric), and fix rigid's bodies' masses, which ghost atoms get by forward communication. */

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_neigh_history.h"
#include "memory.h"
#include "neigh_list.h"
#include "pair_bounce.h"
#include "update.h"
#include "utils.h"

#include "bounce/dem/contact.hpp"
#include "rigid_masses.h"
#include "type_laws.h"

using namespace LAMMPS_NS;

void PairBounce::write_restart_settings(FILE *fp)
{
  const int corrected = corrected_ ? 1 : 0;
  fwrite(&corrected, sizeof(int), 1, fp);
}

void PairBounce::read_restart_settings(FILE *fp)
{
  int corrected = 1;
  if (comm->me == 0) utils::sfread(FLERR, &corrected, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&corrected, 1, MPI_INT, 0, world);
  corrected_ = corrected != 0;
}

// Per type pair I <= J: setflag, and for a pair_coeff's its coefficients as text (type_laws.h);
// the mixed pairs are mixed again at the next run.
void PairBounce::write_restart(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) {
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      const std::string text = bounce::lammps::to_text(entry(i, j)->coeffs);
      const int length = static_cast<int>(text.size());
      fwrite(&length, sizeof(int), 1, fp);
      fwrite(text.data(), 1, text.size(), fp);
    }
  }
}

void PairBounce::read_restart(FILE *fp)
{
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++) {
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      int length = 0;
      if (me == 0) utils::sfread(FLERR, &length, sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&length, 1, MPI_INT, 0, world);
      std::vector<char> text(length);
      if (me == 0) utils::sfread(FLERR, text.data(), 1, length, fp, nullptr, error);
      MPI_Bcast(text.data(), length, MPI_CHAR, 0, world);
      bool kept = false;
      try {
        set_law(i, j, bounce::lammps::restart_type_law(bounce::lammps::from_text(std::string(text.begin(), text.end())),
                                                        kept));
      } catch (const std::exception &e) {
        error->all(FLERR, "pair_style bounce: the restart file's pair_coeff {} {}: {}", i, j, e.what());
      }
      if (kept && comm->me == 0)
        error->warning(FLERR,
                       "pair_style bounce: the restart file's pair_coeff {} {} names no asperity_form: written before "
                       "passive became the default, it keeps the published form its contacts' springs hold "
                       "(docs/lammps.md, Restarts)",
                       i, j);
      published_restart_ = published_restart_ || kept;
    }
  }
}

namespace {

// The position of j in i's neighbor list, searched from where the last search ended (computes ask
// for the pairs in the list's order); -1 if it is not there.
int find_neighbor(const NeighList *list, int i, int j, int &from)
{
  const int count = list->numneigh[i];
  const int *neighbors = list->firstneigh[i];
  for (int n = 0; n < count; n++) {
    from = from + 1 < count ? from + 1 : 0;
    if ((neighbors[from] & NEIGHMASK) == j) return from;
  }
  return -1;
}

}  // namespace

// The force between atoms i and j as compute() has it now, without changing the contact's history:
// fforce = F_n / r along the line of centres; svector the tangential force (x, y, z, magnitude)
// [N]; the energy stored in the contact (krijt's), 0 for the other laws.
double PairBounce::single(int i, int j, int, int, double, double, double factor_lj, double &fforce)
{
  fforce = 0.0;
  for (int m = 0; m < single_extra; m++) svector[m] = 0.0;
  if (factor_lj == 0.0) return 0.0;
  if (i >= atom->nlocal + atom->nghost || j >= atom->nlocal + atom->nghost)
    stop_one("pair_style bounce: single() of atoms not on this rank");
  // The contact's history, a copy: from i's list, or turned round from j's (a half list has the
  // pair once).
  int touch = 0;
  double history[bounce::dem::Layout::largest] = {};
  if (fix_history_ && fix_history_->firstvalue && list) {
    int from = single_neighbor_;
    if (const int n = find_neighbor(list, i, j, from); n >= 0) {
      touch = fix_history_->firstflag[i][n];
      std::copy_n(&fix_history_->firstvalue[i][layout_.size() * n], layout_.size(), history);
    } else if (j < atom->nlocal) {
      from = 0;
      if (const int m = find_neighbor(list, j, i, from); m >= 0) {
        touch = fix_history_->firstflag[j][m];
#if BOUNCE_LAMMPS_TYPED_TRANSFER
        transfer_history(&fix_history_->firstvalue[j][layout_.size() * m], history, 0, 0);
#else
        transfer_history(&fix_history_->firstvalue[j][layout_.size() * m], history);
#endif
      }
    }
    single_neighbor_ = from;
  }
  bounce::dem::StepSettings s{update->dt, false, corrected_};
  bounce::dem::ContactForce c;
  bounce::dem::Kinematics k;
  if (!contact(i, j, touch, history, s, c, k)) return 0.0;
  fforce = c.normal / (atom->radius[i] + atom->radius[j] - k.overlap);
  for (int d = 0; d < 3; d++) svector[d] = c.tangential[d];
  svector[3] = std::sqrt(c.tangential[0] * c.tangential[0] + c.tangential[1] * c.tangential[1] +
                         c.tangential[2] * c.tangential[2]);
  return c.elastic + c.surface + c.spring_energy;
}

// Each atom's rigid body's mass (0 if none), owned and ghost atoms, refreshed where the atoms
// were exchanged (as pair granular).
void PairBounce::update_rigid_masses()
{
  bounce::lammps::rigid_masses(lmp, fix_rigid_, mass_rigid_, nmax_rigid_, "pair_style bounce", "pair:mass_rigid");
#if BOUNCE_LAMMPS_FORWARD_COMM
  comm->forward_comm(this);
#else
  comm->forward_comm_pair(this);
#endif
}

int PairBounce::pack_forward_comm(int n, int *list_, double *buf, int, int *)
{
  for (int k = 0; k < n; k++) buf[k] = mass_rigid_[list_[k]];
  return n;
}

void PairBounce::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) mass_rigid_[first + k] = buf[k];
}

double PairBounce::memory_usage()
{
  return Pair::memory_usage() + static_cast<double>(nmax_rigid_) * sizeof(double);
}
