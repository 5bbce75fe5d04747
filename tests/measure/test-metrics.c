/* Unit tests of tools/metrics.c and tools/patch-search.c: the fast exact
 * search and the measures against brute force on small synthetic images.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "metrics.h"
#include "patch-search.h"
#include "engine/rng.h"
#include "test-util.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif


static bool
close_to (double a, double b, double rel, double abs_tol)
{
  return fabs (a - b) <= rel * fabs (b) + abs_tol;
}

static float *
px (const TsImage *im, size_t x, size_t y)
{
  return im->pixels + (y * im->width + x) * TS_CHANNELS;
}

static TsImage
new_image (size_t w, size_t h)
{
  TsImage im = { w, h, calloc (w * h * TS_CHANNELS, sizeof (float)) };
  if (!im.pixels)
    {
      fputs ("out of memory\n", stderr);
      exit (99);
    }
  return im;
}

/* Smooth random texture quantised to steps of `quantum` (so that equal
 * windows and exact ties occur), with a flat corner if `flat`. */
static TsImage
make_texture (size_t w, size_t h, uint32_t seed, float quantum, bool flat)
{
  TsImage im = new_image (w, h);
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        float *p = px (&im, x, y);
        for (int c = 0; c < 3; c++)
          {
            double v = 30.0 * sin (0.4 * (double) x + 1.7 * c + seed)
                         * cos (0.3 * (double) y - c)
                       + (double) (ts_lcg_next24 (&seed) % 2000) / 100.0;
            p[c] = quantum > 0.0f ? quantum * roundf ((float) v / quantum) : (float) v;
          }
        if (flat && x > w / 2 && y > h / 2)
          {
            p[0] = 50.0f;
            p[1] = 5.0f;
            p[2] = -5.0f;
          }
        p[3] = 1.0f;
      }
  return im;
}

static size_t
wrap_index (ptrdiff_t i, size_t n)
{
  ptrdiff_t m = i % (ptrdiff_t) n;
  return (size_t) (m < 0 ? m + (ptrdiff_t) n : m);
}

/* Independent brute-force window SSD in double; coordinates wrap (callers
 * only pass windows that are inside along non-wrapping axes). */
static double
window_ssd (const TsImage *a, size_t ax, size_t ay, const TsImage *b, size_t bx, size_t by,
            int r)
{
  double sum = 0.0;
  for (int dy = -r; dy <= r; dy++)
    for (int dx = -r; dx <= r; dx++)
      {
        const float *p = px (a, wrap_index ((ptrdiff_t) ax + dx, a->width),
                             wrap_index ((ptrdiff_t) ay + dy, a->height));
        const float *q = px (b, wrap_index ((ptrdiff_t) bx + dx, b->width),
                             wrap_index ((ptrdiff_t) by + dy, b->height));
        for (int c = 0; c < 3; c++)
          sum += ((double) p[c] - q[c]) * ((double) p[c] - q[c]);
      }
  return sum;
}

static TsWindowGrid
grid (const TsImage *im, int r, size_t step, bool wx, bool wy)
{
  TsWindowGrid g = { .image = im, .radius = r, .wrap_x = wx, .wrap_y = wy, .step = step };
  g.x0 = wx ? 0 : (size_t) r;
  g.y0 = wy ? 0 : (size_t) r;
  g.nx = wx ? (im->width + step - 1) / step : (im->width - 2 * (size_t) r - 1) / step + 1;
  g.ny = wy ? (im->height + step - 1) / step : (im->height - 2 * (size_t) r - 1) / step + 1;
  return g;
}

static void
centre (const TsWindowGrid *g, size_t i, size_t *x, size_t *y)
{
  *x = g->x0 + (i % g->nx) * g->step;
  *y = g->y0 + (i / g->nx) * g->step;
}

