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
#include "contact_step.h"

using namespace LAMMPS_NS;


namespace {
const char *const dummy_id = "NEIGH_HISTORY_BOUNCE_DUMMY";
const char *const history_id = "NEIGH_HISTORY_BOUNCE";
}  // namespace

// The law of one type pair, and its inputs as typed, in key order (types I I and J J with the
// same keys and values give I J the same law).
struct PairBounce::TypePair {
  bounce::models::DemModel law;
  std::string inputs;
  bool snaps = false;  // its contacts form before touching (Maugis-Dugdale's zone)
};

PairBounce::PairBounce(LAMMPS *instance) : Pair(instance), fix_history_(nullptr)
{
  single_enable = 0;
  nondefault_history_transfer = 1;
  restartinfo = 0;
  no_virial_fdotr_compute = 1;
  // compute pair bounce: krijt's energies, crack- and bulk-dissipated (on this rank, since the
  // pair style was defined), elastic and surface (stored in its contacts now) [J].
  nextra = 4;
  pvector = new double[nextra]();
  // A placeholder for the history fix, replaced in init_style, so that the fix list keeps the
  // order of the input script (as pair granular does).
  modify->add_fix(std::string(dummy_id) + " all DUMMY");
}

PairBounce::~PairBounce()
{
  if (copymode) return;
  delete[] pvector;
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

// The history is that of pair (i, j); seen from j it is (j, i): the spring turns round, the
// normal force and the crack's state do not.
void PairBounce::transfer_history(double *source, double *target)
{
  for (int k = 0; k < bounce::lammps::last_force; k++) target[k] = -source[k];
  for (int k = bounce::lammps::last_force; k < history_values_; k++) target[k] = source[k];
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
  inputs["model"] = std::string(arg[2]);
  for (int k = 3; k < narg; k += 2) {
    if (k + 1 >= narg)
      error->all(FLERR, "pair_coeff {} {}: {} has no value (pairs of key value follow the model)", arg[0], arg[1],
                 arg[k]);
    if (inputs.count(arg[k]))
      error->all(FLERR, "pair_coeff {} {}: {} is given twice", arg[0], arg[1], arg[k]);
    inputs[arg[k]] = std::string(arg[k + 1]);
  }
  // One atom type is one material: a pair of a type with itself takes no body 2 of its own.
  if (std::max(ilo, jlo) <= std::min(ihi, jhi)) {
    for (const char *key : {"material2", "E2", "nu2", "gamma2"})
      if (inputs.count(key))
        error->all(FLERR, "pair_coeff {} {}: {} = {} is invalid: expected none for a type with itself (one type, one "
                   "material; give unlike types their own pair_coeff I J)",
                   arg[0], arg[1], key, std::get<std::string>(inputs[key]));
  }
  auto entry = std::make_shared<TypePair>();
  for (const auto &[key, value] : inputs) entry->inputs += key + "=" + std::get<std::string>(value) + " ";
  try {
    entry->law = bounce::api::contact_law(inputs);
  } catch (const std::exception &e) {
    error->all(FLERR, "pair_coeff {} {} {}: {}", arg[0], arg[1], arg[2], e.what());
  }

  // An adhesive contact holds beyond touching: its history must survive a neighbour-list build
  // that finds the pair apart (FixNeighHistory keeps it then only with beyond_contact).
  const bounce::models::ContactGeometry unit{1.0, 1.0};
  if (entry->law.release_overlap(unit) < 0.0) beyond_contact = 1;
  entry->snaps = entry->law.snap_overlap(unit) < 0.0;

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
  if (!utils::strmatch(update->integrate_style, "^verlet"))
    error->all(FLERR, "pair_style bounce needs run_style verlet (its corrected integration is velocity Verlet's)");
  warned_ = false;

  // A size neighbor list with history: the touch flag keeps adhesive contacts beyond
  // r = R_i + R_j; the values are the tangential spring and the last normal force.
#if BOUNCE_LAMMPS_ADD_REQUEST
  neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_HISTORY);
#else
  const int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->size = 1;
  neighbor->requests[irequest]->history = 1;
#endif
  if (fix_history_ == nullptr) {
    // A crack law's contacts keep its state too (the fix's size is set once, at the first run).
    history_values_ = bounce::lammps::history_size;
    for (const auto &entry : laws_)
      if (entry && entry->law.crack) history_values_ = bounce::lammps::crack_history_size;
    fix_history_ = dynamic_cast<FixNeighHistory *>(modify->replace_fix(
        dummy_id, std::string(history_id) + " all NEIGH_HISTORY " + std::to_string(history_values_), 1));
    fix_history_->pair = this;
  } else {
    for (const auto &entry : laws_)
      if (entry && entry->law.crack && history_values_ < bounce::lammps::crack_history_size)
        error->all(FLERR, "pair_style bounce: a krijt pair_coeff after the first run keeps no crack state: give it "
                          "before the first run");
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
  return -l->release_overlap(g);
}

// A contact too stiff for the time step: reported once per run and rank, with the numbers.
void PairBounce::coarse(const bounce::lammps::ContactForce &c, const bounce::lammps::Kinematics &k, tagint i, tagint j)
{
  if (warned_) return;
  warned_ = true;
  error->warning(FLERR,
                 "pair_style bounce: the contact of atoms {} and {} (overlap {:.3g} m, force {:.3g} N) has a period of "
                 "{:.3g} steps of dt = {:.6g} s; bounce's laws need 20 or more for a COR to 1e-4, and with fewer than "
                 "about 5 a collision can gain energy: use a smaller time step (docs/lammps.md, Time step)",
                 i, j, k.overlap, c.normal, c.period_steps, update->dt);
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

namespace {

// The contact's geometry and motion, as pair granular takes them: n from j to i, the overlap, the
// normal rate and the contact points' relative velocity in the tangent plane.
bounce::lammps::Kinematics kinematics(const double *xi, const double *xj, const double *vi, const double *vj,
                                      const double *wi, const double *wj, double ri, double rj, double r)
{
  bounce::lammps::Kinematics k;
  const double rinv = 1.0 / r;
  for (int d = 0; d < 3; d++) k.n[d] = (xi[d] - xj[d]) * rinv;
  k.overlap = ri + rj - r;
  const double vr[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
  k.vn = vr[0] * k.n[0] + vr[1] * k.n[1] + vr[2] * k.n[2];
  const double wr[3] = {ri * wi[0] + rj * wj[0], ri * wi[1] + rj * wj[1], ri * wi[2] + rj * wj[2]};
  k.sliding[0] = vr[0] - k.vn * k.n[0] - (k.n[2] * wr[1] - k.n[1] * wr[2]);
  k.sliding[1] = vr[1] - k.vn * k.n[1] - (k.n[0] * wr[2] - k.n[2] * wr[0]);
  k.sliding[2] = vr[2] - k.vn * k.n[2] - (k.n[1] * wr[0] - k.n[0] * wr[1]);
  return k;
}

}  // namespace

// The loop of pair granular; each contact's step is bounce::lammps::contact_step (the
// corrected or plain integration, docs/lammps.md).
void PairBounce::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (eflag) pvector[2] = pvector[3] = 0.0;  // the stored energies; 0 and 1 accumulate over the run
  bounce::lammps::StepSettings settings;
  settings.dt = update->dt;
  settings.update_history = !update->setupflag;
  settings.corrected = corrected_ && settings.update_history;  // setup: whole-step velocities
  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  int **firsttouch = fix_history_->firstflag;
  double **firsthistory = fix_history_->firstvalue;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radsum = radius[i] + radius[j];
      int &touch = firsttouch[i][jj];
      double *history = &firsthistory[i][history_values_ * jj];
      // No contact, none before: its history is zero already (FixNeighHistory zeroes a new pair's,
      // and contact_step an ended contact's), and is left alone (up to 12 values a neighbour).
      // A law whose contact forms before touching (snap_overlap < 0) is asked where.
      const TypePair &entry = *laws_[type[i] * (atom->ntypes + 1) + type[j]];
      if (!touch && rsq >= radsum * radsum && !entry.snaps) continue;
      const bounce::models::DemModel &law = entry.law;
      bounce::models::ContactGeometry g;
      g.effective_radius = radius[i] * radius[j] / radsum;
      g.effective_mass = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
      if (!touch && entry.snaps && radsum - std::sqrt(rsq) <= law.snap_overlap(g)) continue;
      if (rsq == 0.0)
        error->one(FLERR, "pair_style bounce: atoms {} and {} are at the same place (no contact normal)", atom->tag[i],
                   atom->tag[j]);
      const bounce::lammps::Kinematics k =
          kinematics(x[i], x[j], v[i], v[j], omega[i], omega[j], radius[i], radius[j], std::sqrt(rsq));
      const double release = k.overlap > 0.0 || law.crack ? 0.0 : law.normal->release_overlap(g);
      const bounce::lammps::ContactForce c = bounce::lammps::contact_step(law, g, k, release, settings, touch, history);
      if (!c.finite())
        error->one(FLERR,
                   "pair_style bounce: the force between atoms {} and {} is not finite (overlap {:.6g} m, rate {:.6g} "
                   "m/s, dt {:.6g} s): the time step is too large for this law, or an input extreme (docs/lammps.md, "
                   "Time step)",
                   atom->tag[i], atom->tag[j], k.overlap, -k.vn, settings.dt);
      if (c.period_steps > 0.0 && c.period_steps < bounce::lammps::few_steps) coarse(c, k, atom->tag[i], atom->tag[j]);
      apply(i, j, c, k, delx, dely, delz, eflag);
    }
  }
}

