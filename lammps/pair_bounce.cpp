/* pair_style bounce (docs/lammps.md). The loop follows LAMMPS's pair granular (GRANULAR
   package): a size neighbor list with history (FixNeighHistory keeps a touch flag and the
   contact's values), ghost velocities, forces and torques on both atoms, the virial, m_eff of
   fix rigid's bodies and fix freeze's atoms. What happens in a contact is bounce's: the normal
   force of the model's contact law, how long an adhesive contact holds, and BSHP96's tangential
   laws. Setup (init_style, init_one, cutoffs, mixing) is in pair_bounce_setup.cpp; restart
   files, single() and the rigid bodies' masses in pair_bounce_io.cpp. */

#include "pair_bounce.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include "bounce/models/dem_law.hpp"
#include "bounce/dem/contact.hpp"
#include "stop.h"
#include "type_laws.h"

using namespace LAMMPS_NS;

namespace {
const char *const dummy_id = "NEIGH_HISTORY_BOUNCE_DUMMY";
const char *const history_id = "NEIGH_HISTORY_BOUNCE";
}  // namespace

PairBounce::PairBounce(LAMMPS *instance) : Pair(instance), fix_history_(nullptr)
{
  single_enable = 1;
  nondefault_history_transfer = 1;
  restartinfo = 1;
  finitecutflag = 1;
  no_virial_fdotr_compute = 1;
  comm_forward = 1;  // the rigid bodies' masses
  // single(): the tangential force (x, y, z) and its magnitude [N].
  single_extra = 4;
  svector = new double[single_extra]();
  // compute pair bounce: krijt's energies, crack- and bulk-dissipated (on this rank, since the
  // pair style was defined), elastic and surface (stored in its contacts now); then what the
  // rolling, sliding and twisting springs dissipated, and their energy now [J].
  nextra = 8;
  pvector = new double[nextra]();
  // A placeholder for the history fix, replaced in init_style, so that the fix list keeps the
  // order of the input script (as pair granular does).
  modify->add_fix(std::string(dummy_id) + " all DUMMY");
}

PairBounce::~PairBounce()
{
  if (copymode) return;
  delete[] pvector;
  delete[] svector;
  if (fix_history_) modify->delete_fix(history_id);
  else modify->delete_fix(dummy_id);
  memory->destroy(mass_rigid_);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairBounce::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  laws_.assign((n + 1) * (n + 1), nullptr);
  dynamic_radius_.assign(n + 1, 0.0);
  frozen_radius_.assign(n + 1, 0.0);
}

const bounce::lammps::TypeLaw *PairBounce::entry(int itype, int jtype) const
{
  return laws_[itype * (atom->ntypes + 1) + jtype].get();
}

void PairBounce::set_law(int i, int j, std::shared_ptr<const bounce::lammps::TypeLaw> law)
{
  const int n = atom->ntypes;
  if (law->beyond) beyond_contact = 1;
  laws_[i * (n + 1) + j] = laws_[j * (n + 1) + i] = std::move(law);
}

// pair_style bounce [integration corrected | plain]
void PairBounce::settings(int narg, char **arg)
{
  corrected_ = true;
  if (narg == 0) return;
  if (narg > 2 && std::strcmp(arg[0], "integration") == 0)
    error->all(FLERR, "pair_style bounce: '{}' is invalid: expected nothing after integration corrected|plain", arg[2]);
  if (narg == 2 && std::strcmp(arg[0], "integration") == 0) {
    if (std::strcmp(arg[1], "corrected") == 0) return;
    if (std::strcmp(arg[1], "plain") == 0) {
      corrected_ = false;
      return;
    }
    error->all(FLERR, "pair_style bounce: integration = {} is invalid: expected corrected (default) or plain", arg[1]);
  }
  error->all(FLERR,
             "pair_style bounce: '{}' is invalid: expected nothing or integration corrected|plain (models and "
             "materials go in pair_coeff)",
             arg[0]);
}

// The history is that of pair (i, j); seen from j it is (j, i) (dem::Layout::reverse).
#if BOUNCE_LAMMPS_TYPED_TRANSFER
void PairBounce::transfer_history(double *source, double *target, int, int)
#else
void PairBounce::transfer_history(double *source, double *target)
#endif
{
  layout_.reverse(source, target);
}

