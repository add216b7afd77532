/* eps^N(g) of a restitution table (docs/tables.md): cubic Hermite pieces in
 * x = ln(g - v_s) (x = ln g without sticking), one piece per outcome, with a jump between
 * pieces (their facing nodes 1e-11 apart) where the outcome changes. Below the sticking
 * velocity v_s the grains stick (eps^N = 0); between v_s and the first node
 * eps^N ~ sqrt(g - v_s) continues the first node.
 *
 * Plain C99 that also compiles as C++ (it needs <math.h>): the library includes this file,
 * and `bounce table ... --c-header P` writes it into the header with the prefix P on every
 * name, so both run the same algorithm. Every function is static inline: a client that calls
 * one of them gets no "defined but not used" warning for the others (-Wall -Werror). */

typedef struct {
  long n;               /* nodes */
  const double *x;      /* nodes, ascending */
  const double *f;      /* values */
  const double *d;      /* slopes df/dx */
  const double *label;  /* piece of each node: 1 bounce, 0 stick */
} nt_curve;

typedef struct {
  nt_curve curve;
  double g_min, g_max;      /* range [m/s] */
  double sticking_velocity; /* v_s [m/s]; 0: the grains never stick in range */
} nt_table;

/* Cubic Hermite on [x0, x1]. */
static inline double nt_hermite(double x0, double f0, double d0, double x1, double f1, double d1, double x) {
  double h = x1 - x0, t = (x - x0) / h, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * h * d0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * h * d1;
}

/* The value of the piece labelled `want` at x (extrapolated beyond its ends); NaN without one. */
static inline double nt_in_piece(const nt_curve *c, double want, double at) {
  long first = -1, last = -1, i;
  for (i = 0; i < c->n; ++i) {
    if (c->label[i] != want) continue;
    if (first < 0) first = i;
    last = i;
  }
  if (first < 0) return NAN;
  if (first == last) return c->f[first] + c->d[first] * (at - c->x[first]);
  i = first;
  while (i + 2 <= last && at > c->x[i + 1]) ++i;
  return nt_hermite(c->x[i], c->f[i], c->d[i], c->x[i + 1], c->f[i + 1], c->d[i + 1], at);
}

/* The last node at or before `at` (0 before the first), at most n - 2. */
static inline long nt_interval(const nt_curve *c, double at) {
  long lo = 0, hi = c->n - 1;
  if (at >= c->x[c->n - 1]) return c->n - 2;
  if (!(at > c->x[0])) return 0;
  while (hi - lo > 1) {
    long mid = (lo + hi) / 2;
    if (c->x[mid] <= at) lo = mid; else hi = mid;
  }
  return lo;
}

/* The label at x: inside a jump's bracket, the side of the nearer node. */
static inline double nt_label_at(const nt_curve *c, double at) {
  long i;
  if (at < c->x[0]) return c->label[0];
  if (at >= c->x[c->n - 1]) return c->label[c->n - 1];
  i = nt_interval(c, at);
  if (c->label[i] == c->label[i + 1]) return c->label[i];
  return at < 0.5 * (c->x[i] + c->x[i + 1]) ? c->label[i] : c->label[i + 1];
}

/* The curve at x: Hermite inside a piece, the piece of nt_label_at across a jump. */
static inline double nt_curve_at(const nt_curve *c, double at) {
  long i = nt_interval(c, at);
  if (c->label[i] == c->label[i + 1]) {
    return nt_hermite(c->x[i], c->f[i], c->d[i], c->x[i + 1], c->f[i + 1], c->d[i + 1], at);
  }
  return nt_in_piece(c, nt_label_at(c, at), at);
}

/* 1 if grains meeting at g [m/s] stick, 0 if they bounce; -1 outside [g_min, g_max], where
   the table knows nothing (as nt_cor's NaN: never an extrapolated outcome). */
static inline int nt_sticks(const nt_table *t, double g) {
  double offset, x;
  if (!(g >= t->g_min * (1 - 1e-12) && g <= t->g_max * (1 + 1e-12))) return -1;
  if (t->sticking_velocity > 0 && g <= t->sticking_velocity) return 1;
  offset = t->sticking_velocity > 0 ? g - t->sticking_velocity : g;
  x = log(offset);
  if (x < t->curve.x[0]) x = t->curve.x[0];
  return nt_label_at(&t->curve, x) == 0;
}

/* eps^N at g [m/s]; NaN outside [g_min, g_max]. */
static inline double nt_cor(const nt_table *t, double g) {
  double offset, x;
  if (!(g >= t->g_min * (1 - 1e-12) && g <= t->g_max * (1 + 1e-12))) return NAN;
  if (t->sticking_velocity > 0 && g <= t->sticking_velocity) return 0.0;
  offset = t->sticking_velocity > 0 ? g - t->sticking_velocity : g;
  x = log(offset);
  if (x < t->curve.x[0]) return t->curve.f[0] * sqrt(offset / exp(t->curve.x[0]));
  return nt_curve_at(&t->curve, x);
}
