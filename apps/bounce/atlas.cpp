// `bounce atlas build|query|export` (docs/atlas.md): the front door's atlas commands, the
// build's cache file (resume), its progress bar, and an atomic write that Ctrl-C cannot cut.
#include "atlas.hpp"

#include <csignal>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "bounce/api/atlas.hpp"
#include "bounce/core/error.hpp"
#include "mpi_runner.hpp"
#include "output.hpp"

namespace bounce::cli {

namespace {

// SIGINT held back while the atlas is written and renamed: an interrupt lands after it.
class HoldInterrupts {
 public:
  HoldInterrupts() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigprocmask(SIG_BLOCK, &set, &old_);
  }
  ~HoldInterrupts() { sigprocmask(SIG_SETMASK, &old_, nullptr); }
  HoldInterrupts(const HoldInterrupts&) = delete;
  HoldInterrupts& operator=(const HoldInterrupts&) = delete;

 private:
  sigset_t old_{};
};

std::string summary_text(const analysis::Atlas& a) {
  const analysis::AtlasErrors& e = a.errors;
  return fmt::format(
      "atlas of {} ({} nodes in R_eff, {} in rho_eff, {} in speed)\n"
      "  eps error <= {:.3g} (largest measured {:.3g} at {} collisions), {}\n",
      a.model, a.x.count, a.y.count, a.z.count, e.cor, e.cor_measured, e.check_points,
      a.can_stick ? fmt::format("v_stick relative error <= {:.3g}", e.v_stick) : std::string("the model cannot stick"));
}

std::function<int()> build(Options& o) {
  const std::string* output = o.add_text("output", "the atlas file to write (HDF5)", "FILE.h5", "-o");
  const bool* json = o.add_flag("json", "print the atlas's description as JSON");
  const bool* progress = o.add_flag("progress", "report progress on stderr (automatic on a terminal)");
  return [&o, output, json, progress] {
    const analysis::AtlasRequest request = api::atlas_request(o.inputs());
    if (!o.given("output")) throw InvalidArgument("output", "(not given)", "-o FILE.h5, the atlas file to write");
    const std::filesystem::path path(*output);
    const auto parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    if (!std::filesystem::is_directory(parent, ec)) {
      throw InvalidArgument("output", *output, "a file in an existing folder");
    }
    MpiRunner mpi;
    Progress report("bounce atlas build", *progress && mpi.rank() == 0);
    analysis::AtlasRunner runner = mpi.runner(request.threads);
    if (mpi.rank() == 0) runner.cache_path = *output + ".partial";
    runner.progress = [&](std::size_t done, const std::string&) { report(done, 0); };
    const analysis::Atlas atlas = analysis::build_atlas(request, runner);
    if (mpi.rank() != 0) return 0;
    {
      const HoldInterrupts hold;
      analysis::write_atlas(atlas, *output);
      std::filesystem::remove(*output + ".partial", ec);
    }
    const Record r = api::atlas_record(atlas);
    *json ? print_json(r) : print_text(r, summary_text(atlas) + fmt::format("  written to {}\n", *output));
    print_warnings(atlas.warnings);
    return 0;
  };
}

analysis::Atlas open_atlas(const std::string* file, const Options& o) {
  if (!o.given("atlas")) throw InvalidArgument("atlas", "(not given)", "an atlas file written by bounce atlas build");
  return analysis::read_atlas(*file);
}

std::function<int()> query(Options& o) {
  const std::string* file = o.add_positional("atlas", "the atlas file (HDF5)");
  const bool* json = o.add_flag("json", "print JSON");
  return [&o, file, json] {
    const analysis::Atlas atlas = open_atlas(file, o);
    const Record r = api::atlas_query(atlas, o.inputs());
    const Value& v_stick = r.at("v_stick");
    const std::string text =
        fmt::format("{} (eps = {:.6g} +- {:.2g}); v_stick = {}\n", r.at("outcome").text(), r.at("cor").number(),
                    atlas.errors.cor,
                    v_stick.is_null() ? std::string("none (sticks throughout)") : fmt::format("{:.8g} m/s", v_stick.number()));
    *json ? print_json(r) : print_text(r, text);
    return 0;
  };
}

std::function<int()> export_csv(Options& o) {
  const std::string* file = o.add_positional("atlas", "the atlas file (HDF5)");
  const bool* csv = o.add_flag("csv", "the grid as CSV (the default)");
  const bool* json = o.add_flag("json", "the atlas's description (model, parameters, ranges, errors) as JSON");
  return [&o, file, csv, json] {
    if (*csv && *json) throw InvalidArgument("json", "given", "either --csv or --json");
    const analysis::Atlas atlas = open_atlas(file, o);
    if (*json) {
      print_json(api::atlas_record(atlas));
    } else {
      std::cout << analysis::atlas_csv(atlas);
    }
    return 0;
  };
}

}  // namespace

std::vector<Command> add_atlas_commands(CLI::App& root) {
  CLI::App* atlas = root.add_subcommand("atlas", "Collision atlas: tables of eps, sticking and v_stick over radius and speed");
  atlas->require_subcommand(1);
  std::vector<Command> out;
  for (const api::CommandSpec& spec : api::atlas_commands()) {
    const std::string word = spec.name.substr(spec.name.find(' ') + 1);
    Command c;
    c.app = atlas->add_subcommand(word, spec.summary);
    c.options = std::make_unique<Options>(c.app, spec);
    c.run = word == "build" ? build(*c.options) : word == "query" ? query(*c.options) : export_csv(*c.options);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace bounce::cli
