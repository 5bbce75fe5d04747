/* Quality measures for texsynth-measure; definitions in metrics.h.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "metrics.h"

#include "patch-search.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#define TS_OMP(x) _Pragma (#x)
#else
#define TS_OMP(x)
#endif

/* Lifted coordinates per window in the search indexes (see
 * patch-search.h): 7x7 windows often have far neighbours, where tighter
 * bounds pay; copy detection only looks for near-zero distances. */
#ifndef TS_MEASURE_LIFT
#define TS_MEASURE_LIFT 16
#endif
#define TS_COPY_LIFT 8

static bool
big_enough (const TsImage *image)
{
  return image && image->pixels && image->width >= TS_MEASURE_MIN_SIDE
         && image->height >= TS_MEASURE_MIN_SIDE;
}

/* Centres every `step` pixels: along a wrapping axis all of them from 0,
 * else only those whose window lies inside. */
static TsWindowGrid
make_grid (const TsImage *image, int radius, size_t step, bool wrap_x, bool wrap_y)
{
  TsWindowGrid g = { .image = image, .radius = radius, .wrap_x = wrap_x,
                     .wrap_y = wrap_y, .step = step };
  size_t margin = (size_t) radius;
  g.x0 = wrap_x ? 0 : margin;
  g.y0 = wrap_y ? 0 : margin;
  g.nx = wrap_x ? (image->width + step - 1) / step : (image->width - 2 * margin - 1) / step + 1;
  g.ny = wrap_y ? (image->height + step - 1) / step : (image->height - 2 * margin - 1) / step + 1;
  return g;
}

/* Exact nearest `db` window (a grid with step 1) for every `queries`
 * window; stores the SSDs. Rows run in parallel; along a row the match of
 * the previous query, moved by the query step, seeds the search. */
static TsMeasureStatus
nearest_all (const TsWindowGrid *queries, const TsWindowGrid *db, float *ssd)
{
  TsPatchIndex *index = ts_patch_index_new (db, TS_MEASURE_LIFT);
  size_t dims = ts_grid_dims (queries);
  bool ok = true;

  if (!index)
    return TS_MEASURE_OUT_OF_MEMORY;
  TS_OMP (omp parallel reduction (&& : ok))
  {
    float *vec = malloc (dims * sizeof (float));
    if (!vec)
      ok = false;
    TS_OMP (omp for schedule (dynamic, 1))
    for (size_t row = 0; row < queries->ny; row++)
      {
        size_t match = TS_SEARCH_NONE;
        if (!vec)
          continue;
        for (size_t col = 0; col < queries->nx; col++)
          {
            size_t i = row * queries->nx + col, guess = TS_SEARCH_NONE;
            if (match != TS_SEARCH_NONE)
              {
                size_t mx = match % db->nx + queries->step, my = match / db->nx;
                if (mx >= db->nx && db->wrap_x)
                  mx -= db->nx;
                if (mx < db->nx)
                  guess = my * db->nx + mx;
              }
            ts_grid_gather (queries, i, vec);
            match = ts_patch_index_nearest (index, vec, guess, &ssd[i]);
          }
      }
    free (vec);
  }
  ts_patch_index_free (index);
  return ok ? TS_MEASURE_OK : TS_MEASURE_OUT_OF_MEMORY;
}

static double
rms (float ssd, size_t dims)
{
  return sqrt ((double) ssd / (double) dims);
}

/* The SSD to the nearest `database` window (every pixel a centre) of each
 * `queries` window (every TS_MEASURE_STEP pixels), in *ssd (the caller
 * frees it); *grid says where the query centres lie. */
static TsMeasureStatus
nearest_windows (const TsImage *queries, bool queries_wrap_x, bool queries_wrap_y,
                 const TsImage *database, bool database_wrap_x, bool database_wrap_y,
                 TsWindowGrid *grid, float **ssd)
{
  TsWindowGrid db;
  TsMeasureStatus status;

  *ssd = NULL;
  if (!big_enough (queries) || !big_enough (database))
    return TS_MEASURE_TOO_SMALL;
  *grid = make_grid (queries, TS_MEASURE_RADIUS, TS_MEASURE_STEP, queries_wrap_x, queries_wrap_y);
  db = make_grid (database, TS_MEASURE_RADIUS, 1, database_wrap_x, database_wrap_y);
  *ssd = malloc (ts_grid_count (grid) * sizeof (float));
  if (!*ssd)
    return TS_MEASURE_OUT_OF_MEMORY;
  status = nearest_all (grid, &db, *ssd);
  if (status != TS_MEASURE_OK)
    {
      free (*ssd);
      *ssd = NULL;
    }
  return status;
}

