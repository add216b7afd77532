#include "bounce/contact/convex.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/tools/roots.hpp>

#include "bounce/core/checks.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/core/error.hpp"

namespace bounce::contact::convex {

namespace {
double curvature(const char* name, double radius) {
  if (std::isinf(radius) && radius > 0) return 0.0;  // flat direction
  require_positive(name, radius, "principal radius of curvature [m] (inf for flat)");
  return 1.0 / radius;
}
}  // namespace

QuadraticForm quadratic_form(const Curvatures& c) {  // BP04 (8.7)
  const double k1 = curvature("radius1", c.radius1);
  const double k2 = curvature("radius2", c.radius2);
  const double k1p = curvature("radius1_prime", c.radius1_prime);
  const double k2p = curvature("radius2_prime", c.radius2_prime);
  require_finite("angle", c.angle);
  const double sum = 0.5 * (k1 + k2 + k1p + k2p);            // B1 + B2
  const double d1 = k1 - k2;
  const double d2 = k1p - k2p;
  const double square = d1 * d1 + d2 * d2 + 2.0 * std::cos(2.0 * c.angle) * d1 * d2;
  const double difference = 0.5 * std::sqrt(std::max(square, 0.0));  // B1 - B2 >= 0
  QuadraticForm form{0.5 * (sum + difference), 0.5 * (sum - difference)};
  if (!(form.b2 > 1e-12 * form.b1)) {
    throw InvalidArgument("curvatures", "B2 = 0",
                          "a point contact, B2 > 0 (BP04 (8.7)); parallel cylinders or flat "
                          "directions that add up to a line contact are outside the theory");
  }
  return form;
}

double n_function(double x) {  // BP04 (8.15)
  return 2.0 * boost::math::ellint_rf(0.0, x, 1.0);
}

double m_function(double x) {  // BP04 (8.16)
  return 2.0 / 3.0 * x * boost::math::ellint_rd(0.0, 1.0, x);
}

double axis_ratio_function(double x) {  // BP04 (8.18), right-hand side
  return std::sqrt(x) * m_function(1.0 / x) / m_function(x);
}

double axis_ratio_squared(const QuadraticForm& form) {  // BP04 (8.18)
  const double target = form.b2 / form.b1;
  if (target >= 1.0) return 1.0;
  // r(x) rises monotonically from 0 (x -> 0) to 1 (x = 1); solve in log x.
  auto residual = [&](double log_x) { return axis_ratio_function(std::exp(log_x)) - target; };
  double lo = -1.0;
  while (residual(lo) > 0.0) {
    lo *= 2.0;
    if (lo < -700.0) throw NumericalError("BP04 (8.18): axis ratio root not bracketed");
  }
  std::uintmax_t iterations = 200;
  auto tolerance = boost::math::tools::eps_tolerance<double>(52);
  auto [a, b] = boost::math::tools::toms748_solve(residual, lo, 0.0, residual(lo), 1.0 - target,
                                                  tolerance, iterations);
  return std::exp(0.5 * (a + b));
}

ConvexContact solve(const Curvatures& curvatures, double d) {
  ConvexContact c;
  c.form = quadratic_form(curvatures);
  c.x0 = axis_ratio_squared(c.form);
  c.n_x0 = n_function(c.x0);
  c.m_x0 = m_function(c.x0);
  // BP04 (8.21), corrected: eliminating b between (8.19) and (8.20) gives N^3.
  c.force_constant = std::numbers::pi / d *
                     std::sqrt(c.m_x0 / (c.form.b1 * c.x0 * c.n_x0 * c.n_x0 * c.n_x0));
  return c;
}

double force(const ConvexContact& contact, double overlap) {  // BP04 (8.21)
  return overlap > 0.0 ? contact.force_constant * overlap * std::sqrt(overlap) : 0.0;
}

Ellipse ellipse(const ConvexContact& contact, double d, double overlap) {  // BP04 (8.19)
  if (overlap <= 0.0) return {};
  const double b = force(contact, overlap) * d * contact.n_x0 / (std::numbers::pi * overlap);
  return {std::sqrt(contact.x0) * b, b};
}

}  // namespace bounce::contact::convex