/* Nearest, first-within and any-within searches against brute force. */
static void
test_search (const char *name, const TsWindowGrid *q, const TsWindowGrid *db, int lift_dims)
{
  TsPatchIndex *ix = ts_patch_index_new (db, lift_dims);
  size_t nq = ts_grid_count (q), nd = ts_grid_count (db), dims = ts_grid_dims (q);
  float *vec = malloc (dims * sizeof (float));
  double *nn = malloc (nq * sizeof (double)), mean_nn = 0.0;
  float thr;
  int bad = 0;

  CHECK (ix && vec && nn, "%s: index or memory", name);
  if (!ix || !vec || !nn)
    return;
  for (size_t i = 0; i < nq; i++)
    {
      size_t qx, qy, bx, by, guess = (i * 7919) % (nd + 3); /* some guesses invalid */
      float ssd;
      size_t m;
      double best = DBL_MAX;
      centre (q, i, &qx, &qy);
      for (size_t j = 0; j < nd; j++)
        {
          size_t dx, dy;
          double d;
          centre (db, j, &dx, &dy);
          d = window_ssd (q->image, qx, qy, db->image, dx, dy, q->radius);
          best = d < best ? d : best;
        }
      nn[i] = best;
      mean_nn += best;
      ts_grid_gather (q, i, vec);
      m = ts_patch_index_nearest (ix, vec, guess < nd ? guess : TS_SEARCH_NONE, &ssd);
      CHECK (m < nd, "%s: query %zu: no match", name, i);
      if (m >= nd)
        continue;
      centre (db, m, &bx, &by);
      if (!close_to (ssd, best, 1e-4, 1e-3)
          || !close_to (window_ssd (q->image, qx, qy, db->image, bx, by, q->radius), ssd, 1e-4,
                        1e-3))
        bad++;
    }
  CHECK (bad == 0, "%s: %d of %zu nearest neighbours differ from brute force", name, bad, nq);

  /* Threshold between typical NN distances: some queries have windows
   * within it, some not. Semantics use the library's float SSD. */
  thr = (float) (mean_nn / (double) nq);
  bad = 0;
  for (size_t i = 0; i < nq; i++)
    {
      size_t first = TS_SEARCH_NONE, got, any;
      ts_grid_gather (q, i, vec);
      for (size_t j = 0; j < nd && first == TS_SEARCH_NONE; j++)
        if (ts_grid_ssd (vec, db, j, thr) < thr)
          first = j;
      got = ts_patch_index_first_within (ix, vec, thr);
      any = ts_patch_index_any_within (ix, vec, thr);
      if (got != first || (any == TS_SEARCH_NONE) != (first == TS_SEARCH_NONE)
          || (any != TS_SEARCH_NONE && !(ts_grid_ssd (vec, db, any, FLT_MAX) < thr)))
        bad++;
    }
  CHECK (bad == 0, "%s: %d of %zu within-threshold searches differ from brute force", name,
         bad, nq);
  /* ts_grid_ssd itself against the double brute force. */
  for (size_t i = 0; i < nq && i < 50; i++)
    {
      size_t qx, qy, bx, by, j = (i * 31) % nd;
      centre (q, i, &qx, &qy);
      centre (db, j, &bx, &by);
      ts_grid_gather (q, i, vec);
      CHECK (close_to (ts_grid_ssd (vec, db, j, FLT_MAX),
                       window_ssd (q->image, qx, qy, db->image, bx, by, q->radius), 1e-5, 1e-3),
             "%s: ts_grid_ssd", name);
    }
  ts_patch_index_free (ix);
  free (vec);
  free (nn);
}

/* Coherence / seam / completeness by brute force, straight from the
 * definitions in metrics.h. */
static void
brute_measures (const TsImage *ex, const TsImage *res, bool wx, bool wy, double *coherence,
                double *seam, double *completeness)
{
  const int r = 3;
  TsWindowGrid q = grid (res, r, 2, wx, wy), e = grid (ex, r, 1, false, false);
  TsWindowGrid eq = grid (ex, r, 2, false, false), rd = grid (res, r, 1, wx, wy);
  double sum_s = 0, sum_o = 0, sum_c = 0;
  size_t n_s = 0, n_o = 0;

  for (size_t i = 0; i < ts_grid_count (&q); i++)
    {
      size_t x, y;
      double best = DBL_MAX, d;
      bool crosses;
      centre (&q, i, &x, &y);
      for (size_t j = 0; j < ts_grid_count (&e); j++)
        {
          size_t ex_x, ex_y;
          centre (&e, j, &ex_x, &ex_y);
          d = window_ssd (res, x, y, ex, ex_x, ex_y, r);
          best = d < best ? d : best;
        }
      d = sqrt (best / 147.0);
      crosses = (wx && (x < 3 || x + 3 >= res->width)) || (wy && (y < 3 || y + 3 >= res->height));
      if (crosses)
        sum_s += d, n_s++;
      else
        sum_o += d, n_o++;
    }
  *coherence = (sum_s + sum_o) / (double) (n_s + n_o);
  *seam = (wx || wy) && n_s && n_o ? (sum_s / n_s + TS_MEASURE_SEAM_FLOOR) / (sum_o / n_o + TS_MEASURE_SEAM_FLOOR) : NAN;
  for (size_t i = 0; i < ts_grid_count (&eq); i++)
    {
      size_t x, y;
      double best = DBL_MAX;
      centre (&eq, i, &x, &y);
      for (size_t j = 0; j < ts_grid_count (&rd); j++)
        {
          size_t rx, ry;
          double d;
          centre (&rd, j, &rx, &ry);
          d = window_ssd (ex, x, y, res, rx, ry, r);
          best = d < best ? d : best;
        }
      sum_c += sqrt (best / 147.0);
    }
  *completeness = sum_c / (double) ts_grid_count (&eq);
}

