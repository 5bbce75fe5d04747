/* Shape measures of an image's phases (definitions in shape-metrics.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "shape-metrics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Lloyd iterations before k-means stops even if pixels still move. */
#define KMEANS_MAX_ITERATIONS 100

static double
lab_distance2 (const float *pixel, const double centre[3])
{
  double d = 0.0;
  for (int c = 0; c < 3; c++)
    d += ((double) pixel[c] - centre[c]) * ((double) pixel[c] - centre[c]);
  return d;
}

static int
nearest_centre (const float *pixel, const TsPhaseCentres *centres)
{
  int best = 0;
  double best_d = lab_distance2 (pixel, centres->centre[0]);
  for (int k = 1; k < centres->phases; k++)
    {
      double d = lab_distance2 (pixel, centres->centre[k]);
      if (d < best_d)
        best = k, best_d = d;
    }
  return best;
}

typedef struct
{
  float  lightness;
  size_t pixel;
} Ranked;

static int
by_lightness (const void *a, const void *b)
{
  const Ranked *x = a, *y = b;
  if (x->lightness != y->lightness)
    return x->lightness < y->lightness ? -1 : 1;
  return x->pixel < y->pixel ? -1 : x->pixel > y->pixel;
}

static int
by_centre_lightness (const void *a, const void *b)
{
  const double *x = a, *y = b;
  return x[0] < y[0] ? -1 : x[0] > y[0];
}

TsMeasureStatus
ts_shape_centres (const TsImage *exemplar, int phases, TsPhaseCentres *out)
{
  size_t count = exemplar->width * exemplar->height;
  Ranked *ranked;
  uint8_t *label;

  if (phases < 2 || phases > TS_SHAPE_MAX_PHASES || count < (size_t) phases)
    return TS_MEASURE_TOO_SMALL;
  ranked = malloc (count * sizeof *ranked);
  label = malloc (count);
  if (!ranked || !label)
    {
      free (ranked);
      free (label);
      return TS_MEASURE_OUT_OF_MEMORY;
    }
  /* start: the mean colour of each of `phases` equal-count bands of L */
  for (size_t p = 0; p < count; p++)
    ranked[p] = (Ranked) { exemplar->pixels[p * TS_CHANNELS], p };
  qsort (ranked, count, sizeof *ranked, by_lightness);
  for (size_t r = 0; r < count; r++)
    label[ranked[r].pixel] = (uint8_t) (r * (size_t) phases / count);
  free (ranked);
  out->phases = phases;
  for (int iteration = 0; iteration <= KMEANS_MAX_ITERATIONS; iteration++)
    {
      double sum[TS_SHAPE_MAX_PHASES][3] = { { 0 } };
      size_t members[TS_SHAPE_MAX_PHASES] = { 0 }, moved = 0;
      for (size_t p = 0; p < count; p++)
        {
          members[label[p]]++;
          for (int c = 0; c < 3; c++)
            sum[label[p]][c] += exemplar->pixels[p * TS_CHANNELS + (size_t) c];
        }
      for (int k = 0; k < phases; k++)
        for (int c = 0; members[k] && c < 3; c++)
          out->centre[k][c] = sum[k][c] / (double) members[k];
      if (iteration == KMEANS_MAX_ITERATIONS)
        break;
      for (size_t p = 0; p < count; p++)
        {
          uint8_t k = (uint8_t) nearest_centre (exemplar->pixels + p * TS_CHANNELS, out);
          moved += k != label[p];
          label[p] = k;
        }
      if (!moved)
        break;
    }
  free (label);
  qsort (out->centre, (size_t) phases, sizeof out->centre[0], by_centre_lightness);
  return TS_MEASURE_OK;
}

void
ts_shape_label (const TsImage *image, const TsPhaseCentres *centres, uint8_t *labels)
{
  for (size_t p = 0; p < image->width * image->height; p++)
    labels[p] = (uint8_t) nearest_centre (image->pixels + p * TS_CHANNELS, centres);
}

