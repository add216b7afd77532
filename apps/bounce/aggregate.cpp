// `bounce aggregate build` (docs/aggregates.md): grows the aggregate through the front door,
// writes its LAMMPS data file (whole or not at all) and prints its structure.
#include "aggregate.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "bounce/api/aggregate.hpp"
#include "bounce/core/error.hpp"
#include "output.hpp"

namespace bounce::cli {

namespace {

// The file written beside its final name and renamed: a reader never sees half of it.
void write_file(const std::string& path, const std::string& text) {
  const std::filesystem::path target(path);
  const auto parent = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(parent, ec)) throw InvalidArgument("output", path, "a file in an existing folder");
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    out << text;
    if (!out.flush()) throw InvalidArgument("output", path, "a file that can be written");
  }
  std::filesystem::rename(partial, target, ec);
  if (ec) throw InvalidArgument("output", path, "a file that can be written (" + ec.message() + ")");
}

std::string summary_text(const Record& r, const std::string& path) {
  const Value& fit = r.at("fractal_dimension");
  const std::string dimension =
      fit.is_null() ? std::string("too few monomers to fit")
                    : fmt::format("{:.3f} (log R_g on log n over n = {:.0f} to {:.0f})",
                                  fit.record().at("dimension").number(), fit.record().at("n_min").number(),
                                  fit.record().at("n_max").number());
  std::string text = fmt::format(
      "{} aggregate of {:.0f} monomers of radius {:.4g} m (seed {:.0f})\n  R_g = {:.6g} m, {:.0f} contacts "
      "(coordination {:.4g}), filling factor {:.4g}\n  fractal dimension D = {}\n",
      r.at("kind").text(), r.at("n").number(), r.at("radius").number(), r.at("seed").number(),
      r.at("radius_of_gyration").number(), r.at("contacts").number(), r.at("coordination").number(),
      r.at("filling_factor").number(), dimension);
  if (r.contains("ensemble")) {
    text += fmt::format("  ensemble D = {:.3f}\n", r.at("ensemble").record().at("dimension").number());
  }
  return text + fmt::format("  written to {}\n", path);
}

std::function<int()> build(Options& o) {
  const std::string* output = o.add_text("output", "the LAMMPS data file to write", "FILE.data", "-o");
  const bool* json = o.add_flag("json", "print the aggregate's description as JSON");
  const bool* progress = o.add_flag("progress", "report progress on stderr (automatic on a terminal)");
  return [&o, output, json, progress] {
    const api::AggregateJob job = api::aggregate_job(o.inputs());
    if (!o.given("output")) throw InvalidArgument("output", "(not given)", "-o FILE.data, the LAMMPS data file to write");
    Progress report("bounce aggregate build", *progress);
    const aggregate::Aggregate built = aggregate::build(job.request, [&](std::size_t done, std::size_t total) {
      report(done, total);
    });
    std::optional<aggregate::FractalFit> ensemble;
    Progress samples("bounce aggregate build --ensemble (aggregates)", *progress);
    if (job.ensemble > 0) ensemble = aggregate::ensemble_fit(job.request, job.ensemble, samples);
    const Record r = api::aggregate_record(job, built, ensemble);
    const double margin = 4.0 * job.request.radius;  // docs/aggregates.md: the box 4r beyond the surfaces
    write_file(*output, aggregate::lammps_data(built, job.density, margin, api::aggregate_title(job)));
    *json ? print_json(r) : print_text(r, summary_text(r, *output));
    return 0;
  };
}

}  // namespace

std::vector<Command> add_aggregate_commands(CLI::App& root) {
  CLI::App* group = root.add_subcommand("aggregate", "Aggregates of grains: BPCA and BCCA, as LAMMPS data files");
  group->require_subcommand(1);
  std::vector<Command> out;
  for (const api::CommandSpec& spec : api::aggregate_commands()) {
    Command c;
    c.app = group->add_subcommand(spec.name.substr(spec.name.find(' ') + 1), spec.summary);
    c.options = std::make_unique<Options>(c.app, spec);
    c.run = build(*c.options);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace bounce::cli
