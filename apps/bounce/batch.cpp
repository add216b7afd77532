// The batch of fits over MPI ranks (docs/fitting.md). Every rank reads the manifest and
// prepares every fit (cheap); the grids' points are cut into blocks of a fixed size, block u
// of the batch runs on rank u mod N (or is read back from the checkpoint), rank 0 gathers
// the blocks in order and finishes each fit. A grid point's numbers do not depend on where it
// ran, so the output is the same for any number of ranks, and after a restart.
#include "batch.hpp"

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "bounce/api/front_door.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "mpi.hpp"
#include "output.hpp"


namespace bounce::cli {

namespace {

// Points per block: ~60 K13 collisions x 30 speeds, a few seconds; independent of the ranks,
// so that a checkpoint written with N ranks serves a restart with M.
constexpr std::size_t block_size = 60;

struct Unit {
  std::size_t entry, first, count, index;
};

// FNV-1a over what fixes a fit's grid points: the entry's inputs, data and grid. A
// checkpoint of another manifest (or an edited one) is refused, not mixed in.
std::uint64_t fingerprint(const api::BatchEntry& e, const api::FitJob& job) {
  std::string text = e.name;
  for (const auto& [key, value] : e.inputs) text += fmt::format("|{}={}", key, value_text(value));
  for (const auto& m : job.problem().data.points) text += fmt::format("|{:a},{:a}", m.velocity, m.cor);
  for (const auto& axis : job.problem().collision_axes) {
    text += "|" + axis.name;
    for (double v : axis.values) text += fmt::format(",{:a}", v);
  }
  std::uint64_t h = 14695981039346656037ULL;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
  return h;
}

// A block as text: exact (hexadecimal floats), the same in a checkpoint file and a message.
std::string serialise(std::uint64_t print, const Unit& u, const std::vector<analysis::GridPoint>& points) {
  std::string s = fmt::format("bounce-fit-block 1 {:016x} {} {}\n", print, u.first, u.count);
  for (const auto& p : points) {
    s += fmt::format("{} {:a} {:a} {:a} {}", p.failure.empty() ? 'p' : 'f', p.radius, p.mass, p.modulus, p.cor.size());
    for (double c : p.cor) s += fmt::format(" {:a}", c);
    std::string why = p.failure;
    for (char& c : why) c = c == '\n' ? ' ' : c;
    s += p.failure.empty() ? "\n" : " " + why + "\n";
  }
  return s;
}

double hex_number(std::istringstream& in) {
  std::string word;
  in >> word;
  char* end = nullptr;
  const double x = std::strtod(word.c_str(), &end);
  if (word.empty() || end != word.c_str() + word.size()) throw std::runtime_error("bad number " + word);
  return x;
}

// The block back, or none when the text is not this block of this fit (another manifest).
std::optional<std::vector<analysis::GridPoint>> deserialise(const std::string& text, std::uint64_t print, const Unit& u) {
  std::istringstream in(text);
  std::string tag, version, stored;
  std::size_t first = 0, count = 0;
  in >> tag >> version >> stored >> first >> count;
  if (tag != "bounce-fit-block" || version != "1" || stored != fmt::format("{:016x}", print) || first != u.first ||
      count != u.count) {
    return std::nullopt;
  }
  std::vector<analysis::GridPoint> points(count);
  try {
    for (auto& p : points) {
      char kind = 0;
      std::size_t n = 0;
      in >> kind;
      p.radius = hex_number(in), p.mass = hex_number(in), p.modulus = hex_number(in);
      in >> n;
      for (std::size_t k = 0; k < n; ++k) p.cor.push_back(hex_number(in));
      if (kind == 'f') std::getline(in >> std::ws, p.failure);
      if (!in || (kind != 'p' && kind != 'f')) return std::nullopt;
    }
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
  return points;
}

std::filesystem::path block_file(const std::string& dir, const Unit& u) {
  return std::filesystem::path(dir) / fmt::format("experiment-{}-points-{}.block", u.entry + 1, u.first);
}

// A finished block from the checkpoint directory, if there is one of this fit.
std::optional<std::vector<analysis::GridPoint>> load(const std::optional<std::string>& dir, std::uint64_t print,
                                                     const Unit& u) {
  if (!dir) return std::nullopt;
  std::ifstream file(block_file(*dir, u));
  if (!file) return std::nullopt;
  std::stringstream text;
  text << file.rdbuf();
  auto points = deserialise(text.str(), print, u);
  if (!points) {
    throw InvalidArgument("checkpoint", block_file(*dir, u).string(),
                          "a block of this manifest's fits (the manifest or its data changed: use an empty directory)");
  }
  return points;
}

// Written to a temporary name, then renamed: a killed process leaves whole blocks only.
void save(const std::string& dir, const Unit& u, const std::string& text) {
  const auto path = block_file(dir, u);
  const auto temporary = path.string() + ".part";
  {
    std::ofstream file(temporary);
    file << text;
    if (!file) throw NumericalError(fmt::format("could not write the checkpoint {}", temporary));
  }
  std::filesystem::rename(temporary, path);
}


#ifdef BOUNCE_HAVE_MPI
// An error as text that rank 0 raises again as the same kind, with the same fields, so that
// an error met on another rank alone is printed and exits as it would have on rank 0.
constexpr char field_end = '\0';

std::string describe(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const InvalidArgument& x) {
    return fmt::format("i{}{}{}{}{}", x.parameter(), field_end, x.value(), field_end, x.allowed());
  } catch (const NumericalError& x) {
    return fmt::format("n{}", x.what());
  } catch (const std::exception& x) {
    return fmt::format("x{}", x.what());
  } catch (...) {
    return "xan unknown exception";
  }
}

std::exception_ptr revive(const std::string& text, int rank) {
  const std::string body = text.substr(1);
  if (text.front() == 'i') {
    const auto a = body.find(field_end), b = body.find(field_end, a + 1);
    return std::make_exception_ptr(InvalidArgument(body.substr(0, a), body.substr(a + 1, b - a - 1), body.substr(b + 1)));
  }
  const std::string where = fmt::format("{} (on MPI rank {})", body, rank);
  if (text.front() == 'n') return std::make_exception_ptr(NumericalError(where));
  return std::make_exception_ptr(std::runtime_error(where));
}
#endif

struct Batch {
  std::vector<api::BatchEntry> entries;
  std::vector<api::FitJob> jobs;
  std::vector<std::uint64_t> prints;
  std::vector<Unit> units;
};

Batch prepare(const std::string& manifest) {
  const std::string text = read_text_file("batch", manifest, "a readable TOML manifest (docs/fitting.md)");
  Batch b;
  b.entries = api::read_fit_manifest(text, manifest, std::filesystem::path(manifest).parent_path().string());
  for (std::size_t e = 0; e < b.entries.size(); ++e) {
    std::size_t n = 0;
    try {
      b.jobs.emplace_back(b.entries[e].inputs, b.entries[e].data);
      n = b.jobs.back().grid_points();
    } catch (const InvalidArgument& error) {
      throw error.renamed(fmt::format("{}: {}: {}", manifest, b.entries[e].name, error.parameter()));
    }
    b.prints.push_back(fingerprint(b.entries[e], b.jobs.back()));
    for (std::size_t first = 0; first < n; first += block_size) {
      b.units.push_back({e, first, std::min(block_size, n - first), b.units.size()});
    }
  }
  return b;
}

}  // namespace

namespace {

// This rank's blocks, as text, in unit order: read from the checkpoint or integrated (and then
// saved); `loaded` counts those read.
std::vector<std::string> compute_mine(const Batch& b, const Mpi& mpi, const std::optional<std::string>& checkpoint,
                                      bool progress, long& loaded) {
  std::vector<std::string> mine;
  if (checkpoint) std::filesystem::create_directories(*checkpoint);
  Progress report("bounce fit --batch", progress && mpi.rank == 0);
  for (const Unit& u : b.units) {
    if (static_cast<int>(u.index % static_cast<std::size_t>(mpi.size)) != mpi.rank) continue;
    auto points = load(checkpoint, b.prints[u.entry], u);
    const bool computed = !points;
    loaded += computed ? 0 : 1;
    if (computed) points = b.jobs[u.entry].integrate(u.first, u.count);
    mine.push_back(serialise(b.prints[u.entry], u, *points));
    if (computed && checkpoint) save(*checkpoint, u, mine.back());
    report(u.index + 1, b.units.size());
  }
  return mine;
}

// The lowest rank that failed speaks for the batch, through rank 0: one message, whichever
// ranks met it. The other ranks return quietly with exit code 0: OpenMPI's mpirun ends the
// whole job as soon as one process exits non-zero, which could kill rank 0 before it has
// printed the message. The job's exit code is rank 0's. Returns whether a rank failed (rank 0
// then throws).
bool failed_somewhere(Mpi& mpi, std::exception_ptr error) {
  const int first = mpi.min(error ? mpi.rank : mpi.size);
  if (first >= mpi.size) return false;
#ifdef BOUNCE_HAVE_MPI
  // No block has been sent yet, so tag 0 cannot meet one.
  if (mpi.rank == first && first != 0) mpi.send(describe(error), 0);
  if (mpi.rank == 0 && first != 0) error = revive(mpi.receive(first, 0), first);
#endif
  if (mpi.rank == 0) std::rethrow_exception(error);
  return true;
}

// Rank 0: every block in unit order, each experiment's grid points gathered.
std::vector<std::vector<analysis::GridPoint>> gather(const Batch& b, Mpi& mpi, const std::vector<std::string>& mine) {
  std::vector<std::vector<analysis::GridPoint>> points(b.entries.size());
  std::size_t k = 0;
  for (const Unit& u : b.units) {
    const int owner = static_cast<int>(u.index % static_cast<std::size_t>(mpi.size));
    std::string text;
#ifdef BOUNCE_HAVE_MPI
    text = owner == 0 ? mine[k++] : mpi.receive(owner, static_cast<int>(u.index));
#else
    (void)owner;
    text = mine[k++];
#endif
    auto block = deserialise(text, b.prints[u.entry], u);
    if (!block) throw std::logic_error("a block arrived damaged");
    points[u.entry].insert(points[u.entry].end(), block->begin(), block->end());
  }
  return points;
}

}  // namespace

BatchResult run_batch(const std::string& manifest, const std::optional<std::string>& checkpoint, bool progress) {
  Mpi mpi;
  BatchResult result;
  result.printer = mpi.rank == 0;
  std::exception_ptr error;
  Batch b;
  std::vector<std::string> mine;
  long loaded = 0;
  try {
    b = prepare(manifest);
    mine = compute_mine(b, mpi, checkpoint, progress, loaded);
  } catch (...) {
    error = std::current_exception();
  }
  if (failed_somewhere(mpi, error)) return result;
  loaded = mpi.sum(loaded);
  if (checkpoint && mpi.rank == 0) {
    std::cerr << fmt::format("bounce fit --batch: {} of {} blocks read from the checkpoint {}\n", loaded, b.units.size(),
                             *checkpoint);
  }
#ifdef BOUNCE_HAVE_MPI
  if (mpi.rank != 0) {
    std::size_t k = 0;
    for (const Unit& u : b.units) {
      if (static_cast<int>(u.index % static_cast<std::size_t>(mpi.size)) == mpi.rank) mpi.send(mine[k++], static_cast<int>(u.index));
    }
    return result;
  }
#endif
  std::vector<std::vector<analysis::GridPoint>> points = gather(b, mpi, mine);
  Value::List experiments;
  for (std::size_t e = 0; e < b.entries.size(); ++e) {
    Record r = b.jobs[e].finish(std::move(points[e]));
    r.set("name", b.entries[e].name);
    experiments.push_back(std::move(r));
  }
  result.record.set("manifest", manifest).set("experiments", Value(std::move(experiments)));
  return result;
}

}  // namespace bounce::cli
