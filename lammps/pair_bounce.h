/* pair_style bounce: bounce's contact laws as a LAMMPS pair style (docs/lammps.md).

   A front end of bounce like the CLI and Python: `pair_coeff I J MODEL key value ...` hands
   the model and the materials, by the CLI's names, to bounce's front door, which checks them
   by the CLI's rules and returns the contact law; every force comes from bounce's own model
   code, evaluated per contact with the atoms' radii and masses. */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(bounce,PairBounce);
// clang-format on
#else

#ifndef BOUNCE_LAMMPS_PAIR_BOUNCE_H
#define BOUNCE_LAMMPS_PAIR_BOUNCE_H

#include <memory>
#include <string>
#include <vector>

#include "lmptype.h"
#include "pair.h"

#include "bounce/dem/contact.hpp"

namespace bounce::lammps {
struct TypeLaw;
}  // namespace bounce::lammps

namespace LAMMPS_NS {

class PairBounce : public Pair {
 public:
  explicit PairBounce(class LAMMPS *);
  ~PairBounce() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
#if BOUNCE_LAMMPS_TYPED_TRANSFER
  void transfer_history(double *, double *, int, int) override;
#else
  void transfer_history(double *, double *) override;
#endif
  // Restart files: pair_style's setting and every pair_coeff (pair_bounce_io.cpp).
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  // One pair's force (compute pair/local, compute fabric): pair_bounce_io.cpp.
  double single(int, int, int, int, double, double, double, double &) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

 private:
  void allocate();
  void set_law(int i, int j, std::shared_ptr<const bounce::lammps::TypeLaw> entry);
  const bounce::lammps::TypeLaw *entry(int itype, int jtype) const;
  double reach(int itype, int jtype, double radius_i, double radius_j) const;
  double cutoff(int i, int j) const;
  void find_radii();
  void find_rigid_and_frozen();
  void update_rigid_masses();
  double effective_mass(int i, int j) const;
  void report(const bounce::dem::ContactForce &c, const bounce::dem::Kinematics &k, int i, int j);
  bool contact(int i, int j, int &touch, double *history, const bounce::dem::StepSettings &s,
               bounce::dem::ContactForce &c, bounce::dem::Kinematics &k);
  void apply(int i, int j, const bounce::dem::ContactForce &c, const bounce::dem::Kinematics &k, int eflag);
  [[noreturn]] void stop_one(const std::string &message);

  std::vector<std::shared_ptr<const bounce::lammps::TypeLaw>> laws_;  // [itype * (ntypes + 1) + jtype]
  class FixNeighHistory *fix_history_;
  std::vector<double> dynamic_radius_, frozen_radius_;  // per type: the largest, fix pour's and deposit's included
  class Fix *fix_rigid_ = nullptr;  // m_eff takes its bodies' masses (as pair granular)
  double *mass_rigid_ = nullptr;    // per atom: its body's mass, 0 if none
  int nmax_rigid_ = 0;
  int freeze_bit_ = 0;              // fix freeze's group: m_eff is the other atom's mass
  bool corrected_ = true;           // pair_style bounce integration corrected | plain
  // A restart read was written before passive became the asperity law's default (issue 40):
  // pair_coeff's that name no form keep the published one (type_laws.h, restart_type_law).
  bool published_restart_ = false;
  bool warned_ = false;             // a contact too coarse for dt was reported in this run
  bounce::dem::Layout layout_;      // per contact in FixNeighHistory: the laws' states (set at the first run)
  int single_neighbor_ = 0;         // single(): where the last search of j in i's list ended
};

}  // namespace LAMMPS_NS

#endif
#endif