static void
test_measures_vs_brute (const TsImage *ex, const TsImage *res)
{
  for (int mode = 0; mode < 4; mode++)
    {
      bool wx = mode & 1, wy = mode & 2;
      double c, s, k, bc, bs, bk;
      CHECK (ts_measure_coherence (ex, res, wx, wy, &c, &s) == TS_MEASURE_OK, "coherence");
      CHECK (ts_measure_completeness (ex, res, wx, wy, &k) == TS_MEASURE_OK, "completeness");
      brute_measures (ex, res, wx, wy, &bc, &bs, &bk);
      CHECK (close_to (c, bc, 1e-4, 1e-4), "wrap %d: coherence %g, brute force %g", mode, c, bc);
      CHECK (close_to (k, bk, 1e-4, 1e-4), "wrap %d: completeness %g, brute %g", mode, k, bk);
      CHECK ((isnan (s) && isnan (bs)) || close_to (s, bs, 1e-4, 1e-4),
             "wrap %d: seam %g, brute force %g", mode, s, bs);
    }
}

/* Copy region rules, on a small texture and images made from it. */
static void
test_copy (void)
{
  TsImage ex = make_texture (20, 18, 5, 0.0f, false);
  TsImage big = make_texture (40, 36, 77, 0.0f, false);
  TsImage rolled = new_image (20, 18);
  double copy;
  const double interior = 16.0 * 14.0; /* 5x5 windows inside ex */

  CHECK (ts_measure_copy (&ex, &ex, false, false, &copy) == TS_MEASURE_OK && copy == 1.0,
         "exemplar against itself: copy %g, want 1", copy);
  /* The exemplar pasted into an unrelated image: one full copy. */
  for (size_t y = 0; y < ex.height; y++)
    memcpy (px (&big, 11, 9 + y), px (&ex, 0, y), ex.width * TS_CHANNELS * sizeof (float));
  CHECK (ts_measure_copy (&ex, &big, false, false, &copy) == TS_MEASURE_OK && copy == 1.0,
         "pasted exemplar: copy %g, want 1", copy);
  /* Unrelated texture: no verbatim copy at all. */
  {
    TsImage other = make_texture (40, 36, 1234, 0.0f, false);
    CHECK (ts_measure_copy (&ex, &other, true, true, &copy) == TS_MEASURE_OK && copy == 0.0,
           "unrelated: copy %g, want 0", copy);
    free (other.pixels);
  }
  /* Rolled by (7, 5): in the tiled plane the exemplar is whole again, so
   * with wrap-around it is one copy; without, the largest of the four
   * pieces, (13 - 4) x (13 - 4) windows inside. */
  for (size_t y = 0; y < 18; y++)
    for (size_t x = 0; x < 20; x++)
      memcpy (px (&rolled, (x + 7) % 20, (y + 5) % 18), px (&ex, x, y),
              TS_CHANNELS * sizeof (float));
  CHECK (ts_measure_copy (&ex, &rolled, true, true, &copy) == TS_MEASURE_OK && copy == 1.0,
         "rolled, wrapped: copy %g, want 1", copy);
  CHECK (ts_measure_copy (&ex, &rolled, false, false, &copy) == TS_MEASURE_OK
           && fabs (copy - 9.0 * 9.0 / interior) < 1e-9,
         "rolled, not wrapped: copy %g, want %g", copy, 81.0 / interior);
  free (ex.pixels);
  free (big.pixels);
  free (rolled.pixels);
}

