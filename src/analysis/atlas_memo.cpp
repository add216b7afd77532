// The atlas build's cache file (atlas_memo.hpp): one line per result, hexadecimal floats
// (exact), flushed as each result arrives. A line cut by an interrupt is ignored on reading.
#include "atlas_memo.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bounce/core/error.hpp"

namespace bounce::analysis::detail {

namespace {

constexpr const char* magic = "bounce-atlas-cache 1";

bool read_hex(std::istringstream& in, double& x) {
  std::string word;
  if (!(in >> word)) return false;
  char* end = nullptr;
  x = std::strtod(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size();
}

std::string key_text(const AtlasMemo::Key& k) { return fmt::format("{:a} {:a} {:a}", k[0], k[1], k[2]); }

}  // namespace

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 14695981039346656037ULL;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
  return h;
}

AtlasMemo::AtlasMemo(std::string path, std::uint64_t fingerprint, bool writes) : path_(std::move(path)) {
  if (path_.empty()) return;
  bool cut = false;
  const std::string header = fmt::format("{} {:016x}", magic, fingerprint);
  if (std::ifstream in(path_); in) {
    std::string line;
    std::getline(in, line);
    if (line != header) {
      throw InvalidArgument("cache", path_,
                            "the cache of this very build (it was written by another build, or another bounce "
                            "version: delete it, or give the options it was started with)");
    }
    while (std::getline(in, line)) {
      parse(line);
      if (line.starts_with("w ")) seen_warnings_.insert(line);
      new_lines_ += line + "\n";  // shared with the other processes at the start (MPI)
    }
    cut = !line.empty();  // the last line has no newline: an interrupt cut it
  } else if (writes) {
    std::ofstream(path_) << header << '\n';
  }
  if (!writes) return;
  file_ = std::fopen(path_.c_str(), "a");
  if (file_ == nullptr) {
    throw InvalidArgument("cache", path_, fmt::format("a file bounce can write ({})", std::strerror(errno)));
  }
  if (cut) std::fputs("\n", file_);  // the next result on a line of its own
}

AtlasMemo::~AtlasMemo() {
  if (file_ != nullptr) std::fclose(file_);
}

void AtlasMemo::parse(const std::string& line) {
  std::istringstream in(line);
  char kind = 0;
  Key k{};
  if (!(in >> kind) || !read_hex(in, k[0]) || !read_hex(in, k[1]) || !read_hex(in, k[2])) return;
  if (kind == 'c') {
    AtlasCollision c;
    int sticks = 0;
    std::string end;
    if (!(in >> sticks) || !read_hex(in, c.cor) || !read_hex(in, c.contact_time) || !read_hex(in, c.bulk_fraction) ||
        !read_hex(in, c.crack_fraction) || !(in >> end) || end != ";") {
      return;  // cut by an interrupt
    }
    c.sticks = sticks != 0;
    collisions_[k] = c;
  } else if (kind == 's') {
    AtlasThreshold t;
    int defined = 0;
    std::string end;
    if (!(in >> defined) || !read_hex(in, t.velocity) || !(in >> end) || end != ";") return;
    t.defined = defined != 0;
    thresholds_[k] = t;
  } else if (kind == 'w') {
    std::string rest;
    std::getline(in, rest);
    if (rest.size() > 3 && rest.ends_with(" ;")) warnings_.add(k[2], {rest.substr(1, rest.size() - 3)});
  }
}

void AtlasMemo::add_line(const std::string& line, bool fresh) {
  // mutex_ held by the caller
  if (fresh) {
    new_lines_ += line;
    ++computed_;
  }
  if (file_ != nullptr) {
    std::fputs(line.c_str(), file_);
    std::fflush(file_);
  }
}

std::optional<AtlasCollision> AtlasMemo::collision(const Key& k) const {
  const std::lock_guard lock(mutex_);
  const auto it = collisions_.find(k);
  if (it == collisions_.end()) return std::nullopt;
  return it->second;
}

std::optional<AtlasThreshold> AtlasMemo::threshold(const Key& k) const {
  const std::lock_guard lock(mutex_);
  const auto it = thresholds_.find(k);
  if (it == thresholds_.end()) return std::nullopt;
  return it->second;
}

void AtlasMemo::put(const Key& k, const AtlasCollision& c, const std::vector<std::string>& warnings) {
  const std::lock_guard lock(mutex_);
  collisions_[k] = c;
  std::string line = fmt::format("c {} {} {:a} {:a} {:a} {:a} ;\n", key_text(k), c.sticks ? 1 : 0, c.cor,
                                 c.contact_time, c.bulk_fraction, c.crack_fraction);
  for (const std::string& w : warnings) {
    std::string one = w;
    for (char& ch : one) ch = ch == '\n' ? ' ' : ch;
    const std::string warning = fmt::format("w {} {} ;", key_text(k), one);
    seen_warnings_.insert(warning);
    line += warning + "\n";
  }
  warnings_.add(k[2], warnings);
  add_line(line, true);
}

void AtlasMemo::put(const Key& k, const AtlasThreshold& t) {
  const std::lock_guard lock(mutex_);
  thresholds_[k] = t;
  add_line(fmt::format("s {} {} {:a} ;\n", key_text(k), t.defined ? 1 : 0, t.velocity), true);
}

std::string AtlasMemo::take_new() {
  const std::lock_guard lock(mutex_);
  return std::exchange(new_lines_, {});
}

void AtlasMemo::merge(const std::string& lines) {
  std::istringstream in(lines);
  std::string line;
  const std::lock_guard lock(mutex_);
  while (std::getline(in, line)) {
    const std::size_t before = collisions_.size() + thresholds_.size();
    const bool warning = line.starts_with("w ") && seen_warnings_.insert(line).second;
    parse(line);
    // Another rank's result: into this rank's file too (rank 0 keeps the cache).
    if (collisions_.size() + thresholds_.size() != before || warning) add_line(line + "\n", false);
  }
}

std::size_t AtlasMemo::computed() const {
  const std::lock_guard lock(mutex_);
  return computed_;
}

std::vector<std::string> AtlasMemo::warnings() const {
  const std::lock_guard lock(mutex_);
  return warnings_.list();
}

}  // namespace bounce::analysis::detail
