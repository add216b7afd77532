/* pair_style bounce's setup for a run (docs/lammps.md): the neighbor list with history, the
   cutoffs from the largest radii (as pair granular: present atoms, fix pour's and fix deposit's
   coming ones, frozen ones), the laws of unlike types mixed by bounce's rule, fix rigid's and fix
   freeze's masses. */

#include <algorithm>
#include <cstring>
#include <exception>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_neigh_history.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair_bounce.h"
#include "update.h"
#include "utils.h"
#if !BOUNCE_LAMMPS_ADD_REQUEST
#include "neigh_request.h"
#endif

#include "bounce/dem/state.hpp"
#include "type_laws.h"

using namespace LAMMPS_NS;

namespace {
const char *const dummy_id = "NEIGH_HISTORY_BOUNCE_DUMMY";
const char *const history_id = "NEIGH_HISTORY_BOUNCE";
}  // namespace

void PairBounce::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "pair_style bounce needs atom_style sphere (radius, rmass, omega, torque)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "pair_style bounce needs ghost atoms' velocities: comm_modify vel yes");
  if (std::strcmp(update->unit_style, "si") != 0)
    error->all(FLERR, "pair_style bounce needs units si (bounce's laws are in SI units), not units {}",
               update->unit_style);
  if (!utils::strmatch(update->integrate_style, "^verlet"))
    error->all(FLERR, "pair_style bounce needs run_style verlet (its corrected integration is velocity Verlet's)");
  warned_ = false;

  // A size neighbor list with history: the touch flag keeps adhesive contacts beyond
  // r = R_i + R_j; the values are the contact's state (bounce::dem::Layout).
#if BOUNCE_LAMMPS_ADD_REQUEST
  neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_HISTORY);
#else
  const int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->size = 1;
  neighbor->requests[irequest]->history = 1;
#endif
  // Each contact keeps the states of the sub-models its laws use (the fix's size is set once, at
  // the first run).
  bounce::dem::Layout layout;
  for (const auto &law : laws_)
    if (law) layout.add(law->law);
  if (fix_history_ == nullptr) {
    layout_ = layout;
    fix_history_ = dynamic_cast<FixNeighHistory *>(modify->replace_fix(
        dummy_id, std::string(history_id) + " all NEIGH_HISTORY " + std::to_string(layout_.size()), 1));
    fix_history_->pair = this;
  } else if (layout.size() > layout_.size()) {
    error->all(FLERR, "pair_style bounce: a pair_coeff after the first run needs a state its contacts do not keep "
                      "(krijt's crack): give it before the first run");
  }
  find_rigid_and_frozen();
  find_radii();
}

// fix rigid's bodies (m_eff takes their masses) and fix freeze's group (m_eff the other atom's).
void PairBounce::find_rigid_and_frozen()
{
  fix_rigid_ = nullptr;
  freeze_bit_ = 0;
  for (int k = 0; k < modify->nfix; k++) {
    Fix *fix = modify->fix[k];
    if (fix->rigid_flag) {
      if (fix_rigid_) error->all(FLERR, "pair_style bounce: only one fix rigid at a time (its bodies' masses are m_eff's)");
      fix_rigid_ = fix;
    }
    if (utils::strmatch(fix->style, "^freeze")) {
      if (freeze_bit_) error->all(FLERR, "pair_style bounce: only one fix freeze at a time");
      freeze_bit_ = fix->groupbit;
    }
  }
  if (!fix_rigid_) {
    memory->destroy(mass_rigid_);
    mass_rigid_ = nullptr;
    nmax_rigid_ = 0;
  }
}

// The largest radius of each type, of dynamic and of frozen atoms; the dynamic ones include the
// atoms fix pour and fix deposit will insert (pair granular's rule: an empty box that a pour
// fills gets its cutoff from the pour).
void PairBounce::find_radii()
{
  const int n = atom->ntypes;
  std::vector<double> dynamic(n + 1, 0.0), frozen(n + 1, 0.0);
  for (int k = 0; k < modify->nfix; k++) {
    Fix *fix = modify->fix[k];
    if (!utils::strmatch(fix->style, "^pour") && !utils::strmatch(fix->style, "^deposit")) continue;
    for (int t = 1; t <= n; t++) {
      int itype = t;
      const auto *r = static_cast<const double *>(fix->extract("radius", itype));
      if (r && *r > 0.0) dynamic[t] = std::max(dynamic[t], *r);
    }
  }
  for (int i = 0; i < atom->nlocal; i++) {
    double &largest = (atom->mask[i] & freeze_bit_) ? frozen[atom->type[i]] : dynamic[atom->type[i]];
    largest = std::max(largest, atom->radius[i]);
  }
  MPI_Allreduce(dynamic.data(), dynamic_radius_.data(), n + 1, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(frozen.data(), frozen_radius_.data(), n + 1, MPI_DOUBLE, MPI_MAX, world);
}

// How far beyond r = R_i + R_j a contact of these radii holds: -release_overlap (JKR's neck).
double PairBounce::reach(int itype, int jtype, double radius_i, double radius_j) const
{
  const bounce::lammps::TypeLaw *l = entry(itype, jtype);
  if (!l || radius_i <= 0.0 || radius_j <= 0.0) return 0.0;
  const bounce::models::ContactGeometry g{radius_i * radius_j / (radius_i + radius_j), 0.0};
  return -l->law.release_overlap(g);
}

// Contacts reach R_i + R_j, and adhesive ones beyond it down to their release overlap, between
// dynamic atoms and between a dynamic and a frozen one (two frozen atoms never meet); where no
// radius of one type is known yet, the largest 2R of any type (as pair granular).
double PairBounce::cutoff(int i, int j) const
{
  const std::vector<double> &d = dynamic_radius_, &f = frozen_radius_;
  if ((d[i] > 0.0 && d[j] > 0.0) || (d[i] > 0.0 && f[j] > 0.0) || (f[i] > 0.0 && d[j] > 0.0)) {
    double cut = 0.0;
    for (const auto &[ri, rj] : {std::pair{d[i], d[j]}, std::pair{f[i], d[j]}, std::pair{d[i], f[j]}}) {
      if (ri <= 0.0 || rj <= 0.0) continue;
      const double beyond = reach(i, j, ri, rj);
      if (beyond > 0.0 && beyond >= neighbor->skin)
        error->all(FLERR,
                   "pair_style bounce: types {} {} stay in contact up to {:.3g} m beyond touching (the adhesive neck), "
                   "more than the neighbor skin {:.3g} m: use a larger skin (neighbor SKIN bin)",
                   i, j, beyond, neighbor->skin);
      cut = std::max(cut, ri + rj + beyond);
    }
    return cut;
  }
  double largest = 0.0;
  for (int k = 1; k <= atom->ntypes; k++) largest = std::max({largest, 2.0 * d[k], 2.0 * f[k]});
  return largest;
}

double PairBounce::init_one(int i, int j)
{
  if (setflag[i][j] == 0) {
    const bounce::lammps::TypeLaw *ii = entry(i, i), *jj = entry(j, j);
    if (!ii || !jj)
      error->all(FLERR, "pair_style bounce: no pair_coeff for types {} {}, nor for {} {} and {} {} to mix", i, j,
                 i, i, j, j);
    try {
      set_law(i, j, bounce::lammps::mix(*ii, *jj, i, j));
    } catch (const bounce::lammps::CannotMix &e) {
      error->all(FLERR, "pair_style bounce: {}", e.what());
    } catch (const std::exception &e) {
      error->all(FLERR, "pair_style bounce: types {} and {} mixed: {}", i, j, e.what());
    }
  }
  return cutoff(i, j);
}
