// The subcommands: each hands the options to the front door and prints what it returns
// (JSON, CSV or text). The physics and every check are in the library.
#include "commands.hpp"

#include <iostream>
#include <optional>
#include <iterator>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "batch.hpp"
#include "interrupt.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "stream.hpp"
#include "text.hpp"

namespace bounce::cli {

namespace {

std::string model_of(const std::string& command, const api::Inputs& in) {
  const auto it = in.find("model");
  return it == in.end() ? api::default_model(api::command(command)) : std::get<std::string>(it->second);
}

// At most one output format.
void one_format(const Options& o, std::initializer_list<const char*> formats) {
  const char* first = nullptr;
  for (const char* f : formats) {
    if (!o.given(f)) continue;
    if (first) {
      throw InvalidArgument(f, o.typed(f), fmt::format("one output format: {} or {}, not both", option_name(first), option_name(f)));
    }
    first = f;
  }
}

std::string read_file(const std::string& option, const std::string& path, const std::string& what) {
  if (path == "-") return {std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
  return read_text_file(option, path, what);
}

using Setup = std::function<std::function<int()>(Options&)>;

std::string interrupted_note(std::size_t points) {
  return fmt::format("Ctrl-C (SIGINT) after {} points: the points computed so far; the boundaries were not searched",
                     points);
}

std::function<int()> materials(Options& o) {
  const bool* json = o.add_flag("json", "print JSON");
  return [&o, json] {
    const Value m = api::materials(o.inputs());
    *json ? print_json(m) : print_text(m, materials_text(m));
    return 0;
  };
}

std::function<int()> models(Options& o) {
  const bool* json = o.add_flag("json", "print JSON");
  const bool* markdown = o.add_flag("markdown", "print the Markdown tables of docs/models.md");
  return [&o, json, markdown] {
    one_format(o, {"json", "markdown"});
    const Value registry = api::models();
    if (*json) {
      print_json(registry);
    } else {
      print_text(registry, *markdown ? models_markdown(registry) : models_text(registry));
    }
    return 0;
  };
}

std::function<int()> contact(Options& o) {
  const bool* json = o.add_flag("json", "print JSON");
  const bool* csv = o.add_flag("csv", "print a CSV curve (needs one range: --forces, --overlaps or --contact-radii)");
  return [&o, json, csv] {
    one_format(o, {"json", "csv"});
    const api::Inputs in = o.inputs();
    const char* range = nullptr;
    for (const char* name : {"forces", "overlaps", "contact_radii"}) {
      if (in.count(name)) range = name;
    }
    if (*csv && range == nullptr) {
      throw InvalidArgument("csv", "given", "one range with it: --forces, --overlaps or --contact-radii LO:HI:N");
    }
    if (!*csv && range != nullptr) {
      throw InvalidArgument(range, std::get<std::string>(in.at(range)), "--csv with a range (it prints a CSV curve)");
    }
    if (*csv) {
      CsvStream rows;
      api::contact_curve(in, [&rows](const Table& row) { rows.write(row); });
      return 0;
    }
    const Record out = api::contact(in);
    *json ? print_json(out) : print_text(out, contact_text(out));
    return 0;
  };
}

std::function<int()> collide(Options& o) {
  const bool* json = o.add_flag("json", "print JSON");
  const bool* csv = o.add_flag("csv", "with --trajectory: print the trajectory as CSV");
  return [&o, json, csv] {
    one_format(o, {"json", "csv"});
    const api::Inputs in = o.inputs();
    if (*csv && !in.count("trajectory")) throw InvalidArgument("csv", "given", "--trajectory with --csv (the trajectory as CSV)");
    const Record out = api::collide(in);
    if (*csv) {  // CSV has no place for the notes (a thinned trajectory) and warnings: stderr
      print_csv(out.at("trajectory").table());
      for (const Value& note : out.at("notes").list()) std::cerr << "bounce: note: " << note.text() << '\n';
      print_warnings(out);
    } else {
      *json ? print_json(out) : print_text(out, collide_text(out));
    }
    return 0;
  };
}

// A curve's JSON: the points wait in a temporary file for the boundaries, which sort first. A
// Ctrl-C before the end closes the document with the points computed so far ("boundaries": null
// and "interrupted" saying why), exit 130.
int curve_json(const api::Inputs& inputs, Progress& report) {
  JsonSpool points;
  std::optional<Record> rest;
  {
    DeferredInterrupt hold;
    try {
      rest = api::curve(inputs, [&](const Record& p) { points.add(p, 1); check_interrupt(); }, std::ref(report));
    } catch (const Interrupted&) {
    }
  }
  if (rest) require_finite(*rest);
  std::cout << "{\n  \"boundaries\": ";
  if (rest) {
    write_json(std::cout, rest->at("boundaries"), 1);
  } else {
    std::cout << "null,\n  \"interrupted\": " << nlohmann::json(interrupted_note(points.size())).dump();
  }
  std::cout << ",\n  \"points\": ";
  points.print_list(std::cout, 1);
  std::cout << "\n}\n";
  if (rest) return 0;
  std::cerr << fmt::format("bounce: interrupted (SIGINT): the {} points computed so far are printed as a whole JSON "
                           "document (\"interrupted\" says so)\n", points.size());
  return 130;
}

std::function<int()> curve(Options& o) {
  const bool* json = o.add_flag("json", "print JSON");
  o.add_flag("csv", "print CSV (the default)");
  const bool* progress = o.add_flag("progress", "report progress on stderr (automatic on a terminal)");
  return [&o, json, progress] {
    one_format(o, {"json", "csv"});
    Progress report("bounce curve", *progress);
    if (*json) return curve_json(o.inputs(), report);
    CsvStream rows;  // each row written as it is computed; CSV has no place for the boundaries
    WarningTally warnings;
    api::curve(
        o.inputs(),
        [&](const Record& p) {
          rows.write(api::curve_table(Record().set("points", Value::List{p})));
          warnings.add(p);
        },
        std::ref(report), false);
    warnings.print();
    return 0;
  };
}

std::function<int()> analytic(Options& o) {
  const bool* json = o.add_flag("json", "print JSON");
  return [&o, json] {
    const Record out = api::analytic(o.inputs());
    *json ? print_json(out) : print_text(out, analytic_text(out));
    return 0;
  };
}

std::function<int()> sticking(Options& o) {
  const bool* json = o.add_flag("json", "print JSON");
  const bool* progress = o.add_flag("progress", "report progress on stderr (automatic on a terminal)");
  return [&o, json, progress] {
    const api::Inputs in = o.inputs();
    if (!in.count("radii")) {
      const Record out = api::sticking(in);
      *json ? print_json(out) : print_text(out, sticking_text(out, model_of("sticking", in)));
      return 0;
    }
    Progress report("bounce sticking", *progress);
    if (*json) {  // a Ctrl-C closes the list after the radii done (exit 130)
      JsonListStream rows;
      bool interrupted = false;
      {
        DeferredInterrupt hold;
        try {
          api::sticking_over_radii(in, [&rows](const Record& r) { rows.add(r); check_interrupt(); }, std::ref(report));
        } catch (const Interrupted&) {
          interrupted = true;
        }
      }
      rows.close();
      if (interrupted) std::cerr << "bounce: interrupted (SIGINT): the radii done so far are printed as a whole JSON list\n";
      return interrupted ? 130 : 0;
    }
    CsvStream rows;
    WarningTally warnings;
    api::sticking_over_radii(
        in,
        [&](const Record& r) {
          rows.write(api::sticking_table(Value::List{r}));
          warnings.add(r);
        },
        std::ref(report));
    warnings.print();
    return 0;
  };
}

std::function<int()> rules(Options& o) {
  const std::string* input = o.add_text("input", "JSON file of encounters (default -: standard input)", "FILE");
  return [&o, input] {
    const std::string path = o.given("input") ? *input : "-";
    const std::string text = read_file("input", path, "a readable JSON file (or - for standard input)");
    try {
      print_json(api::rules(o.inputs(), text));
    } catch (const InvalidArgument& e) {
      const std::string shown = path == "-" ? "(standard input)" : path;
      if (e.parameter() == "encounters") throw InvalidArgument("input", shown, e.allowed());
      if (o.all_names().count(e.parameter())) throw;
      throw e.renamed(fmt::format("{}: {}", shown, e.parameter()));  // a field of the file
    }
    return 0;
  };
}

int write_table(const Options& o, const std::string& prefix, const auto& table) {
  const std::string json = table.to_json();
  if (o.given("json")) print_text(json + '\n', json);
  if (o.given("csv")) print_text(table.to_csv(), json);
  if (o.given("c_header")) print_text(table.to_c_header(prefix), json);
  print_warnings(table.warnings);
  return 0;
}

std::function<int()> table(Options& o) {
  o.add_flag("json", "write the table as JSON (read back by --load)");
  o.add_flag("csv", "write the table's nodes as CSV");
  const std::string* prefix = o.add_text("c_header", "write a self-contained C99 header; PREFIX names its symbols", "PREFIX");
  const std::string* load = o.add_text("load", "read a JSON table and print its value at --velocity", "FILE");
  const bool* progress = o.add_flag("progress", "report progress on stderr (automatic on a terminal)");
  return [&o, prefix, load, progress] {
    if (o.given("load")) {
      const std::string text = read_file("load", *load, "a readable JSON file written by bounce table --json");
      const Record out = [&] {
        try {
          return api::table_value(text, o.inputs());
        } catch (const InvalidArgument& e) {  // the file named as typed
          if (e.parameter() != "load") throw;
          throw InvalidArgument("load", *load, e.allowed());
        }
      }();
      o.given("json") ? print_json(out) : print_text(out, table_value_text(out));
      return 0;
    }
    one_format(o, {"json", "csv", "c_header"});
    if (!o.given("json") && !o.given("csv") && !o.given("c_header")) {
      throw InvalidArgument("output format", "(none given)", "one of --json, --csv, --c-header PREFIX");
    }
    Progress report("bounce table", *progress);
    const auto t = api::table(o.inputs(), std::ref(report));
    return std::visit([&](const auto& built) { return write_table(o, *prefix, built); }, t);
  };
}

int fit_batch(const Options& o, const std::string& manifest, const std::string* checkpoint, bool json, bool progress) {
  for (const auto& [name, value] : o.inputs()) {
    throw InvalidArgument(name, value_text(value), "none with --batch: each experiment's options are in the manifest");
  }
  if (o.given("data")) throw InvalidArgument("data", o.typed("data"), "none with --batch (the manifest names the data)");
  const BatchResult r = run_batch(manifest, o.given("checkpoint") ? std::optional(*checkpoint) : std::nullopt, progress);
  if (!r.printer) return 0;  // rank 0 prints, and raised any error
  if (json) {
    print_json(r.record);
  } else {
    std::string text;
    for (const Value& e : r.record.at("experiments").list()) {
      text += fmt::format("== {}\n{}", e.record().at("name").text(), fit_text(e.record()));
    }
    print_text(r.record, text);
  }
  return 0;
}

std::function<int()> fit(Options& o) {
  const std::string* data = o.add_text(
      "data",
      "CSV of the measured restitution curve: a header naming the columns velocity [m/s], cor and optionally "
      "cor_error, outcome (bounce|stick), any case, a unit in brackets; comma, tab or semicolon separated "
      "(docs/fitting.md; - for standard input)",
      "FILE");
  const std::string* columns = o.add_text(
      "columns", "the file's names of the columns, e.g. velocity=Speed,cor=e,cor_error=sigma (with --data)", "MAP");
  const std::string* batch = o.add_text("batch", "TOML manifest of experiments to fit (mpirun -np N: over N ranks)", "FILE");
  const std::string* checkpoint = o.add_text("checkpoint", "with --batch: keep finished grid blocks in DIR, reuse them", "DIR");
  const std::string* plot = o.add_text(
      "plot", "also write the fit's figure (K13 Fig 6) to FILE.png, .svg or .pdf (drawn by /usr/bin/python3 with "
              "matplotlib)", "FILE");
  const bool* json = o.add_flag("json", "print JSON");
  const bool* progress = o.add_flag("progress", "report progress on stderr (automatic on a terminal)");
  return [&o, data, columns, batch, checkpoint, plot, json, progress] {
    if (o.given("batch")) {
      if (o.given("columns")) throw InvalidArgument("columns", *columns, "--data with it (a manifest's experiment has its own columns key)");
      if (o.given("plot")) throw InvalidArgument("plot", *plot, "--data with it (one fit's figure; a batch: bounce.plot.batch_summary)");
      return fit_batch(o, *batch, checkpoint, *json, *progress);
    }
    if (o.given("checkpoint")) throw InvalidArgument("checkpoint", *checkpoint, "--batch with it (a batch's blocks)");
    if (!o.given("data")) throw InvalidArgument("data", "(not given)", "a CSV file of velocity,cor[,cor_error][,outcome]");
    const std::string text = read_file("data", *data, "a readable CSV file (or - for standard input)");
    const analysis::ColumnNames names = o.given("columns") ? analysis::parse_column_names(*columns) : analysis::ColumnNames{};
    const analysis::Experiment experiment =
        analysis::parse_experiment(text, *data == "-" ? "(standard input)" : *data, names);
    if (!*json && o.inputs().count("chi2_grid")) {
      throw InvalidArgument("chi2_grid", "given", "--json with it (the whole chi^2 grid is printed as JSON only)");
    }
    if (o.given("plot")) check_plot(*plot);  // before a fit of minutes
    Progress report("bounce fit", *progress);
    const Record out = api::fit(o.inputs(), experiment, std::ref(report));
    *json ? print_json(out) : print_text(out, fit_text(out));
    if (o.given("plot")) write_plot(*plot, to_json(out).dump());
    return 0;
  };
}

std::function<int()> lammps(Options& o) {
  const bool* json = o.add_flag("json", "print JSON");
  return [&o, json] {
    const Record out = api::lammps_export(o.inputs());
    *json ? print_json(out) : print_text(out, std::get<std::string>(out.at("script").data()));
    return 0;
  };
}

const std::map<std::string, Setup>& setups() {
  static const std::map<std::string, Setup> table = {
      {"materials", materials}, {"models", models},     {"contact", contact},   {"collide", collide}, {"curve", curve},
      {"analytic", analytic},   {"sticking", sticking}, {"rules", rules},       {"table", ::bounce::cli::table},
      {"fit", ::bounce::cli::fit},  {"lammps", lammps}};
  return table;
}

}  // namespace

Command add_command(CLI::App& root, const api::CommandSpec& spec) {
  Command c;
  c.app = root.add_subcommand(spec.name, spec.summary);
  c.options = std::make_unique<Options>(c.app, spec);
  c.run = setups().at(spec.name)(*c.options);
  return c;
}

}  // namespace bounce::cli
