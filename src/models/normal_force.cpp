#include "bounce/models/normal_force.hpp"

#include <cmath>

namespace bounce::models {

double power_law_reference_overlap(double d1, double alpha, double speed) {  // BP04 (8.65)
  return std::pow((alpha + 1.0) / (2.0 * d1), 1.0 / (1.0 + alpha)) * std::pow(speed, 2.0 / (1.0 + alpha));
}

}  // namespace bounce::models
