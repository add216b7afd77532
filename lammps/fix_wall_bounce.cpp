/* fix wall/bounce (docs/lammps.md, Walls): the atom is body 1, the flat wall body 2 (R_eff = R,
   m_eff = m); each contact's step is bounce::dem::step, as pair_style bounce's. */

#include "fix_wall_bounce.h"

#include <cmath>
#include <cstring>
#include <exception>
#include <set>
#include <string>
#include <utility>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include "bounce/api/front_door.hpp"
#include "bounce/dem/contact.hpp"
#include "rigid_masses.h"
#include "stop.h"
#include "type_laws.h"

using namespace LAMMPS_NS;

FixWallBounce::FixWallBounce(LAMMPS *instance, int narg, char **arg) : Fix(instance, narg, arg), state_(nullptr)
{
  if (narg < 7)
    error->all(FLERR, "fix wall/bounce: expected fix ID group wall/bounce xplane|yplane|zplane LO HI MODEL key value ...");
  if (std::strcmp(arg[3], "xplane") == 0) axis_ = 0;
  else if (std::strcmp(arg[3], "yplane") == 0) axis_ = 1;
  else if (std::strcmp(arg[3], "zplane") == 0) axis_ = 2;
  else error->all(FLERR, "fix wall/bounce: wall = {} is invalid: expected xplane, yplane or zplane", arg[3]);
  for (int w = 0; w < 2; w++) {
    has_[w] = std::strcmp(arg[4 + w], "NULL") != 0;
    position_[w] = has_[w] ? utils::numeric(FLERR, arg[4 + w], false, lmp) : 0.0;
  }
  if (!has_[0] && !has_[1]) error->all(FLERR, "fix wall/bounce: LO and HI are both NULL: no wall");
  if (has_[0] && has_[1] && position_[0] >= position_[1])
    error->all(FLERR, "fix wall/bounce: LO = {} is invalid: expected LO < HI = {}", arg[4], arg[5]);

  bounce::api::Inputs inputs;
  inputs["model"] = std::string(arg[6]);
  std::set<std::string> seen;
  for (int k = 7; k < narg; k += 2) {
    if (k + 1 >= narg) error->all(FLERR, "fix wall/bounce: {} has no value (pairs of key value follow the model)", arg[k]);
    if (!seen.insert(arg[k]).second) error->all(FLERR, "fix wall/bounce: {} is given twice", arg[k]);
    if (std::strcmp(arg[k], "integration") == 0) {
      if (std::strcmp(arg[k + 1], "corrected") == 0) corrected_ = true;
      else if (std::strcmp(arg[k + 1], "plain") == 0) corrected_ = false;
      else error->all(FLERR, "fix wall/bounce: integration = {} is invalid: expected corrected or plain", arg[k + 1]);
    } else if (std::strcmp(arg[k], "rigid_wall") == 0) {
      if (std::strcmp(arg[k + 1], "yes") == 0)
        for (int m = 7; m + 1 < narg; m += 2)
          if (std::strcmp(arg[m], "material2") == 0)
            error->all(FLERR,
                       "fix wall/bounce: material2 = {} is invalid: expected none with rigid_wall yes (a rigid wall "
                       "has no elastic moduli; its surface energy is gamma2, by default the atom's)",
                       arg[m + 1]);
      const std::string v = arg[k + 1];
      if (v != "yes" && v != "no") error->all(FLERR, "fix wall/bounce: rigid_wall = {} is invalid: expected yes or no", v);
      inputs["rigid_wall"] = v == "yes";
    } else {
      inputs[arg[k]] = std::string(arg[k + 1]);
    }
  }
  make_laws(inputs, arg[6]);

  layout_.add(*law_);
  values_ = 1 + layout_.size();
  size_ = 2 * values_;
  restart_peratom = 1;
  create_attribute = 1;  // atoms made after the fix (fix pour, deposit) start untouched: set_arrays
  FixWallBounce::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) FixWallBounce::set_arrays(i);
}

FixWallBounce::~FixWallBounce()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(mass_rigid_);
  memory->destroy(state_);
}

