// The atlas's C API (include/bounce/atlas.h): the library's Atlas behind an opaque handle,
// with no exception crossing into C.
#include "bounce/atlas.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "bounce/analysis/atlas.hpp"

struct bounce_atlas {
  bounce::analysis::Atlas atlas;
};

namespace {

void copy_message(const std::string& text, char* error, std::size_t size) {
  if (error == nullptr || size == 0) return;
  const std::size_t n = std::min(text.size(), size - 1);
  std::memcpy(error, text.data(), n);
  error[n] = '\0';
}

}  // namespace

extern "C" {

bounce_atlas* bounce_atlas_open(const char* path, const char* model, char* error, std::size_t error_size) {
  try {
    if (path == nullptr) throw std::invalid_argument("path = NULL is invalid: expected an atlas file");
    auto* handle = new bounce_atlas{bounce::analysis::read_atlas(path, model != nullptr ? model : "")};
    copy_message("", error, error_size);
    return handle;
  } catch (const std::exception& e) {
    copy_message(e.what(), error, error_size);
    return nullptr;
  } catch (...) {
    copy_message("bounce_atlas_open: an unexpected error", error, error_size);
    return nullptr;
  }
}

void bounce_atlas_close(bounce_atlas* atlas) { delete atlas; }

double bounce_atlas_cor(const bounce_atlas* atlas, double r1, double r2, double v) {
  return atlas->atlas.cor_unchecked(r1, r2, v);
}

void bounce_atlas_cor_n(const bounce_atlas* atlas, std::size_t n, const double* r1, const double* r2, const double* v,
                        double* out) {
  atlas->atlas.cor_many(n, r1, r2, v, out);
}

int bounce_atlas_sticks(const bounce_atlas* atlas, double r1, double r2, double v) {
  return atlas->atlas.sticks_unchecked(r1, r2, v);
}

double bounce_atlas_v_stick(const bounce_atlas* atlas, double r1, double r2) {
  return atlas->atlas.v_stick_unchecked(r1, r2);
}

int bounce_atlas_lookup(const bounce_atlas* atlas, double r1, double r2, double v, bounce_atlas_value* out) {
  try {
    const bounce::analysis::AtlasValue got = atlas->atlas.at({r1, r2, v});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    *out = {got.cor, got.sticks ? 1 : 0, got.v_stick, got.contact_time.value_or(nan), got.bulk_fraction.value_or(nan),
            got.crack_fraction.value_or(nan)};
    return 0;
  } catch (...) {
    return -1;
  }
}

void bounce_atlas_get_ranges(const bounce_atlas* atlas, bounce_atlas_ranges* out) {
  const auto& a = atlas->atlas;
  *out = {a.radius_min, a.radius_max, a.velocity_min, a.velocity_max, a.density_min, a.density_max,
          a.errors.cor,  a.errors.v_stick};
}

void bounce_atlas_get_grid(const bounce_atlas* atlas, bounce_atlas_grid* out) {
  const auto& a = atlas->atlas;
  *out = {a.x.count, a.y.count, a.z.count, a.x.nodes.data(), a.y.start, a.y.step, a.z.start, a.z.step,
          a.ln_v_reference, a.can_stick ? 1 : 0, a.stick_ratio.data(), a.values.data()};
}

}  // extern "C"