// pair_coeff I J MODEL key value ...: the CLI's names without dashes (docs/lammps.md).
void PairBounce::coeff(int narg, char **arg)
{
  if (narg < 3) error->all(FLERR, "pair_coeff for pair_style bounce: I J MODEL key value ... (docs/lammps.md)");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  bounce::lammps::Coeffs coeffs;
  coeffs["model"] = arg[2];
  for (int k = 3; k < narg; k += 2) {
    if (k + 1 >= narg)
      error->all(FLERR, "pair_coeff {} {}: {} has no value (pairs of key value follow the model)", arg[0], arg[1],
                 arg[k]);
    if (coeffs.count(arg[k])) error->all(FLERR, "pair_coeff {} {}: {} is given twice", arg[0], arg[1], arg[k]);
    coeffs[arg[k]] = arg[k + 1];
  }
  // One atom type is one material: a pair of a type with itself takes no body 2 of its own.
  if (std::max(ilo, jlo) <= std::min(ihi, jhi)) {
    for (const char *key : {"material2", "E2", "nu2", "gamma2", "surface_energy2"})
      if (coeffs.count(key))
        error->all(FLERR,
                   "pair_coeff {} {}: {} = {} is invalid: expected none for a type with itself (one type, one "
                   "material; unlike types mix their materials, or take their own pair_coeff I J)",
                   arg[0], arg[1], key, coeffs[key]);
  }
  // After a restart written before passive became the default, a law naming no form keeps the
  // published one, as the file's own pair_coeff's do (pair_bounce_io.cpp).
  std::shared_ptr<const bounce::lammps::TypeLaw> law;
  bool kept = false;
  try {
    law = published_restart_ ? bounce::lammps::restart_type_law(coeffs, kept) : bounce::lammps::make_type_law(coeffs);
  } catch (const std::exception &e) {
    error->all(FLERR, "pair_coeff {} {} {}: {}", arg[0], arg[1], arg[2], e.what());
  }
  if (kept && comm->me == 0)
    error->warning(FLERR,
                   "pair_coeff {} {} names no asperity_form: after a restart written before passive became the "
                   "default, it keeps the published form (docs/lammps.md, Restarts)",
                   arg[0], arg[1]);
  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      set_law(i, j, law);
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "pair_coeff {} {}: no type pair I <= J in these ranges", arg[0], arg[1]);
}

void PairBounce::stop_one(const std::string &message)
{
  bounce::lammps::stop_one(lmp, message);
}

// The effective mass, as pair granular takes it: a rigid body's mass for its atoms, and the other
// atom's own where one is frozen.
double PairBounce::effective_mass(int i, int j) const
{
  const double *rmass = atom->rmass;
  double mi = rmass[i], mj = rmass[j];
  if (mass_rigid_) {
    if (mass_rigid_[i] > 0.0) mi = mass_rigid_[i];
    if (mass_rigid_[j] > 0.0) mj = mass_rigid_[j];
  }
  if (freeze_bit_) {
    if (atom->mask[i] & freeze_bit_) return mj;
    if (atom->mask[j] & freeze_bit_) return mi;
  }
  return mi * mj / (mi + mj);
}

// A contact whose step is a tenth of the explicit step's limit or more: a WARNING once per run
// and rank; at the limit (unstable) LAMMPS stops.
void PairBounce::report(const bounce::dem::ContactForce &c, const bounce::dem::Kinematics &k, int i, int j)
{
  const double dt = update->dt;
  if (c.check.stability >= 1.0)
    stop_one(fmt::format("pair_style bounce: the time step is too long for the contact of atoms {} and {} at overlap "
                         "{:.3g} m: the explicit step cannot integrate it (its energy grows each step); {} "
                         "(docs/lammps.md, Time step)",
                         atom->tag[i], atom->tag[j], k.overlap, c.check.describe(dt)));
  if (warned_) return;
  warned_ = true;
  error->warning(FLERR,
                 "pair_style bounce: the contact of atoms {} and {} at overlap {:.3g} m is coarse for the time step: {}; "
                 "bounce's laws need a tenth of that limit or less (COR to ~1e-4 at a period of 250 steps): use a "
                 "smaller time step (docs/lammps.md, Time step)",
                 atom->tag[i], atom->tag[j], k.overlap, c.check.describe(dt));
}