// --- the shape as parameters ---------------------------------------------------------

namespace bounce::contact::convex {

namespace {
std::vector<ParameterSpec> make_shape_parameters() {
  Range radii = positive();
  radii.infinite = true;  // a flat direction
  ParameterSpec r1 = real_parameter("curvature_radii", "principal radii R1,R2 of body 1", "m", radii,
                                    "principal radii R1,R2 of body 1 [m] (convex bodies; inf for a flat direction)");
  r1.kind = ParameterKind::reals;
  r1.count = 2;
  ParameterSpec r2 = r1;
  r2.name = "curvature_radii2";
  r2.quantity = "principal radii R1',R2' of body 2";
  r2.help = "principal radii R1',R2' of body 2 [m] (default: as body 1, or flat for a wall)";
  return {r1, r2,
          real_parameter("angle", "angle phi between the planes of R1 and R1'", "rad", Range{},
                         "angle phi between the planes of R1 and R1' [rad] (convex bodies; default 0)")};
}
}  // namespace

std::span<const ParameterSpec> shape_parameters() {
  static const std::vector<ParameterSpec> specs = make_shape_parameters();
  return specs;
}

std::optional<Curvatures> curvatures_from(const Parameters& p, bool body2_is_wall) {
  if (!p.given("curvature_radii") && !p.given("curvature_radii2") && !p.given("angle")) return std::nullopt;
  if (!p.given("curvature_radii")) throw InvalidArgument("curvature_radii", "(not given)", "R1,R2 of body 1 in m");
  const std::vector<double> r1 = *p.reals("curvature_radii");
  constexpr double flat = std::numeric_limits<double>::infinity();
  const std::vector<double> r2 = p.given("curvature_radii2") ? *p.reals("curvature_radii2")
                                 : body2_is_wall             ? std::vector<double>{flat, flat}
                                                             : r1;
  return Curvatures{r1[0], r1[1], r2[0], r2[1], p.real("angle").value_or(0.0)};
}

}  // namespace bounce::contact::convex

// --- the "hertz" contact law of convex bodies --------------------------------------------

namespace bounce::contact {

namespace {

class ConvexHertzLaw final : public ContactLaw {
 public:
  ConvexHertzLaw(const Pair& pair, const convex::Curvatures& c)
      : d_(pair.hertz_compliance_d()), shape_(convex::solve(c, d_)) {}

  std::string_view name() const override { return "hertz"; }

  ContactPoint at_force(double force) const override {
    require_non_negative("force", force, "force [N] (hertz has no adhesion)");
    const double ratio = force / shape_.force_constant;
    return at_overlap(std::cbrt(ratio * ratio));  // BP04 (8.21) inverted
  }

  ContactPoint at_overlap(double overlap) const override {
    require_non_negative("overlap", overlap, "overlap [m]");
    const convex::Ellipse e = convex::ellipse(shape_, d_, overlap);
    return {std::sqrt(e.semi_axis_a * e.semi_axis_b), overlap, convex::force(shape_, overlap)};
  }

  ContactPoint at_contact_radius(double a) const override {
    throw InvalidArgument("contact_radius", format_value(a),
                          "a force or an overlap for convex bodies (their contact is an ellipse)");
  }

  std::optional<AdhesionSummary> adhesion() const override { return std::nullopt; }

  std::vector<std::pair<std::string, double>> shape(const ContactPoint& point) const override {
    const convex::Ellipse e = convex::ellipse(shape_, d_, point.overlap);
    return {{"semi_axis_a", e.semi_axis_a}, {"semi_axis_b", e.semi_axis_b}, {"x0", shape_.x0},
            {"b1", shape_.form.b1},         {"b2", shape_.form.b2},         {"n_x0", shape_.n_x0},
            {"m_x0", shape_.m_x0},          {"force_constant", shape_.force_constant}};
  }

 private:
  double d_;
  convex::ConvexContact shape_;
};

}  // namespace

std::unique_ptr<ContactLaw> make_convex_hertz_law(const Pair& pair, const convex::Curvatures& curvatures) {
  return std::make_unique<ConvexHertzLaw>(pair, curvatures);
}

}  // namespace bounce::contact