static void
test_sharpness_and_errors (void)
{
  TsImage ex = make_texture (30, 30, 9, 0.0f, false), blur = new_image (30, 30);
  TsImage tiny = new_image (6, 30), flat = new_image (10, 10);
  TsMeasures m;
  double s;

  for (size_t y = 0; y < 30; y++)
    for (size_t x = 0; x < 30; x++)
      for (int c = 0; c < 4; c++)
        {
          double acc = 0.0;
          for (int d = -1; d <= 1; d++)
            for (int e = -1; e <= 1; e++)
              acc += px (&ex, wrap_index ((ptrdiff_t) x + d, 30), wrap_index ((ptrdiff_t) y + e, 30))[c];
          px (&blur, x, y)[c] = (float) (acc / 9.0);
        }
  CHECK (ts_measure_sharpness (&ex, &ex, &s) == TS_MEASURE_OK && s == 1.0, "self %g", s);
  CHECK (ts_measure_sharpness (&ex, &blur, &s) == TS_MEASURE_OK && s < 0.8, "blurred %g", s);
  CHECK (ts_measure_sharpness (&flat, &flat, &s) == TS_MEASURE_OK && s == 1.0, "flat %g", s);
  CHECK (ts_measure_all (&ex, &tiny, false, false, &m) == TS_MEASURE_TOO_SMALL, "too small");
  CHECK (ts_measure_all (&tiny, &ex, true, true, &m) == TS_MEASURE_TOO_SMALL, "too small");
  CHECK (ts_measure_all (&flat, &ex, true, false, &m) == TS_MEASURE_OK && !isnan (m.seam)
           && m.completeness >= 0.0 && m.copy == 0.0,
         "flat exemplar");
  free (ex.pixels);
  free (blur.pixels);
  free (tiny.pixels);
  free (flat.pixels);
}

/* Stripes whose edges run at `degrees`, smoothly shaded so the gradient
 * is well defined, and concentric rings (every direction alike). */
static TsImage
make_stripes (size_t side, double degrees, bool rings)
{
  TsImage im = new_image (side, side);
  double a = degrees * 3.14159265358979323846 / 180.0;
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      {
        double dx = (double) x - 0.5 * (double) side, dy = (double) y - 0.5 * (double) side;
        double t = rings ? sqrt (dx * dx + dy * dy) : dx * cos (a) + dy * sin (a);
        float *p = px (&im, x, y);
        /* Rings end inside the inscribed circle: the square's corners
         * would add diagonal edges. */
        double pi = 3.14159265358979323846, last = floor ((0.5 * (double) side - 2.0) * 0.3 / pi) * pi / 0.3;
        if (rings && t > last)
          t = last;
        p[0] = (float) (50.0 + 40.0 * sin (t * 0.3));
        p[3] = 1.0f;
      }
  return im;
}

static void
test_axis_edges (void)
{
  TsImage axial = make_stripes (64, 0.0, false), diagonal = make_stripes (64, 45.0, false);
  TsImage tilted = make_stripes (64, 25.0, false), rings = make_stripes (96, 0.0, true);
  TsImage flat = new_image (10, 10);
  TsMeasures m;
  double share;

  CHECK (ts_measure_axis_edge_share (&axial, &share) == TS_MEASURE_OK && share > 0.99,
         "axis-aligned stripes: share %g, want 1", share);
  CHECK (ts_measure_axis_edge_share (&diagonal, &share) == TS_MEASURE_OK && share < 0.01,
         "45-degree stripes: share %g, want 0", share);
  CHECK (ts_measure_axis_edge_share (&tilted, &share) == TS_MEASURE_OK && share < 0.01,
         "25-degree stripes: share %g, want 0", share);
  /* Isotropic: 40 of 180 degrees. */
  CHECK (ts_measure_axis_edge_share (&rings, &share) == TS_MEASURE_OK && fabs (share - 0.222) < 0.03,
         "rings: share %g, want about 0.222", share);
  CHECK (ts_measure_axis_edge_share (&flat, &share) == TS_MEASURE_OK && isnan (share),
         "flat: share %g, want NaN", share);
  CHECK (ts_measure_all (&rings, &axial, false, false, &m) == TS_MEASURE_OK && m.axis_edges > 3.5,
         "stripes against rings: ratio %g", m.axis_edges);
  CHECK (ts_measure_all (&rings, &rings, false, false, &m) == TS_MEASURE_OK && m.axis_edges == 1.0,
         "self: ratio %g", m.axis_edges);
  free (axial.pixels);
  free (diagonal.pixels);
  free (tilted.pixels);
  free (rings.pixels);
  free (flat.pixels);
}