// The wall's law, and where it takes the default asperity form, the same with the published form
// (the one a restart written before passive became the default holds: unpack_restart).
void FixWallBounce::make_laws(bounce::api::Inputs inputs, const char *model)
{
  try {
    law_ = std::make_shared<const bounce::models::DemModel>(bounce::api::wall_dem_model(inputs));
    if (bounce::lammps::takes_default_asperity_form(*law_, inputs.count("asperity_form") > 0)) {
      inputs["asperity_form"] = std::string(bounce::lammps::form_before_passive_default);
      published_law_ = std::make_shared<const bounce::models::DemModel>(bounce::api::wall_dem_model(inputs));
    }
  } catch (const std::exception &e) {
    error->all(FLERR, "fix wall/bounce {}: {}", model, e.what());
  }
}

int FixWallBounce::setmask()
{
  return FixConst::POST_FORCE;
}

void FixWallBounce::init()
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "fix wall/bounce needs atom_style sphere (radius, rmass, omega, torque)");
  if (std::strcmp(update->unit_style, "si") != 0)
    error->all(FLERR, "fix wall/bounce needs units si (bounce's laws are in SI units), not units {}", update->unit_style);
  if (!utils::strmatch(update->integrate_style, "^verlet"))
    error->all(FLERR, "fix wall/bounce needs run_style verlet");
  warned_ = false;
  keep_published_form();
  fix_rigid_ = nullptr;
  for (int k = 0; k < modify->nfix; k++)
    if (modify->fix[k]->rigid_flag) fix_rigid_ = modify->fix[k];
}

// Each owned atom's rigid body's mass (0 if none), refreshed where atoms were exchanged.
void FixWallBounce::update_rigid_masses()
{
  bounce::lammps::rigid_masses(lmp, fix_rigid_, mass_rigid_, nmax_rigid_, "fix wall/bounce",
                               "fix_wall_bounce:mass_rigid");
}

// Continued from a restart written before passive became the default (on any rank), a law that
// names no asperity form keeps the published one, whose springs the atoms' records hold.
void FixWallBounce::keep_published_form()
{
  int mine = old_restart_ ? 1 : 0, any = 0;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  if (!any || !published_law_) return;
  law_ = std::move(published_law_);
  published_law_.reset();
  if (comm->me == 0)
    error->warning(FLERR,
                   "fix wall/bounce {}: its restart records were written before passive became the default "
                   "asperity_form: naming no form, it keeps the published form their springs hold (docs/lammps.md, "
                   "Restarts)",
                   id);
}

// m_eff against an immovable wall: the atom's mass, or its rigid body's.
double FixWallBounce::mass(int i) const
{
  return fix_rigid_ && mass_rigid_[i] > 0.0 ? mass_rigid_[i] : atom->rmass[i];
}

void FixWallBounce::setup(int vflag)
{
  post_force(vflag);
}

// A contact whose step is a tenth of the explicit step's limit or more: a WARNING once per run
// and rank; at the limit (unstable) LAMMPS stops (step_check.h).
void FixWallBounce::report(const bounce::dem::ContactForce &c, const bounce::dem::Kinematics &k, int i, double dt)
{
  if (c.check.stability >= 1.0)
    bounce::lammps::stop_one(
        lmp, fmt::format("fix wall/bounce: the time step is too long for the contact of atom {} with the wall at "
                         "overlap {:.3g} m: the explicit step cannot integrate it (its energy grows each step); {} "
                         "(docs/lammps.md, Time step)",
                         atom->tag[i], k.overlap, c.check.describe(dt)));
  if (warned_) return;
  warned_ = true;
  error->warning(FLERR,
                 "fix wall/bounce: the contact of atom {} with the wall at overlap {:.3g} m is coarse for the time step: "
                 "{}; bounce's laws need a tenth of that limit or less: use a smaller time step (docs/lammps.md, Time "
                 "step)",
                 atom->tag[i], k.overlap, c.check.describe(dt));
}

void FixWallBounce::not_finite(int i, const bounce::dem::Kinematics &k, double dt)
{
  bounce::lammps::stop_one(
      lmp, fmt::format("fix wall/bounce: the force on atom {} is not finite (overlap {:.6g} m, rate {:.6g} m/s, dt "
                       "{:.6g} s): the time step is too large for this law, or an input extreme (docs/lammps.md, "
                       "Time step)",
                       atom->tag[i], k.overlap, -k.vn, dt));
}

