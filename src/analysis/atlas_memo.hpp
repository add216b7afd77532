#pragma once
// Private: the atlas build's memory of what it computed (collisions and sticking velocities,
// keyed by their exact inputs), kept in a cache file line by line as results arrive, so that
// an interrupted build resumes where it stopped (docs/atlas.md, "Resume").

#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "table_common.hpp"

namespace bounce::analysis::detail {

/// What the atlas keeps of one collision.
struct AtlasCollision {
  bool sticks = false;
  double cor = 0.0, contact_time = 0.0, bulk_fraction = 0.0, crack_fraction = 0.0;
};

/// A sticking velocity: none when the grains stick up to the sound speed.
struct AtlasThreshold {
  bool defined = true;
  double velocity = 0.0;
};

class AtlasMemo {
 public:
  using Key = std::array<double, 3>;  // R1, R2, v (v = 0 for a threshold)

  /// Opens (and reads) the cache file; a file of another build (fingerprint) is refused.
  AtlasMemo(std::string path, std::uint64_t fingerprint, bool writes);
  ~AtlasMemo();
  AtlasMemo(const AtlasMemo&) = delete;
  AtlasMemo& operator=(const AtlasMemo&) = delete;

  std::optional<AtlasCollision> collision(const Key& k) const;
  std::optional<AtlasThreshold> threshold(const Key& k) const;
  void put(const Key& k, const AtlasCollision& c, const std::vector<std::string>& warnings);
  void put(const Key& k, const AtlasThreshold& t);

  /// The lines added (or read from the file) since the last call, for sharing among MPI ranks,
  /// and merging others'.
  std::string take_new();
  void merge(const std::string& lines);

  std::size_t computed() const;  ///< results added by this build (not read back)
  std::vector<std::string> warnings() const;

 private:
  void add_line(const std::string& line, bool fresh);
  void parse(const std::string& line);
  std::string path_;
  std::FILE* file_ = nullptr;
  mutable std::mutex mutex_;
  std::map<Key, AtlasCollision> collisions_;
  std::map<Key, AtlasThreshold> thresholds_;
  WarningLog warnings_;
  std::set<std::string> seen_warnings_;  ///< warning lines written or merged (each once)
  std::string new_lines_;
  std::size_t computed_ = 0;
};

/// FNV-1a of a text.
std::uint64_t fnv1a(const std::string& text);

}  // namespace bounce::analysis::detail
