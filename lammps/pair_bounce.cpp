/* pair_style bounce (docs/lammps.md). The loop follows LAMMPS's pair granular (GRANULAR
   package): a size neighbor list with history (FixNeighHistory keeps a touch flag and three
   numbers per contact), ghost velocities, forces and torques on both atoms, the virial. What
   happens in a contact is bounce's: the normal force of the model's contact law, how long an
   adhesive contact holds, and BSHP96's tangential laws. */

#include "pair_bounce.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"
#if !BOUNCE_LAMMPS_ADD_REQUEST
#include "neigh_request.h"
#endif

#include "bounce/api/front_door.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/contact_law.hpp"

using namespace LAMMPS_NS;

namespace {
// Per contact: the tangential spring (models::tangential_step), then the last normal force.
constexpr int history_size = 4;
constexpr int last_force = 3;
// The force at the ends of a contact is taken this fraction of the step's overlap inside it:
// the limit there (viscoelastic-shifted jumps to C0 (A xi')^{3/2} at first touch; JKR to its
// snap-on force), finite where a law is singular at xi = 0 (adhesive-viscoelastic's xi^{-1/4}).
constexpr double inside = 1e-6;
const char *const dummy_id = "NEIGH_HISTORY_BOUNCE_DUMMY";
const char *const history_id = "NEIGH_HISTORY_BOUNCE";
// The normal force of a contact law (positive: repulsive); under the `force` end rule it is
// never attractive (the contact has ended where it first vanished).
double normal_force(const bounce::models::DemModel &law, const bounce::models::ContactGeometry &g, double overlap,
                    double rate)
{
  const double f = law.normal->force(g, overlap, rate);
  return law.end_rule == bounce::models::EndRule::force && f < 0.0 ? 0.0 : f;
}
}  // namespace

// The law of one type pair, and what the user typed for it (types I I and J J with the same
// inputs give I J the same law).
struct PairBounce::TypePair {
  bounce::models::DemModel law;
  std::string inputs;
};

PairBounce::PairBounce(LAMMPS *instance) : Pair(instance), fix_history_(nullptr)
{
  single_enable = 0;
  nondefault_history_transfer = 1;
  restartinfo = 0;
  no_virial_fdotr_compute = 1;
  // A placeholder for the history fix, replaced in init_style, so that the fix list keeps the
  // order of the input script (as pair granular does).
  fix_dummy_ = dynamic_cast<FixDummy *>(modify->add_fix(std::string(dummy_id) + " all DUMMY"));
}

PairBounce::~PairBounce()
{
  if (copymode) return;
  if (fix_history_) modify->delete_fix(history_id);
  else modify->delete_fix(dummy_id);
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
  max_radius_.assign(n + 1, 0.0);
}

// pair_style bounce [integration corrected | plain]
void PairBounce::settings(int narg, char **arg)
{
  corrected_ = true;
  if (narg == 0) return;
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

// The history is that of pair (i, j); seen from j it is (j, i): the spring turns round, the
// normal force does not.
void PairBounce::transfer_history(double *source, double *target)
{
  for (int k = 0; k < last_force; k++) target[k] = -source[k];
  target[last_force] = source[last_force];
}

// pair_coeff I J MODEL key value ...: the CLI's names without dashes (docs/lammps.md).
void PairBounce::coeff(int narg, char **arg)
{
  if (narg < 3) error->all(FLERR, "pair_coeff for pair_style bounce: I J MODEL key value ... (docs/lammps.md)");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  bounce::api::Inputs inputs;
  std::string typed = arg[2];
  inputs["model"] = std::string(arg[2]);
  for (int k = 3; k < narg; k += 2) {
    if (k + 1 >= narg)
      error->all(FLERR, "pair_coeff {} {}: {} has no value (pairs of key value follow the model)", arg[0], arg[1],
                 arg[k]);
    if (inputs.count(arg[k]))
      error->all(FLERR, "pair_coeff {} {}: {} is given twice", arg[0], arg[1], arg[k]);
    inputs[arg[k]] = std::string(arg[k + 1]);
    typed += std::string(" ") + arg[k] + " " + arg[k + 1];
  }
  auto entry = std::make_shared<TypePair>();
  entry->inputs = typed;
  try {
    entry->law = bounce::api::contact_law(inputs);
  } catch (const std::exception &e) {
    error->all(FLERR, "pair_coeff {} {} {}: {}", arg[0], arg[1], arg[2], e.what());
  }

  const int n = atom->ntypes;
  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      laws_[i * (n + 1) + j] = laws_[j * (n + 1) + i] = entry;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "pair_coeff {} {}: no type pair I <= J in these ranges", arg[0], arg[1]);
}