void FixWallBounce::post_force(int)
{
  bounce::dem::StepSettings settings;
  settings.dt = update->dt;
  settings.update_history = !update->setupflag;
  settings.corrected = corrected_ && settings.update_history;
  double **x = atom->x, **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  if (fix_rigid_ && (neighbor->ago == 0 || !mass_rigid_)) update_rigid_masses();
  const bounce::models::DemModel &law = *law_;
  // Does the law's contact form before touching (Maugis-Dugdale's zone)?
  const bool snaps = law.snap_overlap(bounce::models::ContactGeometry{1.0, 1.0}) < 0.0;

  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int w = 0; w < 2; w++) {
      if (!has_[w]) continue;
      double *slot = &state_[i][w * values_];
      const double sign = w == 0 ? 1.0 : -1.0;  // n points from the wall into the box
      const double distance = sign * (x[i][axis_] - position_[w]);
      const double overlap = radius[i] - distance;
      const bool touch = slot[0] != 0.0;
      if (distance <= 0.0) {  // the centre is behind the wall: no contact (as fix wall/gran)
        for (int m = 0; m < values_; m++) slot[m] = 0.0;
        continue;
      }
      if (!touch && overlap <= 0.0 && !snaps) continue;
      bounce::models::ContactGeometry g;
      g.effective_radius = radius[i];  // a flat wall
      g.effective_mass = mass(i);      // an immovable one
      if (!touch && snaps && !bounce::dem::within_reach(law, g, overlap)) continue;  // out of the zone's reach
      const bounce::dem::Kinematics k =
          bounce::dem::wall_kinematics({x[i], atom->v[i], atom->omega[i], radius[i]}, axis_, sign, overlap);
      bounce::dem::ContactState state = layout_.read(touch, slot + 1);
      const bounce::dem::ContactForce c = bounce::dem::step(law, g, k, settings, state);
      slot[0] = state.touching ? 1.0 : 0.0;
      layout_.write(state, slot + 1);
      if (!c.finite()) not_finite(i, k, settings.dt);
      if (c.check.stability > bounce::dem::coarse_stability) report(c, k, i, settings.dt);
      const bounce::dem::Loads l = bounce::dem::loads(c, k, radius[i], radius[i]);
      for (int d = 0; d < 3; d++) {
        f[i][d] += l.force[d];
        torque[i][d] += l.torque1[d];
      }
    }
  }
}

double FixWallBounce::memory_usage()
{
  return static_cast<double>(atom->nmax) * size_ * sizeof(double);
}

void FixWallBounce::grow_arrays(int nmax)
{
  memory->grow(state_, nmax, size_, "fix_wall_bounce:state");
}

void FixWallBounce::copy_arrays(int i, int j, int)
{
  for (int m = 0; m < size_; m++) state_[j][m] = state_[i][m];
}

void FixWallBounce::set_arrays(int i)
{
  for (int m = 0; m < size_; m++) state_[i][m] = 0.0;
}

int FixWallBounce::pack_exchange(int i, double *buf)
{
  for (int m = 0; m < size_; m++) buf[m] = state_[i][m];
  return size_;
}

int FixWallBounce::unpack_exchange(int nlocal, double *buf)
{
  for (int m = 0; m < size_; m++) state_[nlocal][m] = buf[m];
  return size_;
}

// A restart file's per-atom record: its length, the two walls' touch flags and histories, then
// record_mark. Records written before passive became the default asperity form have no mark (and
// an odd length: size_ is even); a plugin of then reads the new ones, leaving the mark unread.
int FixWallBounce::pack_restart(int i, double *buf)
{
  buf[0] = size_ + 2;
  for (int m = 0; m < size_; m++) buf[m + 1] = state_[i][m];
  buf[size_ + 1] = record_mark;
  return size_ + 2;
}

void FixWallBounce::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;  // this fix's record among the atom's: skip the ones before it
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  const int length = static_cast<int>(extra[nlocal][m]);
  if (length == size_ + 1) {
    old_restart_ = true;  // its springs are the published form's if the law names none (keep_published_form)
  } else if (length != size_ + 2 || extra[nlocal][m + size_ + 1] != record_mark) {
    error->one(FLERR,
               "fix wall/bounce {}: the restart file's record of atom {} ({} values) is not this law's ({}): give "
               "the fix the model it was written with",
               id, atom->tag[nlocal], length, size_ + 2);
  }
  m++;
  for (int k = 0; k < size_; k++) state_[nlocal][k] = extra[nlocal][m++];
}

int FixWallBounce::size_restart(int)
{
  return size_ + 2;
}

int FixWallBounce::maxsize_restart()
{
  return size_ + 2;
}
