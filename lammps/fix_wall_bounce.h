/* fix wall/bounce: flat walls acting on atoms with a bounce contact law (docs/lammps.md, Walls).

   fix ID group wall/bounce xplane|yplane|zplane LO HI MODEL key value ...

   LO and HI are the wall positions along the axis (NULL: no wall there); MODEL and the keys
   are pair_coeff's, body 1 being the atom and body 2 the wall (material2, E2, nu2, gamma2, or
   rigid_wall yes). Each atom keeps, per wall, the contact's touch flag and history. */

#ifdef FIX_CLASS
// clang-format off
FixStyle(wall/bounce,FixWallBounce);
// clang-format on
#else

#ifndef BOUNCE_LAMMPS_FIX_WALL_BOUNCE_H
#define BOUNCE_LAMMPS_FIX_WALL_BOUNCE_H

#include <memory>

#include "fix.h"
#include "bounce/api/front_door.hpp"
#include "bounce/dem/contact.hpp"

namespace LAMMPS_NS {

class FixWallBounce : public Fix {
 public:
  FixWallBounce(class LAMMPS *, int, char **);
  ~FixWallBounce() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  // Restart files keep each atom's touch flags and histories (the fix itself is given again).
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

 private:
  void make_laws(bounce::api::Inputs inputs, const char *model);
  void keep_published_form();
  void report(const bounce::dem::ContactForce &c, const bounce::dem::Kinematics &k, int i, double dt);
  void update_rigid_masses();
  [[noreturn]] void not_finite(int i, const bounce::dem::Kinematics &k, double dt);
  double mass(int i) const;
  bounce::dem::Layout layout_;  // the contact's state in the history
  int values_ = 0;              // per atom and wall: the touch flag, the history
  int size_ = 0;                // per atom: two walls
  int axis_;
  bool has_[2];
  double position_[2];
  bool corrected_ = true;
  std::shared_ptr<const bounce::models::DemModel> law_;
  // law_ with asperity_form published where the fix names no form: the law of a run continued
  // from a restart written before passive became the default (old_restart_, on any rank).
  std::shared_ptr<const bounce::models::DemModel> published_law_;
  bool old_restart_ = false;
  static constexpr double record_mark = 2.0;  // ends each atom's restart record since issue 40
  double **state_;  // [atom][wall * values + k]
  bool warned_ = false;  // a contact too coarse for dt was reported in this run
  class Fix *fix_rigid_ = nullptr;  // m_eff is its body's mass (as fix wall/gran)
  double *mass_rigid_ = nullptr;    // per atom: its body's mass, 0 if none
  int nmax_rigid_ = 0;
};

}  // namespace LAMMPS_NS

#endif
#endif
