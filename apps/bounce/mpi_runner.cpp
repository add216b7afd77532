// The atlas build over MPI ranks (mpi_runner.hpp).
#include "mpi_runner.hpp"

#include <exception>
#include <memory>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "bounce/core/error.hpp"
#include "mpi.hpp"

namespace bounce::cli {

namespace {

// A job's failure on one rank becomes every rank's: its error travels with the results
// (a line "!" kind '\x1f' parameter '\x1f' value '\x1f' allowed), and each rank raises it
// again after the exchange, so that none waits forever for the others.
std::string describe(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const InvalidArgument& e) {
    return fmt::format("!I\x1f{}\x1f{}\x1f{}\n", e.parameter(), e.value(), e.allowed());
  } catch (const std::exception& e) {
    return fmt::format("!N\x1f{}\n", e.what());
  } catch (...) {
    return "!N\x1f" "an unexpected error\n";
  }
}

[[noreturn]] void raise(const std::string& line) {
  std::vector<std::string> parts;
  std::size_t from = 2;
  for (std::size_t at = line.find('\x1f', from); at != std::string::npos; at = line.find('\x1f', from)) {
    parts.push_back(line.substr(from, at - from));
    from = at + 1;
  }
  parts.push_back(line.substr(from));
  if (line[1] == 'I' && parts.size() == 4) throw InvalidArgument(parts[1], parts[2], parts[3]);
  throw NumericalError(parts.back());
}

}  // namespace

struct MpiRunner::Shared {
  Mpi mpi;
  std::exception_ptr error;
};

MpiRunner::MpiRunner() : shared_(std::make_shared<Shared>()), rank_(shared_->mpi.rank), size_(shared_->mpi.size) {}

MpiRunner::~MpiRunner() = default;

analysis::AtlasRunner MpiRunner::runner(unsigned threads) const {
  analysis::AtlasRunner r;
  r.writes_cache = rank_ == 0;  // and reads it: the others receive what it held (share)
  if (size_ == 1) return r;  // threads alone: the library's default
  const std::shared_ptr<Shared> s = shared_;
  const int rank = rank_, size = size_;
  r.distribute = [s, rank, size, threads](std::size_t count, const std::function<void(std::size_t)>& job) {
    std::vector<std::size_t> mine;
    for (std::size_t i = static_cast<std::size_t>(rank); i < count; i += static_cast<std::size_t>(size)) mine.push_back(i);
    std::mutex m;
    std::size_t next = 0;
    const unsigned workers = threads != 0 ? threads : std::max(1U, std::thread::hardware_concurrency());
    auto work = [&] {
      for (;;) {
        std::size_t i = 0;
        {
          const std::lock_guard lock(m);
          if (next >= mine.size() || s->error) return;
          i = mine[next++];
        }
        try {
          job(i);
        } catch (...) {
          const std::lock_guard lock(m);
          if (!s->error) s->error = std::current_exception();
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned w = 1; w < workers; ++w) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
  };
  r.share = [s](const std::string& lines, std::exception_ptr error) {
    if (!error) error = s->error;
    const std::string mine = error ? describe(error) + lines : lines;
    s->error = nullptr;
    const std::string all = s->mpi.allgather(mine);
    for (std::size_t at = all.find('!'); at != std::string::npos; at = all.find('!', at + 1)) {
      if (at == 0 || all[at - 1] == '\n') raise(all.substr(at, all.find('\n', at) - at));
    }
    return all;
  };
  return r;
}

}  // namespace bounce::cli