TsMeasureStatus
ts_measure_coherence (const TsImage *exemplar, const TsImage *result, bool wrap_x,
                      bool wrap_y, double *coherence, double *seam)
{
  TsWindowGrid q;
  float *ssd;
  TsMeasureStatus status;
  size_t n, dims, n_seam = 0, n_other = 0;
  double sum_seam = 0.0, sum_other = 0.0;
  const size_t r = TS_MEASURE_RADIUS;

  *coherence = *seam = NAN;
  status = nearest_windows (result, wrap_x, wrap_y, exemplar, false, false, &q, &ssd);
  if (status != TS_MEASURE_OK)
    return status;
  n = ts_grid_count (&q);
  dims = ts_grid_dims (&q);
  /* Summed in a fixed order: same figures with any number of threads. */
  for (size_t i = 0; i < n; i++)
    {
      size_t x, y;
      bool crosses;
      ts_grid_centre (&q, i, &x, &y);
      crosses = (wrap_x && (x < r || x + r >= result->width))
                || (wrap_y && (y < r || y + r >= result->height));
      if (crosses)
        {
          sum_seam += rms (ssd[i], dims);
          n_seam++;
        }
      else
        {
          sum_other += rms (ssd[i], dims);
          n_other++;
        }
    }
  free (ssd);
  *coherence = (sum_seam + sum_other) / (double) n;
  if ((wrap_x || wrap_y) && n_seam > 0 && n_other > 0)
    *seam = (sum_seam / (double) n_seam + TS_MEASURE_SEAM_FLOOR)
            / (sum_other / (double) n_other + TS_MEASURE_SEAM_FLOOR);
  return TS_MEASURE_OK;
}

TsMeasureStatus
ts_measure_completeness (const TsImage *exemplar, const TsImage *result, bool wrap_x,
                         bool wrap_y, double *completeness)
{
  TsWindowGrid q;
  float *ssd;
  TsMeasureStatus status;
  size_t n, dims;
  double sum = 0.0;

  *completeness = NAN;
  status = nearest_windows (exemplar, false, false, result, wrap_x, wrap_y, &q, &ssd);
  if (status != TS_MEASURE_OK)
    return status;
  n = ts_grid_count (&q);
  dims = ts_grid_dims (&q);
  for (size_t i = 0; i < n; i++)
    sum += rms (ssd[i], dims);
  *completeness = sum / (double) n;
  free (ssd);
  return status;
}

/* Copy detection.
 *
 * A result pixel "matches" if its 5x5 window is within TS_COPY_MAX_RMS of
 * some exemplar window. Regions grow greedily from seeds, the matching
 * pixels in raster order not yet in a region; a seed takes the offset
 * o = exemplar centre - result centre of its first matching exemplar
 * window in raster order, and a 4-neighbour p joins if its window matches
 * the exemplar window at p + o within the threshold. Each pixel joins at
 * most one region. Growing checks p + o
 * directly rather than p's own match, so repetitive or flat exemplars
 * (many equally good matches) still give one region per pasted copy.
 *
 * Along a wrapping axis the result is treated as one period of the tiled
 * plane: growth crosses the edge and p is taken at its unwrapped plane
 * position, so o stays the same. A copy that straddles the seam of a
 * tileable result is then one region, as it is when the result is tiled;
 * comparing plain stored positions would split it at the edge. A region
 * never holds two pixels with the same exemplar centre, so copy <= 1. */
typedef struct
{
  ptrdiff_t x, y;
} PlanePos;