const bounce::models::DemModel *PairBounce::law(int itype, int jtype) const
{
  const auto &entry = laws_[itype * (atom->ntypes + 1) + jtype];
  return entry ? &entry->law : nullptr;
}

void PairBounce::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "pair_style bounce needs atom_style sphere (radius, rmass, omega, torque)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "pair_style bounce needs ghost atoms' velocities: comm_modify vel yes");
  if (std::strcmp(update->unit_style, "si") != 0)
    error->all(FLERR, "pair_style bounce needs units si (bounce's laws are in SI units), not units {}",
               update->unit_style);

  // A size neighbor list with history: the touch flag keeps adhesive contacts beyond
  // r = R_i + R_j, the three numbers the tangential spring.
#if BOUNCE_LAMMPS_ADD_REQUEST
  neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_HISTORY);
#else
  const int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->size = 1;
  neighbor->requests[irequest]->history = 1;
#endif
  if (fix_history_ == nullptr) {
    fix_history_ = dynamic_cast<FixNeighHistory *>(modify->replace_fix(
        dummy_id, std::string(history_id) + " all NEIGH_HISTORY " + std::to_string(history_size), 1));
    fix_history_->pair = this;
    fix_dummy_ = nullptr;
  }

  // The largest radius of each type (the cutoffs, and the reach of adhesive contacts).
  const int n = atom->ntypes;
  std::vector<double> local(n + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++) local[atom->type[i]] = std::max(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), max_radius_.data(), n + 1, MPI_DOUBLE, MPI_MAX, world);
}

// How far beyond r = R_i + R_j a contact of these radii holds: -release_overlap (JKR's neck).
double PairBounce::reach(int itype, int jtype, double radius_i, double radius_j) const
{
  const bounce::models::DemModel *l = law(itype, jtype);
  if (!l || radius_i <= 0.0 || radius_j <= 0.0) return 0.0;
  const bounce::models::ContactGeometry g{radius_i * radius_j / (radius_i + radius_j), 0.0};
  return -l->normal->release_overlap(g);
}

double PairBounce::init_one(int i, int j)
{
  const int n = atom->ntypes;
  if (setflag[i][j] == 0) {
    const auto &ii = laws_[i * (n + 1) + i], &jj = laws_[j * (n + 1) + j];
    if (!ii || !jj || ii->inputs != jj->inputs)
      error->all(FLERR,
                 "pair_style bounce: no pair_coeff {} {}; types {} and {} have different laws, so give the pair its "
                 "own (both materials: material material2, or E nu E2 nu2 ...)",
                 i, j, i, j);
    laws_[i * (n + 1) + j] = laws_[j * (n + 1) + i] = ii;
  }
  // Contacts reach R_i + R_j, and adhesive ones beyond it down to their release overlap: the
  // size neighbor list finds them only while its skin covers that reach.
  double largest = 0.0;
  for (int k = 1; k <= n; k++) largest = std::max(largest, max_radius_[k]);
  const double ri = max_radius_[i] > 0.0 ? max_radius_[i] : largest;
  const double rj = max_radius_[j] > 0.0 ? max_radius_[j] : largest;
  const double beyond = reach(i, j, ri, rj);
  if (beyond >= neighbor->skin)
    error->all(FLERR,
               "pair_style bounce: types {} {} stay in contact up to {:.3g} m beyond touching (the adhesive neck), "
               "more than the neighbor skin {:.3g} m: use a larger skin (neighbor SKIN bin)",
               i, j, beyond, neighbor->skin);
  return ri + rj + beyond;
}