/* Two-point correlation of `phase` at lags 1 .. TS_SHAPE_MAX_LAG. */
static void
two_point (const uint8_t *labels, size_t w, size_t h, uint8_t phase, double *s2)
{
  for (size_t r = 1; r <= TS_SHAPE_MAX_LAG; r++)
    {
      double along[2] = { NAN, NAN }, sum = 0.0;
      int directions = 0;
      if (r < w)
        {
          size_t both = 0;
          for (size_t y = 0; y < h; y++)
            for (size_t x = 0; x + r < w; x++)
              both += labels[y * w + x] == phase && labels[y * w + x + r] == phase;
          along[0] = (double) both / (double) (h * (w - r));
        }
      if (r < h)
        {
          size_t both = 0;
          for (size_t y = 0; y + r < h; y++)
            for (size_t x = 0; x < w; x++)
              both += labels[y * w + x] == phase && labels[(y + r) * w + x] == phase;
          along[1] = (double) both / (double) ((h - r) * w);
        }
      for (int d = 0; d < 2; d++)
        if (!isnan (along[d]))
          sum += along[d], directions++;
      s2[r] = directions ? sum / directions : NAN;
    }
}

/* Mean length of the runs of `phase` along lines of `length` pixels,
 * `lines` of them, pixel i of line l at labels[l * line_step + i * step]. */
static double
mean_chord (const uint8_t *labels, size_t lines, size_t length, size_t line_step, size_t step, uint8_t phase)
{
  size_t pixels = 0, runs = 0;
  for (size_t l = 0; l < lines; l++)
    for (size_t i = 0; i < length; i++)
      if (labels[l * line_step + i * step] == phase)
        {
          pixels++;
          runs += i == 0 || labels[l * line_step + (i - 1) * step] != phase;
        }
  return runs ? (double) pixels / (double) runs : NAN;
}

typedef struct
{
  long x, y;
} Corner;

static int
by_x_then_y (const void *a, const void *b)
{
  const Corner *p = a, *q = b;
  if (p->x != q->x)
    return p->x < q->x ? -1 : 1;
  return p->y < q->y ? -1 : p->y > q->y;
}

