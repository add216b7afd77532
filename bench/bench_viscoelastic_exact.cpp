// Prints the master-curve COR at (kappa, rule): the exact value the scipy
// comparison measures errors against (bench/viscoelastic_vs_scipy.py).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bounce/analytic/master_curve.hpp"

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  const auto rule = std::string(argv[2]) == "force" ? bounce::models::EndRule::force
                                                    : bounce::models::EndRule::overlap;
  std::printf("%.17g\n", bounce::analytic::master_cor(std::strtod(argv[1], nullptr), rule));
  return 0;
}
