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

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lmptype.h"
#include "pair.h"

namespace bounce::models {
struct DemModel;
struct ContactGeometry;
}  // namespace bounce::models
namespace bounce::lammps {
struct ContactForce;
struct Kinematics;
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
  void transfer_history(double *, double *) override;

  // The law of a type pair (for tests and the wall fix).
  const bounce::models::DemModel *law(int itype, int jtype) const;

 private:
  struct TypePair;
  void allocate();
  double reach(int itype, int jtype, double radius_i, double radius_j) const;
  void coarse(const bounce::lammps::ContactForce &c, const bounce::lammps::Kinematics &k, tagint i, tagint j);
  void apply(int i, int j, const bounce::lammps::ContactForce &c, const bounce::lammps::Kinematics &k, double delx,
             double dely, double delz, int eflag);

  std::vector<std::shared_ptr<const TypePair>> laws_;  // [itype * (ntypes + 1) + jtype]
  class FixNeighHistory *fix_history_;
  std::vector<double> max_radius_;  // per type, over all atoms
  bool corrected_ = true;           // pair_style bounce integration corrected | plain
  bool warned_ = false;             // a contact too stiff for dt was reported in this run
  int history_values_ = 0;          // per contact: history_size, or crack_history_size with krijt
};

}  // namespace LAMMPS_NS

#endif
#endif