// A contact's force and torque on atoms i and j (j only when it is owned or newton pair is on),
// its energies and its virial.
void PairBounce::apply(int i, int j, const bounce::lammps::ContactForce &c, const bounce::lammps::Kinematics &k,
                       double delx, double dely, double delz, int eflag)
{
  double **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const double *ft = c.tangential;
  const double fx = k.n[0] * c.normal + ft[0], fy = k.n[1] * c.normal + ft[1], fz = k.n[2] * c.normal + ft[2];
  f[i][0] += fx;
  f[i][1] += fy;
  f[i][2] += fz;
  // The lever arm is the radius, as in BSHP96's (10) and in the contact points' velocity
  // (pair granular's R - xi/2 here would make the tangential force's power differ from
  // -F^T . sliding by O(xi/R), and eps^T by ~1e-3 from bounce's).
  const double tor[3] = {k.n[1] * ft[2] - k.n[2] * ft[1], k.n[2] * ft[0] - k.n[0] * ft[2],
                         k.n[0] * ft[1] - k.n[1] * ft[0]};
  for (int d = 0; d < 3; d++) torque[i][d] -= radius[i] * tor[d];
  if (newton_pair || j < nlocal) {
    f[j][0] -= fx;
    f[j][1] -= fy;
    f[j][2] -= fz;
    for (int d = 0; d < 3; d++) torque[j][d] -= radius[j] * tor[d];
  }
  // A crack law's energies (krijt): the pair is computed twice, once on each side, when j is a
  // ghost atom and newton pair is off.
  const double share = newton_pair || j < nlocal ? 1.0 : 0.5;
  pvector[0] += share * c.crack_dissipated;
  pvector[1] += share * c.bulk_dissipated;
  if (eflag) {
    pvector[2] += share * c.elastic;
    pvector[3] += share * c.surface;
  }
  if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, c.elastic + c.surface, 0.0, fx, fy, fz, delx, dely, delz);
}