// The step of the contact of atoms i and j (touch and history: its neighbor-list entry's), by
// bounce::dem::step on the history's state. False where there is none (nothing to apply).
bool PairBounce::contact(int i, int j, int &touch, double *history, const bounce::dem::StepSettings &s,
                         bounce::dem::ContactForce &c, bounce::dem::Kinematics &k)
{
  double **x = atom->x;
  const double *radius = atom->radius;
  const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
  const double rsq = delx * delx + dely * dely + delz * delz;
  const double radsum = radius[i] + radius[j];
  // No contact, none before: its history is zero already (FixNeighHistory zeroes a new pair's,
  // and contact_step an ended contact's), and is left alone. A law whose contact forms before
  // touching (snap_overlap < 0) is asked where.
  const bounce::lammps::TypeLaw &type_law = *entry(atom->type[i], atom->type[j]);
  if (!touch && rsq >= radsum * radsum && !type_law.snaps) return false;
  const bounce::models::DemModel &law = type_law.law;
  const bounce::models::ContactGeometry g{radius[i] * radius[j] / radsum, effective_mass(i, j)};
  const double r = std::sqrt(rsq);
  if (!touch && type_law.snaps && !bounce::dem::within_reach(law, g, radsum - r)) return false;
  if (rsq == 0.0)
    stop_one(fmt::format("pair_style bounce: atoms {} and {} are at the same place (no contact normal)", atom->tag[i],
                         atom->tag[j]));
  double **v = atom->v, **omega = atom->omega;
  k = bounce::dem::pair_kinematics({x[i], v[i], omega[i], radius[i]}, {x[j], v[j], omega[j], radius[j]}, r);
  bounce::dem::ContactState state = layout_.read(touch != 0, history);
  c = bounce::dem::step(law, g, k, s, state);
  touch = state.touching;
  layout_.write(state, history);
  if (c.narrower_than_xi_crit > 0.0)
    stop_one(fmt::format("pair_style bounce: xi_crit = {:.6g} is invalid: expected xi_crit < a0 = {:.6g} m, the "
                         "contact radius of atoms {} and {} (R_eff = {:.6g} m): the rolling model holds for contacts "
                         "wider than its critical displacement (docs/resistance.md, Validity)",
                         law.resistance->xi_crit, c.narrower_than_xi_crit, atom->tag[i], atom->tag[j], g.effective_radius));
  if (!c.finite())
    stop_one(fmt::format("pair_style bounce: the force between atoms {} and {} is not finite (overlap {:.6g} m, rate "
                         "{:.6g} m/s, dt {:.6g} s): the time step is too large for this law, or an input extreme "
                         "(docs/lammps.md, Time step)",
                         atom->tag[i], atom->tag[j], k.overlap, -k.vn, s.dt));
  return true;
}

// The loop of pair granular; each contact's step is bounce::dem::step (the corrected or plain
// integration, docs/lammps.md).
void PairBounce::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (eflag) pvector[2] = pvector[3] = pvector[7] = 0.0;  // the stored energies; 0, 1, 4-6 accumulate
  if (fix_rigid_ && neighbor->ago == 0) update_rigid_masses();
  bounce::dem::StepSettings settings;
  settings.dt = update->dt;
  settings.update_history = !update->setupflag;
  settings.corrected = corrected_ && settings.update_history;  // setup: whole-step velocities
  int **firsttouch = fix_history_->firstflag;
  double **firsthistory = fix_history_->firstvalue;
  bounce::dem::ContactForce c;
  bounce::dem::Kinematics k;
  const int values = layout_.size();
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!contact(i, j, firsttouch[i][jj], &firsthistory[i][values * jj], settings, c, k)) continue;
      if (c.check.stability > bounce::dem::coarse_stability) report(c, k, i, j);
      apply(i, j, c, k, eflag);
    }
  }
}

// A contact's force and torque on atoms i and j (j only when it is owned or newton pair is on),
// its energies and its virial.
void PairBounce::apply(int i, int j, const bounce::dem::ContactForce &c, const bounce::dem::Kinematics &k, int eflag)
{
  double **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const bounce::dem::Loads l = bounce::dem::loads(c, k, radius[i], radius[j]);
  for (int d = 0; d < 3; d++) {
    f[i][d] += l.force[d];
    torque[i][d] += l.torque1[d];
  }
  if (newton_pair || j < nlocal) {
    for (int d = 0; d < 3; d++) {
      f[j][d] -= l.force[d];
      torque[j][d] += l.torque2[d];
    }
  }
  // A crack law's energies (krijt): the pair is computed twice, once on each side, when j is a
  // ghost atom and newton pair is off.
  const double share = newton_pair || j < nlocal ? 1.0 : 0.5;
  pvector[0] += share * c.crack_dissipated;
  pvector[1] += share * c.bulk_dissipated;
  pvector[4] += share * c.rolling_dissipated;
  pvector[5] += share * c.sliding_dissipated;
  pvector[6] += share * c.twisting_dissipated;
  if (eflag) {
    pvector[2] += share * c.elastic;
    pvector[3] += share * c.surface;
    pvector[7] += share * c.spring_energy;
  }
  if (evflag) {
    double **x = atom->x;
    ev_tally_xyz(i, j, nlocal, newton_pair, c.elastic + c.surface + c.spring_energy, 0.0, l.force[0], l.force[1], l.force[2],
                 x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]);
  }
}