// LAMMPS's velocity Verlet is a leapfrog: the force of step n acts over [t_n - dt/2, t_n + dt/2],
// computed with the positions at t_n and the velocities at t_n - dt/2. With integration
// `corrected` (the default, docs/lammps.md) three things make a collision second order in dt:
//  * the rate of the overlap is predicted to t_n with this contact's last force,
//    xi' = -v_n - (dt/2) F_last / m_eff (exact to O(dt^2) in a binary collision);
//  * a contact that forms inside the step, phi dt before t_n, gets the impulse of its force over
//    that time by Simpson's rule, plus F_n dt/2: phi (F_0 + 4 F_m + F_n)/6 + F_n/2, with F_0 at
//    first touch (JKR's snap-on, viscoelastic-shifted's C0 (A xi')^{3/2}; 0 for Hertz) and F_m
//    at half the overlap;
//  * a contact that ends inside the step, theta dt after t_{n-1}, gets the impulse of its force
//    from the last overlap to the release overlap by Simpson's rule, less the F_{n-1} dt/2 the
//    last step already gave: theta (F_{n-1} + 4 F_m + F_r)/6 - F_{n-1}/2.
//  Simpson's rule follows the force's sqrt(xi) and xi^{3/2} near xi = 0 closely (a trapezoid
//  made the COR error 3x larger).
// phi and theta come from the overlap at the step before, xi_n + dt v_n (Verlet's drift is
// exactly dt v). `plain` computes the force as LAMMPS's own pair styles do.
void PairBounce::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const bool update_history = !update->setupflag;
  const bool corrected = corrected_ && update_history;  // setup: whole-step velocities
  const double dt = update->dt;
  double **x = atom->x, **v = atom->v, **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  int **firsttouch = fix_history_->firstflag;
  double **firsthistory = fix_history_->firstvalue;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int itype = type[i];
    int *touch = firsttouch[i];
    double *all_history = firsthistory[i];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radsum = radius[i] + radius[j];
      const bounce::models::DemModel &law = *this->law(itype, type[j]);
      bounce::models::ContactGeometry g;
      g.effective_radius = radius[i] * radius[j] / radsum;
      double *history = &all_history[history_size * jj];

      // A contact forms at r < R_i + R_j; one that exists holds down to its release overlap.
      const bool touching = touch[jj];
      bool contact = rsq < radsum * radsum;
      double release = 0.0;
      if (!contact && touching) {
        release = law.normal->release_overlap(g);
        contact = rsq < (radsum - release) * (radsum - release);
      }
      if (!contact && !(touching && corrected)) {
        touch[jj] = 0;
        for (int k = 0; k < history_size; k++) history[k] = 0.0;
        continue;
      }
      const double r = std::sqrt(rsq), rinv = 1.0 / r;
      const double n[3] = {delx * rinv, dely * rinv, delz * rinv};
      const double vr[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
      const double vn = vr[0] * n[0] + vr[1] * n[1] + vr[2] * n[2];
      const double overlap = radsum - r;
      const double before = overlap + dt * vn;  // the overlap at the step before
      g.effective_mass = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);

      double fn = 0.0;
      double ft[3] = {0.0, 0.0, 0.0};
      if (!contact) {
        // Released inside the step, theta dt after the last one.
        const double theta = before > overlap ? std::clamp((before - release) / (before - overlap), 0.0, 1.0) : 0.0;
        const double last = history[last_force];
        const double middle = normal_force(law, g, 0.5 * (before + release), -vn);
        const double end = normal_force(law, g, release + inside * (before - release), -vn);
        fn = theta * (last + 4.0 * middle + end) / 6.0 - 0.5 * last;
        touch[jj] = 0;
        for (int k = 0; k < history_size; k++) history[k] = 0.0;
      } else {
        touch[jj] = 1;
        // The normal force (positive: repulsive) at overlap radsum - r and its rate.
        const double rate = -vn - (corrected ? 0.5 * dt * history[last_force] / g.effective_mass : 0.0);
        fn = normal_force(law, g, overlap, rate);
        const double previous = history[last_force];
        if (update_history) history[last_force] = fn;
        if (law.tangential) tangential(law, n, vr, vn, i, j, g, fn, touching ? previous : fn, dt, update_history, history, ft);
        // Formed inside the step, phi dt before now (a whole step if it overlapped already).
        if (corrected && !touching) {
          const double phi = before < 0.0 ? overlap / (overlap - before) : 1.0;
          const double first = normal_force(law, g, inside * overlap, rate);
          const double middle = normal_force(law, g, 0.5 * overlap, rate);
          fn = phi * (first + 4.0 * middle + fn) / 6.0 + 0.5 * fn;
        }
      }

      const double fx = n[0] * fn + ft[0], fy = n[1] * fn + ft[1], fz = n[2] * fn + ft[2];
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;
      const double tor[3] = {n[1] * ft[2] - n[2] * ft[1], n[2] * ft[0] - n[0] * ft[2], n[0] * ft[1] - n[1] * ft[0]};
      // The lever arm is the radius, as in BSHP96's (10) and in the contact points' velocity
      // above (pair granular's R - xi/2 here would make the tangential force's power differ
      // from -F^T . sliding by O(xi/R), and eps^T by ~1e-3 from bounce's).
      const double arm_i = radius[i];
      for (int k = 0; k < 3; k++) torque[i][k] -= arm_i * tor[k];
      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
        const double arm_j = radius[j];
        for (int k = 0; k < 3; k++) torque[j][k] -= arm_j * tor[k];
      }
      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
    }
  }
}

