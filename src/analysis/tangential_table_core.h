/* eps^T(g^N, g^T) of BSHP96's asperity law (published form, (35) in the history form of
 * docs/decisions.md D11) from a table of the contact's fundamental solutions (docs/tables.md).
 *
 * Between asperity breaks the tangential motion is linear, BSHP96 (10) with (35):
 *   p'' = -K(tau) p,  K = mu lambda_n f / kappa,  p = (zeta - zeta_a) / (g^T t_u),
 * in the scaled time tau = t / t_u of the normal collision (t_u = xi0 / g^N, f the scaled
 * normal force). With y1, y2 its solutions y1(0) = 1, y1'(0) = 0, y2(0) = 0, y2'(0) = 1
 * (Wronskian 1), the motion after a break at sigma with sliding speed v is
 *   p = v (y1(sigma) y2(tau) - y2(sigma) y1(tau)),  z' = v (y1(sigma) y2'(tau) - y2(sigma) y1'(tau)),
 * and the next asperity breaks where |p| first reaches zeta0 / (g^T t_u). The table holds
 * y1, y1', y2, y2', K and dK/ds on nodes in s = sqrt(tau / tau_end) (tau_end: the normal
 * force returns to 0) for rows equally spaced in ln g^N; a lookup interpolates the rows
 * (Lagrange), builds quintic Hermite pieces in s and replays the breaks on them.
 *
 * Plain C99 that also compiles as C++ (it needs <math.h>): the library includes this file,
 * and `bounce table --tangential-velocities ... --c-header P` writes it into the header with
 * the prefix P on every name, so both run the same algorithm. Every function is static inline:
 * a client that calls one of them gets no "defined but not used" warning for the others. */

typedef struct {
  int rows, nodes, order; /* order: number of rows in a Lagrange stencil */
  double x0, dx;          /* ln g^N [m/s] of row 0 and the spacing of the rows */
  double zeta0;           /* asperity size [m] */
  const double *s;        /* nodes, 0 = s_0 < ... < s_{nodes-1} = 1 */
  const double *row;      /* per row: tau_end, ln t_u [s] */
  const double *node;     /* per row and node: y1, y1', y2, y2', K, dK/ds */
} tt_table;

enum { tt_row_values = 2, tt_node_values = 6, tt_max_order = 12 };

/* The rows of the stencil around x = ln g^N and their Lagrange weights. */
static inline int tt_stencil(const tt_table *t, double x, double *w) {
  double pos = (x - t->x0) / t->dx;
  int first = (int)floor(pos) - (t->order - 1) / 2, i, k;
  if (first < 0) first = 0;
  if (first > t->rows - t->order) first = t->rows - t->order;
  for (i = 0; i < t->order; ++i) {
    double wi = 1.0;
    for (k = 0; k < t->order; ++k) {
      if (k != i) wi *= (pos - (first + k)) / (double)(i - k);
    }
    w[i] = wi;
  }
  return first;
}

/* Values interpolated across the stencil: `count` values starting at `offset` of each row's block of `stride`. */
static inline void tt_mix(const tt_table *t, const double *data, long stride, long offset, int count, int first,
                   const double *w, double *out) {
  int i, k;
  for (k = 0; k < count; ++k) out[k] = 0.0;
  for (i = 0; i < t->order; ++i) {
    const double *d = data + (long)(first + i) * stride + offset;
    for (k = 0; k < count; ++k) out[k] += w[i] * d[k];
  }
}

/* Quintic through (f0, d0, e0) at t = 0 and (f1, d1, e1) at t = 1 (derivatives in t). */
static inline void tt_quintic(double f0, double d0, double e0, double f1, double d1, double e1, double *c) {
  double F, D, E;
  c[0] = f0;
  c[1] = d0;
  c[2] = 0.5 * e0;
  F = f1 - c[0] - c[1] - c[2];
  D = d1 - c[1] - 2.0 * c[2];
  E = e1 - 2.0 * c[2];
  c[3] = 10.0 * F - 4.0 * D + 0.5 * E;
  c[4] = -15.0 * F + 7.0 * D - E;
  c[5] = 6.0 * F - 3.0 * D + 0.5 * E;
}

static inline double tt_poly(const double *c, double t) {
  return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
}

static inline double tt_dpoly(const double *c, double t) {
  return c[1] + t * (2.0 * c[2] + t * (3.0 * c[3] + t * (4.0 * c[4] + t * 5.0 * c[5])));
}

/* The Hermite data of y1, y1', y2, y2' in s at one node: q[4][3] = value, d/ds, d2/ds2 (times h, h^2). */
static inline void tt_node_data(const double *n, double s, double tau_end, double h, double q[4][3]) {
  const double ts = 2.0 * tau_end * s, tss = 2.0 * tau_end, K = n[4], Kp = n[5];
  int i;
  for (i = 0; i < 2; ++i) {
    const double y = n[2 * i], v = n[2 * i + 1];
    q[2 * i][0] = y;
    q[2 * i][1] = h * v * ts;
    q[2 * i][2] = h * h * (-K * y * ts * ts + v * tss);
    q[2 * i + 1][0] = v;
    q[2 * i + 1][1] = -h * K * y * ts;
    q[2 * i + 1][2] = h * h * (-Kp * y * ts - K * v * ts * ts - K * y * tss);
  }
}

/* Root of the polynomial c minus `level` in [a, b] (a sign change there), by bisection
 * steps guarding regula falsi (Illinois) to the last bits. */