/* Anisotropy: stripes of any direction read 1, a grid of axis-aligned
 * squares nearly so (two orthogonal orientations), rings 0. */
static void
test_anisotropy (void)
{
  TsImage tilted = make_stripes (64, 25.0, false), rings = make_stripes (96, 0.0, true);
  TsImage grid_image = new_image (64, 64), flat = new_image (10, 10);
  double a;

  for (size_t y = 0; y < 64; y++)
    for (size_t x = 0; x < 64; x++)
      px (&grid_image, x, y)[0] = ((x / 8 + y / 8) & 1) ? 80.0f : 20.0f;
  CHECK (ts_measure_anisotropy (&tilted, &a) == TS_MEASURE_OK && a > 0.95,
         "25-degree stripes: anisotropy %g, want 1", a);
  /* Near 1: only the squares' corners give diagonal gradients (0.86). */
  CHECK (ts_measure_anisotropy (&grid_image, &a) == TS_MEASURE_OK && a > 0.8,
         "checkerboard: anisotropy %g, want near 1", a);
  CHECK (ts_measure_anisotropy (&rings, &a) == TS_MEASURE_OK && a < 0.05,
         "rings: anisotropy %g, want 0", a);
  CHECK (ts_measure_anisotropy (&flat, &a) == TS_MEASURE_OK && isnan (a),
         "flat: anisotropy %g, want NaN", a);
  free (tilted.pixels);
  free (rings.pixels);
  free (grid_image.pixels);
  free (flat.pixels);
}

int
main (void)
{
  TsImage ex = make_texture (26, 23, 1, 2.0f, true);
  TsImage res = make_texture (31, 28, 2, 2.0f, true);
  TsImage smooth = make_texture (24, 24, 3, 0.0f, false);

  /* Paste exemplar pieces into the result so that exact matches exist. */
  for (size_t y = 0; y < 12; y++)
    memcpy (px (&res, 2, 3 + y), px (&ex, 5, 4 + y), 14 * TS_CHANNELS * sizeof (float));

  for (int lift = 8; lift <= 32; lift *= 2)
    for (int mode = 0; mode < 4; mode++)
      {
        bool wx = mode & 1, wy = mode & 2;
        char name[64];
        TsWindowGrid q = grid (&res, 3, 2, wx, wy), db = grid (&ex, 3, 1, false, false);
        TsWindowGrid eq = grid (&ex, 3, 2, false, false), rdb = grid (&res, 3, 1, wx, wy);
        TsWindowGrid q5 = grid (&res, 2, 1, wx, wy), db5 = grid (&smooth, 2, 1, false, false);
        snprintf (name, sizeof name, "7x7 lift %d wrap %d", lift, mode);
        test_search (name, &q, &db, lift);
        snprintf (name, sizeof name, "7x7 wrapped db lift %d wrap %d", lift, mode);
        test_search (name, &eq, &rdb, lift);
        snprintf (name, sizeof name, "5x5 lift %d wrap %d", lift, mode);
        test_search (name, &q5, &db5, lift);
      }

  test_measures_vs_brute (&ex, &res);
  test_measures_vs_brute (&smooth, &res);
  test_copy ();
  test_sharpness_and_errors ();
  test_axis_edges ();
  test_anisotropy ();

#ifdef _OPENMP
  /* Same figures with any number of threads. */
  {
    TsMeasures one, two;
    omp_set_num_threads (1);
    ts_measure_all (&ex, &res, true, true, &one);
    omp_set_num_threads (2);
    ts_measure_all (&ex, &res, true, true, &two);
    CHECK (memcmp (&one, &two, sizeof one) == 0, "results depend on the thread count");
  }
#endif

  free (ex.pixels);
  free (res.pixels);
  free (smooth.pixels);
  return test_finish ("test-metrics");
}