static bool
axis_to_stored (ptrdiff_t plane, size_t n, bool wrap, size_t margin, size_t *stored)
{
  if (wrap)
    {
      ptrdiff_t m = plane % (ptrdiff_t) n;
      *stored = (size_t) (m < 0 ? m + (ptrdiff_t) n : m);
      return true;
    }
  if (plane < (ptrdiff_t) margin || plane >= (ptrdiff_t) (n - margin))
    return false;
  *stored = (size_t) plane;
  return true;
}

static size_t
grow_region (const TsWindowGrid *q, const TsWindowGrid *db, size_t seed, size_t seed_match,
             float max_ssd, uint8_t *visited, PlanePos *queue, float *vec)
{
  const size_t r = (size_t) q->radius;
  const TsImage *ex = db->image;
  size_t sx, sy, ex_x, ex_y, head = 0, tail = 0;
  ptrdiff_t ox, oy;
  static const int steps[4][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } };

  ts_grid_centre (q, seed, &sx, &sy);
  ts_grid_centre (db, seed_match, &ex_x, &ex_y);
  ox = (ptrdiff_t) ex_x - (ptrdiff_t) sx;
  oy = (ptrdiff_t) ex_y - (ptrdiff_t) sy;
  visited[seed] = 1;
  queue[tail++] = (PlanePos) { (ptrdiff_t) sx, (ptrdiff_t) sy };
  while (head < tail)
    {
      PlanePos p = queue[head++];
      for (int k = 0; k < 4; k++)
        {
          PlanePos n = { p.x + steps[k][0], p.y + steps[k][1] };
          ptrdiff_t ecx = n.x + ox, ecy = n.y + oy;
          size_t x, y, qi, ei;
          if (!axis_to_stored (n.x, q->image->width, q->wrap_x, r, &x)
              || !axis_to_stored (n.y, q->image->height, q->wrap_y, r, &y)
              || ecx < (ptrdiff_t) r || ecx >= (ptrdiff_t) (ex->width - r)
              || ecy < (ptrdiff_t) r || ecy >= (ptrdiff_t) (ex->height - r))
            continue;
          qi = (y - q->y0) * q->nx + (x - q->x0);
          if (visited[qi])
            continue;
          ei = ((size_t) ecy - r) * db->nx + ((size_t) ecx - r);
          ts_grid_gather (q, qi, vec);
          if (ts_grid_ssd (vec, db, ei, max_ssd) < max_ssd)
            {
              visited[qi] = 1;
              queue[tail++] = n;
            }
        }
    }
  return tail;
}

/* Marks the pixels whose window matches some exemplar window within
 * `max_ssd`. Along a row, the offset that matched the previous pixel is
 * tried first: inside a copied region it matches again, no search needed. */
static bool
mark_matching (const TsWindowGrid *q, const TsWindowGrid *db, const TsPatchIndex *index,
               float max_ssd, uint8_t *matches)
{
  size_t dims = ts_grid_dims (q);
  bool ok = true;
  TS_OMP (omp parallel reduction (&& : ok))
  {
    float *v = malloc (dims * sizeof (float));
    if (!v)
      ok = false;
    TS_OMP (omp for schedule (dynamic, 4))
    for (size_t row = 0; row < q->ny; row++)
      {
        size_t last = TS_SEARCH_NONE; /* db index that matched col - 1 */
        if (!v)
          continue;
        for (size_t col = 0; col < q->nx; col++)
          {
            size_t i = row * q->nx + col, found = TS_SEARCH_NONE;
            ts_grid_gather (q, i, v);
            if (last != TS_SEARCH_NONE && last % db->nx + 1 < db->nx
                && ts_grid_ssd (v, db, last + 1, max_ssd) < max_ssd)
              found = last + 1;
            else
              found = ts_patch_index_any_within (index, v, max_ssd);
            matches[i] = found != TS_SEARCH_NONE;
            last = found;
          }
      }
    free (v);
  }
  return ok;
}

