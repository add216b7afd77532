/* The collision atlas from C and Fortran (docs/atlas.md): open a file written by
 * `bounce atlas build`, look up eps, the outcome and v_stick of a pair of radii at an impact
 * speed, and read the raw grids (for codes that copy them to a GPU).
 *
 * Plain C (C99 and C++); link with -lbounce (a shared libbounce opens its HDF5 module from the
 * folder bounce/ beside it: copy both). Every length in m, speed in m/s. R2 = INFINITY
 * is a wall of the atlas's second material. A query outside the atlas's ranges returns NaN
 * (or -1 for bounce_atlas_sticks): never an extrapolated value. The lookups are read-only and
 * may run on many threads at once. */
#ifndef BOUNCE_ATLAS_H
#define BOUNCE_ATLAS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct bounce_atlas bounce_atlas;

/* Opens an atlas; NULL on failure, with the reason in `error` (at most error_size bytes, may be
 * NULL). `model` (may be NULL or "") refuses a file of another model (e.g. "krijt"). */
bounce_atlas *bounce_atlas_open(const char *path, const char *model, char *error, size_t error_size);
void bounce_atlas_close(bounce_atlas *atlas);

/* eps in [0, 1] (0 where the grains stick); NaN outside the atlas. */
double bounce_atlas_cor(const bounce_atlas *atlas, double r1, double r2, double v);
/* eps at n points at once: faster per point, the points' independent work overlapping, with
 * vector logarithms (out[i] is bounce_atlas_cor(r1[i], r2[i], v[i]) within 1e-13; stick or
 * bounce may differ only within that width of v_stick: docs/atlas.md). out may be one of the
 * inputs. */
void bounce_atlas_cor_n(const bounce_atlas *atlas, size_t n, const double *r1, const double *r2, const double *v,
                        double *out);
/* 1 stick, 0 bounce, -1 outside the atlas. */
int bounce_atlas_sticks(const bounce_atlas *atlas, double r1, double r2, double v);
/* The sticking velocity; INFINITY where the grains stick at every speed of the atlas (v_stick
 * above its top speed); 0 for a model that cannot stick; NaN outside the atlas's radii. */
double bounce_atlas_v_stick(const bounce_atlas *atlas, double r1, double r2);

typedef struct {
  double cor;            /* eps */
  int sticks;            /* 1 stick, 0 bounce */
  double v_stick;        /* [m/s] */
  double contact_time;   /* [s]; NaN for a sticking collision */
  double bulk_fraction;  /* bulk viscous loss / initial kinetic energy; NaN when sticking */
  double crack_fraction; /* loss at the crack tip / initial kinetic energy; NaN when sticking */
} bounce_atlas_value;
/* Every quantity at once; 0 on success, -1 outside the atlas (out untouched). */
int bounce_atlas_lookup(const bounce_atlas *atlas, double r1, double r2, double v, bounce_atlas_value *out);

typedef struct {
  double radius_min, radius_max;     /* reduced radius R_eff [m] */
  double velocity_min, velocity_max; /* [m/s] */
  double density_min, density_max;   /* effective density rho_eff [kg/m^3] */
  double cor_error;                  /* stated bound on |eps - eps_collide| */
  double v_stick_error;              /* stated bound on the relative error of v_stick */
} bounce_atlas_ranges;
void bounce_atlas_get_ranges(const bounce_atlas *atlas, bounce_atlas_ranges *out);

/* The raw grid (docs/atlas.md, "Format"): axes x = ln R_eff (its nodes x_nodes, ascending,
 * refined where needed), y = ln rho_eff and z = ln(v - v_stick) (each start + i step); stick_ratio (nx, ny) w = v_ref / v_stick with
 * v_ref = exp(ln_v_reference - 5/6 x - y/2); values (4, nx, ny, nz), z fastest: eps sqrt(v /
 * (v - v_stick)), ln contact time, bulk and crack fractions. The pointers live as long as the atlas. */
typedef struct {
  size_t nx, ny, nz;
  const double *x_nodes;
  double y_start, y_step, z_start, z_step;
  double ln_v_reference;
  int can_stick;
  const double *stick_ratio;
  const double *values;
} bounce_atlas_grid;
void bounce_atlas_get_grid(const bounce_atlas *atlas, bounce_atlas_grid *out);

#ifdef __cplusplus
}
#endif

#endif /* BOUNCE_ATLAS_H */
