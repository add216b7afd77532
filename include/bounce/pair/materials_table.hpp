#pragma once
// The materials table: the built-in one (data/materials.toml, compiled into the
// library) and user files in the same TOML format.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "bounce/pair/material.hpp"

namespace bounce {

class MaterialTable {
 public:
  /// The built-in table: K13 table 2 plus `ice-bshp96` (docs/materials.md).
  static const MaterialTable& builtin();
  /// Parse a TOML file; every entry is validated. Throws InvalidArgument naming
  /// the file, entry and key on any malformed, partial or out-of-range entry.
  static MaterialTable from_file(const std::filesystem::path& path);
  /// Same as from_file, for text already in memory; `origin` names it in errors.
  static MaterialTable from_toml(std::string_view text, std::string_view origin);

  /// This table with a user's added: an entry of `user` replaces the one of the same name, the
  /// others are appended (what --materials-file does to the built-in table).
  MaterialTable with(const MaterialTable& user) const;

  /// The material called `name`; throws InvalidArgument("material", name, "one of …").
  const Material& at(std::string_view name) const;
  bool contains(std::string_view name) const;
  const std::vector<Material>& materials() const noexcept { return materials_; }
  std::vector<std::string> names() const;

 private:
  std::vector<Material> materials_;
};

}  // namespace bounce