TsMeasureStatus
ts_measure_copy (const TsImage *exemplar, const TsImage *result, bool wrap_x, bool wrap_y,
                 double *copy)
{
  TsWindowGrid q, db;
  TsPatchIndex *index;
  size_t n, dims, largest = 0;
  uint8_t *matches, *visited;
  PlanePos *queue;
  float max_ssd, *vec;
  bool ok;

  *copy = NAN;
  if (!big_enough (exemplar) || !big_enough (result))
    return TS_MEASURE_TOO_SMALL;
  q = make_grid (result, TS_COPY_RADIUS, 1, wrap_x, wrap_y);
  db = make_grid (exemplar, TS_COPY_RADIUS, 1, false, false);
  n = ts_grid_count (&q);
  dims = ts_grid_dims (&q);
  max_ssd = (float) (TS_COPY_MAX_RMS * TS_COPY_MAX_RMS * (double) dims);
  index = ts_patch_index_new (&db, TS_COPY_LIFT);
  matches = malloc (n);
  visited = calloc (n, 1);
  queue = malloc (n * sizeof (PlanePos));
  vec = malloc (dims * sizeof (float));
  ok = index && matches && visited && queue && vec
       && mark_matching (&q, &db, index, max_ssd, matches);
  if (ok)
    {
      /* Seeds in raster order, each with its first matching exemplar
       * window (only seeds need that slower search). */
      for (size_t i = 0; i < n; i++)
        if (matches[i] && !visited[i])
          {
            size_t m, area;
            ts_grid_gather (&q, i, vec);
            m = ts_patch_index_first_within (index, vec, max_ssd);
            if (m == TS_SEARCH_NONE)
              continue;
            area = grow_region (&q, &db, i, m, max_ssd, visited, queue, vec);
            largest = area > largest ? area : largest;
          }
      *copy = (double) largest / (double) ts_grid_count (&db);
    }
  ts_patch_index_free (index);
  free (matches);
  free (visited);
  free (queue);
  free (vec);
  return ok ? TS_MEASURE_OK : TS_MEASURE_OUT_OF_MEMORY;
}

/* Mean |grad L| by central differences over pixels with both neighbours
 * inside the image (no wrap: the same rule for exemplar and result). */
static double
mean_gradient (const TsImage *image)
{
  size_t w = image->width, h = image->height;
  double sum = 0.0;
  for (size_t y = 1; y + 1 < h; y++)
    {
      double row = 0.0;
      for (size_t x = 1; x + 1 < w; x++)
        {
          const float *p = image->pixels + (y * w + x) * TS_CHANNELS;
          double gx = 0.5 * (p[TS_CHANNELS] - p[-TS_CHANNELS]);
          double gy = 0.5 * (p[w * TS_CHANNELS] - p[-(ptrdiff_t) (w * TS_CHANNELS)]);
          row += sqrt (gx * gx + gy * gy);
        }
      sum += row;
    }
  return sum / ((double) (w - 2) * (double) (h - 2));
}

TsMeasureStatus
ts_measure_sharpness (const TsImage *exemplar, const TsImage *result, double *sharpness)
{
  double ge, gr;
  *sharpness = NAN;
  if (!big_enough (exemplar) || !big_enough (result))
    return TS_MEASURE_TOO_SMALL;
  ge = mean_gradient (exemplar);
  gr = mean_gradient (result);
  /* A flat exemplar: 1 if the result is flat too, else infinitely sharper. */
  *sharpness = ge > 0.0 ? gr / ge : (gr > 0.0 ? INFINITY : 1.0);
  return TS_MEASURE_OK;
}

/* Sums over the inner pixels of the Sobel gradient of L (rather than
 * central differences: its direction error is far smaller, so an
 * isotropic texture reads as isotropic), with t the gradient's angle:
 * its energy, the energy within TS_AXIS_EDGE_DEGREES of the axes, and
 * the energy-weighted (cos 2t, sin 2t) and (cos 4t, sin 4t). */
typedef struct
{
  double total, axial, c2, s2, c4, s4;
} GradientSums;