// BSHP96's tangential law of a contact (models::tangential_step) with the contact points'
// relative velocity in the tangent plane, as pair granular takes it.
void PairBounce::tangential(const bounce::models::DemModel &law, const double n[3], const double vr[3], double vn,
                            int i, int j, const bounce::models::ContactGeometry &g, double fn, double previous, double dt, bool update_history,
                            double *history, double ft[3]) const
{
  const double *radius = atom->radius;
  double **omega = atom->omega;
  const double wr[3] = {radius[i] * omega[i][0] + radius[j] * omega[j][0],
                        radius[i] * omega[i][1] + radius[j] * omega[j][1],
                        radius[i] * omega[i][2] + radius[j] * omega[j][2]};
  const double sliding[3] = {vr[0] - vn * n[0] - (n[2] * wr[1] - n[1] * wr[2]),
                             vr[1] - vn * n[1] - (n[0] * wr[2] - n[2] * wr[0]),
                             vr[2] - vn * n[2] - (n[1] * wr[0] - n[0] * wr[1])};
  if (update_history) {
    // The spring turns with the contact: back into the tangent plane, its length kept.
    const double along = history[0] * n[0] + history[1] * n[1] + history[2] * n[2];
    const double before = std::sqrt(history[0] * history[0] + history[1] * history[1] + history[2] * history[2]);
    for (int k = 0; k < 3; k++) history[k] -= along * n[k];
    const double after = std::sqrt(history[0] * history[0] + history[1] * history[1] + history[2] * history[2]);
    if (after > 0.0)
      for (int k = 0; k < 3; k++) history[k] *= before / after;
  }
  bounce::models::tangential_step(*law.tangential, fn, previous, g.effective_mass, sliding, dt, update_history,
                                  history, ft);
}
