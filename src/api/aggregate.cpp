// The front door's aggregates (docs/aggregates.md).
#include "bounce/api/aggregate.hpp"

#include <fmt/format.h>

#include "bounce/core/error.hpp"
#include "bounce/pair/materials_table.hpp"

namespace bounce::api {

namespace {

Record fit_record(const aggregate::FractalFit& f, const char* over) {
  return Record()
      .set("dimension", f.dimension)
      .set("prefactor", f.prefactor)
      .set("n_min", f.n_min)
      .set("n_max", f.n_max)
      .set("points", f.points)
      .set("over", over);
}

}  // namespace

AggregateJob aggregate_job(const Inputs& inputs) {
  const Parameters own = bind_parameters(aggregate_commands().front().parameters, inputs, "bounce aggregate build");
  AggregateJob job;
  job.request.kind = own.text("kind") == "bcca" ? aggregate::Kind::bcca : aggregate::Kind::bpca;
  const double n = own.require_real("n", fmt::format("number of monomers n, 1 to {}", aggregate::max_monomers));
  job.request.n = static_cast<std::size_t>(n);
  if (job.request.kind == aggregate::Kind::bcca && (job.request.n & (job.request.n - 1)) != 0) {
    throw InvalidArgument("n", own.typed("n"), "a power of 2 for bcca (clusters join in equal pairs: 2, 4, ..., 1024, ...)");
  }
  job.request.radius = own.require_real("radius", "monomer radius r [m] > 0 and finite");
  job.request.seed = static_cast<std::uint64_t>(*own.real("seed"));
  job.ensemble = static_cast<std::size_t>(*own.real("ensemble"));
  const std::size_t fewest = aggregate::min_fit_monomers(job.request.kind);
  if (job.ensemble > 0 && job.request.n < fewest) {
    throw InvalidArgument("ensemble", own.typed("ensemble"),
                          fmt::format("0 below {} monomers for {} (too little growth to fit D)", fewest,
                                      aggregate::kind_name(job.request.kind)));
  }
  if (own.given("material")) {
    job.material = own.text("material");
    job.density = MaterialTable::builtin().at(job.material).density;
  }
  if (own.given("density")) job.density = *own.real("density");
  if (!own.given("material") && !own.given("density")) {
    throw InvalidArgument("material", "(not given)", "a material name (bounce materials) or --density KG_M3");
  }
  return job;
}

Record aggregate_record(const AggregateJob& job, const aggregate::Aggregate& built,
                        const std::optional<aggregate::FractalFit>& ensemble) {
  const aggregate::Structure s = aggregate::structure(built);
  Record out;
  out.set("kind", aggregate::kind_name(job.request.kind)).set("n", job.request.n);
  out.set("radius", job.request.radius).set("seed", job.request.seed);
  out.set("material", job.material.empty() ? Value(nullptr) : Value(job.material)).set("density", job.density);
  out.set("radius_of_gyration", s.radius_of_gyration).set("contacts", s.contacts);
  out.set("coordination", s.coordination).set("filling_factor", s.filling_factor);
  out.set("min_distance", job.request.n > 1 ? Value(s.min_distance) : Value(nullptr));
  out.set("fractal_dimension", s.fit ? Value(fit_record(*s.fit, "growth history of this aggregate")) : Value(nullptr));
  if (ensemble) out.set("ensemble", fit_record(*ensemble, "geometric mean R_g over the ensemble's aggregates"));
  return out;
}

std::string aggregate_title(const AggregateJob& job) {
  return fmt::format("LAMMPS data file (atom_style sphere, units si): bounce aggregate build --kind {} --n {} "
                     "--radius {} --seed {}{} --density {}",
                     aggregate::kind_name(job.request.kind), job.request.n, job.request.radius, job.request.seed,
                     job.material.empty() ? "" : " --material " + job.material, job.density);
}

}  // namespace bounce::api