static long
cross (Corner o, Corner a, Corner b)
{
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/* Twice the area of the convex hull of `corners` (sorted in place;
 * `hull` holds count + 1 of them). */
static long
hull_area2 (Corner *corners, size_t count, Corner *hull)
{
  size_t k = 0;
  long area2 = 0;
  qsort (corners, count, sizeof *corners, by_x_then_y);
  for (size_t i = 0; i < count; i++) /* lower chain */
    {
      while (k >= 2 && cross (hull[k - 2], hull[k - 1], corners[i]) <= 0)
        k--;
      hull[k++] = corners[i];
    }
  for (size_t i = count - 1, lower = k + 1; i-- > 0;) /* upper chain */
    {
      while (k >= lower && cross (hull[k - 2], hull[k - 1], corners[i]) <= 0)
        k--;
      hull[k++] = corners[i];
    }
  for (size_t i = 0; i + 1 < k; i++)
    area2 += hull[i].x * hull[i + 1].y - hull[i + 1].x * hull[i].y;
  return area2;
}

typedef struct
{
  size_t *stack, *members; /* the component being filled, its pixels */
  long   *row_min, *row_max;
  Corner *corners, *hull;
} Scratch;

/* Fills the 4-connected component of `phase` from `seed`, marking it in
 * `seen`; returns its pixel count and sets *hull2 to twice its hull's area. */
static size_t
component (const uint8_t *labels, size_t w, size_t h, uint8_t phase, size_t seed, uint8_t *seen,
           Scratch *s, long *hull2)
{
  size_t top = 0, area = 0, y_lo = h, y_hi = 0, corners = 0;
  s->stack[top++] = seed;
  seen[seed] = 1;
  while (top)
    {
      size_t p = s->stack[--top], x = p % w, y = p / w;
      size_t next[4];
      int count = 0;
      s->members[area++] = p;
      if (x > 0)
        next[count++] = p - 1;
      if (x + 1 < w)
        next[count++] = p + 1;
      if (y > 0)
        next[count++] = p - w;
      if (y + 1 < h)
        next[count++] = p + w;
      for (int i = 0; i < count; i++)
        if (!seen[next[i]] && labels[next[i]] == phase)
          {
            seen[next[i]] = 1;
            s->stack[top++] = next[i];
          }
    }
  /* the hull only needs each row's outermost pixel squares' corners */
  for (size_t i = 0; i < area; i++)
    {
      size_t y = s->members[i] / w;
      if (y < y_lo)
        y_lo = y;
      if (y > y_hi)
        y_hi = y;
    }
  for (size_t y = y_lo; y <= y_hi; y++)
    s->row_min[y] = (long) w, s->row_max[y] = -1;
  for (size_t i = 0; i < area; i++)
    {
      size_t y = s->members[i] / w;
      long x = (long) (s->members[i] % w);
      if (x < s->row_min[y])
        s->row_min[y] = x;
      if (x > s->row_max[y])
        s->row_max[y] = x;
    }
  for (size_t y = y_lo; y <= y_hi; y++)
    if (s->row_max[y] >= 0)
      {
        long top_edge = (long) y, bottom_edge = (long) y + 1;
        s->corners[corners++] = (Corner) { s->row_min[y], top_edge };
        s->corners[corners++] = (Corner) { s->row_min[y], bottom_edge };
        s->corners[corners++] = (Corner) { s->row_max[y] + 1, top_edge };
        s->corners[corners++] = (Corner) { s->row_max[y] + 1, bottom_edge };
      }
  *hull2 = hull_area2 (s->corners, corners, s->hull);
  return area;
}

static void
solidity (const uint8_t *labels, size_t w, size_t h, uint8_t phase, uint8_t *seen, Scratch *s,
          TsPhaseShape *out)
{
  double weighted = 0.0, total = 0.0;
  out->components = 0;
  for (size_t p = 0; p < w * h; p++)
    if (labels[p] == phase && !seen[p])
      {
        long hull2;
        size_t area = component (labels, w, h, phase, p, seen, s, &hull2);
        if (area < TS_SHAPE_MIN_COMPONENT)
          continue;
        out->components++;
        weighted += (double) area * (double) area / (0.5 * (double) hull2);
        total += (double) area;
      }
  out->solidity = total > 0.0 ? weighted / total : NAN;
}

TsMeasureStatus
ts_shape_measure_labels (const uint8_t *labels, size_t width, size_t height, int phases, TsPhaseShape *out)
{
  size_t count = width * height;
  Scratch s;
  uint8_t *seen;
  TsMeasureStatus status = TS_MEASURE_OUT_OF_MEMORY;

  if (!count || phases < 1 || phases > TS_SHAPE_MAX_PHASES)
    return TS_MEASURE_TOO_SMALL;
  s.stack = malloc (count * sizeof (size_t));
  s.members = malloc (count * sizeof (size_t));
  s.row_min = malloc (height * sizeof (long));
  s.row_max = malloc (height * sizeof (long));
  s.corners = malloc (4 * height * sizeof (Corner));
  s.hull = malloc ((4 * height + 1) * sizeof (Corner));
  seen = calloc (count, 1);
  if (s.stack && s.members && s.row_min && s.row_max && s.corners && s.hull && seen)
    {
      for (int k = 0; k < phases; k++)
        {
          size_t in = 0;
          for (size_t p = 0; p < count; p++)
            in += labels[p] == k;
          out[k].fraction = out[k].s2[0] = (double) in / (double) count;
          two_point (labels, width, height, (uint8_t) k, out[k].s2);
          out[k].chord_rows = mean_chord (labels, height, width, width, 1, (uint8_t) k);
          out[k].chord_columns = mean_chord (labels, width, height, 1, width, (uint8_t) k);
          solidity (labels, width, height, (uint8_t) k, seen, &s, &out[k]);
        }
      status = TS_MEASURE_OK;
    }
  free (s.stack);
  free (s.members);
  free (s.row_min);
  free (s.row_max);
  free (s.corners);
  free (s.hull);
  free (seen);
  return status;
}

TsMeasureStatus
ts_shape_measure (const TsImage *image, const TsPhaseCentres *centres, TsPhaseShape *out)
{
  uint8_t *labels = malloc (image->width * image->height);
  TsMeasureStatus status;
  if (!labels)
    return TS_MEASURE_OUT_OF_MEMORY;
  ts_shape_label (image, centres, labels);
  status = ts_shape_measure_labels (labels, image->width, image->height, centres->phases, out);
  free (labels);
  return status;
}