static TsMeasureStatus
gradient_sums (const TsImage *image, GradientSums *g)
{
  /* Both gradient components compared to tan(10 deg) of the other. */
  double tan_limit = tan (TS_AXIS_EDGE_DEGREES * 3.14159265358979323846 / 180.0);
  ptrdiff_t row = (ptrdiff_t) (image->width * TS_CHANNELS);

  memset (g, 0, sizeof *g);
  if (!big_enough (image))
    return TS_MEASURE_TOO_SMALL;
  for (size_t y = 1; y + 1 < image->height; y++)
    for (size_t x = 1; x + 1 < image->width; x++)
      {
        const float *p = image->pixels + (y * image->width + x) * TS_CHANNELS;
        double gx = (p[-row + TS_CHANNELS] + 2.0 * p[TS_CHANNELS] + p[row + TS_CHANNELS])
                    - (p[-row - TS_CHANNELS] + 2.0 * p[-TS_CHANNELS] + p[row - TS_CHANNELS]);
        double gy = (p[row - TS_CHANNELS] + 2.0 * p[row] + p[row + TS_CHANNELS])
                    - (p[-row - TS_CHANNELS] + 2.0 * p[-row] + p[-row + TS_CHANNELS]);
        double xx = gx * gx, yy = gy * gy, energy = xx + yy;
        if (energy <= 0.0)
          continue;
        g->total += energy;
        if (fabs (gy) <= tan_limit * fabs (gx) || fabs (gx) <= tan_limit * fabs (gy))
          g->axial += energy;
        g->c2 += xx - yy;
        g->s2 += 2.0 * gx * gy;
        g->c4 += (xx * xx - 6.0 * xx * yy + yy * yy) / energy;
        g->s4 += 4.0 * gx * gy * (xx - yy) / energy;
      }
  return TS_MEASURE_OK;
}

static double
axis_share_of (const GradientSums *g)
{
  return g->total > 0.0 ? g->axial / g->total : NAN;
}

/* The second moment is large when edges share one orientation, the
 * fourth also when they share two orthogonal ones (a grid, which the
 * second cancels); both vanish on isotropic images. */
static double
anisotropy_of (const GradientSums *g)
{
  return g->total > 0.0
           ? fmax (sqrt (g->c2 * g->c2 + g->s2 * g->s2), sqrt (g->c4 * g->c4 + g->s4 * g->s4)) / g->total
           : NAN;
}

TsMeasureStatus
ts_measure_axis_edge_share (const TsImage *image, double *share)
{
  GradientSums g;
  TsMeasureStatus status = gradient_sums (image, &g);

  *share = axis_share_of (&g);
  return status;
}

TsMeasureStatus
ts_measure_anisotropy (const TsImage *image, double *anisotropy)
{
  GradientSums g;
  TsMeasureStatus status = gradient_sums (image, &g);

  *anisotropy = anisotropy_of (&g);
  return status;
}

TsMeasureStatus
ts_measure_all (const TsImage *exemplar, const TsImage *result, bool wrap_x, bool wrap_y,
                TsMeasures *out)
{
  TsMeasureStatus s;
  out->coherence = out->completeness = out->seam = out->copy = out->sharpness = NAN;
  out->axis_edges = out->axis_edges_exemplar = out->axis_edges_result = NAN;
  out->anisotropy_exemplar = NAN;
  s = ts_measure_coherence (exemplar, result, wrap_x, wrap_y, &out->coherence, &out->seam);
  if (s == TS_MEASURE_OK)
    s = ts_measure_completeness (exemplar, result, wrap_x, wrap_y, &out->completeness);
  if (s == TS_MEASURE_OK)
    s = ts_measure_copy (exemplar, result, wrap_x, wrap_y, &out->copy);
  if (s == TS_MEASURE_OK)
    s = ts_measure_sharpness (exemplar, result, &out->sharpness);
  if (s == TS_MEASURE_OK)
    {
      /* One pass over the exemplar serves its share and its anisotropy. */
      GradientSums g;
      s = gradient_sums (exemplar, &g);
      out->axis_edges_exemplar = axis_share_of (&g);
      out->anisotropy_exemplar = anisotropy_of (&g);
    }
  if (s == TS_MEASURE_OK)
    s = ts_measure_axis_edge_share (result, &out->axis_edges_result);
  if (s == TS_MEASURE_OK && out->axis_edges_exemplar > 0.0)
    out->axis_edges = out->axis_edges_result / out->axis_edges_exemplar;
  return s;
}