static inline double tt_root(const double *c, int derivative, double level, double a, double b) {
  double fa = (derivative ? tt_dpoly(c, a) : tt_poly(c, a)) - level;
  double fb = (derivative ? tt_dpoly(c, b) : tt_poly(c, b)) - level;
  int side = 0, it;
  for (it = 0; it < 200 && b - a > 4e-16 * (1.0 + fabs(a)); ++it) {
    double m = (fa * b - fb * a) / (fa - fb), fm;
    if (!(m > a && m < b) || it % 8 == 7) m = 0.5 * (a + b);
    fm = (derivative ? tt_dpoly(c, m) : tt_poly(c, m)) - level;
    if (fm == 0.0) return m;
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      b = m;
      fb = fm;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (a + b);
}

/* The first t in [a, b] where |P| reaches `level` (|P(a)| < level), or -1. P is split at
 * the zeros of P' into monotone pieces: in each, |P| reaches the level iff it does at the
 * piece's end; a maximum of |P| just reaching it is a break (as in the direct integration). */
static inline double tt_first_reach(const double *c, double level, double a, double b) {
  const int sub = 4;
  int k;
  double u = a;
  for (k = 1; k <= sub; ++k) {
    const double w = a + (b - a) * k / sub;
    double ends[3];
    int n = 0, i;
    const double du = tt_dpoly(c, u), dw = tt_dpoly(c, w);
    if ((du < 0) != (dw < 0) && du != 0.0 && dw != 0.0) ends[n++] = tt_root(c, 1, 0.0, u, w);
    ends[n++] = w;
    for (i = 0; i < n; ++i) {
      const double pe = tt_poly(c, ends[i]);
      if (fabs(pe) >= level) return tt_root(c, 0, pe > 0 ? level : -level, u, ends[i]);
      u = ends[i];
    }
  }
  return -1.0;
}

/* eps^T at (g^N, g^T) [m/s]; NaN outside the table's g^N range. `breaks` (may be NULL)
 * receives the number of asperities that broke. */
static inline double tt_cor(const tt_table *t, double gn, double gt, long *breaks) {
  double w[tt_max_order], rowv[tt_row_values], lo[tt_node_values], hi[tt_node_values];
  double qa[4][3], qb[4][3];
  double x = log(gn), tau_end, level, budget, a = 1.0, b = 0.0, z = 1.0;
  long count = 0;
  int first, j;
  if (!(x >= t->x0 - 1e-12 && x <= t->x0 + (t->rows - 1) * t->dx + 1e-12) || !(gt > 0.0)) return NAN;
  first = tt_stencil(t, x, w);
  tt_mix(t, t->row, tt_row_values, 0, tt_row_values, first, w, rowv);
  tau_end = rowv[0];
  level = t->zeta0 / (gt * exp(rowv[1]));
  /* Between two breaks |p| climbs from 0 to `level`, and |dp/dtau| is the sliding speed over
   * g^T, which stays below about 1.2 (|eps^T| <= 1.13 with the published form): a collision
   * has fewer than tau_end / level breaks. Four times that (and a few per node) is the
   * budget; a table that asks for more was altered (the fuzzer's dK/ds 1e6 times too large
   * replayed 1e8 breaks): no value. bounce refuses to load a table needing more than 1e5
   * breaks; 1e6 bounds a lookup to ~0.3 s whatever the table. */
  budget = 4.0 * tau_end / level + 64.0 * t->nodes;
  if (!(budget < 1e6)) budget = 1e6;
  tt_mix(t, t->node, (long)t->nodes * tt_node_values, 0, tt_node_values, first, w, lo);
  for (j = 0; j + 1 < t->nodes; ++j) {
    const double h = t->s[j + 1] - t->s[j];
    double c1[6], c2[6], v1[6], v2[6], p[6], start = 0.0;
    int k;
    tt_mix(t, t->node, (long)t->nodes * tt_node_values, (long)(j + 1) * tt_node_values, tt_node_values, first, w, hi);
    tt_node_data(lo, t->s[j], tau_end, h, qa);
    tt_node_data(hi, t->s[j + 1], tau_end, h, qb);
    tt_quintic(qa[0][0], qa[0][1], qa[0][2], qb[0][0], qb[0][1], qb[0][2], c1);
    tt_quintic(qa[1][0], qa[1][1], qa[1][2], qb[1][0], qb[1][1], qb[1][2], v1);
    tt_quintic(qa[2][0], qa[2][1], qa[2][2], qb[2][0], qb[2][1], qb[2][2], c2);
    tt_quintic(qa[3][0], qa[3][1], qa[3][2], qb[3][0], qb[3][1], qb[3][2], v2);
    for (;;) {
      double at;
      for (k = 0; k < 6; ++k) p[k] = a * c2[k] + b * c1[k];
      at = tt_first_reach(p, level, start, 1.0);
      if (at < 0.0) break;
      /* An asperity breaks: p restarts from 0 with the sliding speed z'. */
      z = a * tt_poly(v2, at) + b * tt_poly(v1, at);
      a = z * tt_poly(c1, at);
      b = -z * tt_poly(c2, at);
      start = at;
      if (++count > budget) return NAN;
    }
    z = a * tt_poly(v2, 1.0) + b * tt_poly(v1, 1.0);
    for (k = 0; k < tt_node_values; ++k) lo[k] = hi[k];
  }
  if (breaks) *breaks = count;
  return z;
}
