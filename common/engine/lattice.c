/* The lattice estimate: the normalised autocorrelation of lightness
 * (through the FFT), its periods (peaks along which the autocorrelation
 * itself repeats), refined by a least-squares fit to every peak near a
 * lattice point.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "lattice.h"
#include "fft.h"

#include <math.h>
#include <stdlib.h>

/* The estimate runs on the finest pyramid level whose sides are at most
 * this: a period longer than half of it would be seen fewer than twice
 * in most exemplars anyway, and the FFT stays small. */
#define TS_LATTICE_ESTIMATE_SIDE 512
/* Shortest period, in pixels of the level: a shorter one is aliased at
 * the next coarser level, where the guide starts (lattice-guide.c), and
 * the finest neighbourhoods (5 px and up) hold it whole anyway. */
#define TS_LATTICE_SHORTEST 4.0
/* A second period lies at least this many pixels off the first one's
 * line: nearer, it is the first one's harmonic seen through rounding. */
#define TS_LATTICE_OFF_LINE 1.5
/* A peak counts in the lattice's fit when it lies this near a lattice
 * point (pixels): the rounding of two integer periods, each off by at
 * most half a pixel. */
#define TS_LATTICE_FIT_RADIUS 1.5
/* A period is one when the texture repeats along it, and then so does
 * its autocorrelation: shifted by the period, the autocorrelation must
 * explain at least this share of its own variance around the origin
 * (see repeats_along). A streak, a ridge or a one-off match between two
 * features has a peak there, but what surrounds the origin is not
 * repeated around it. */
#define TS_LATTICE_REPEAT_SHARE (1.0 / 3.0)

typedef struct
{
  double *r;              /* autocorrelation, (2 ry + 1) rows of 2 rx + 1 */
  int     rx, ry;         /* largest offsets held                          */
  int     limit_x, limit_y; /* largest offsets searched: half the sides    */
  double  origin_fall;    /* 1 - the lowest value two pixels from the origin:
                             how steeply the origin's peak falls          */
} Correlation;

static double
at (const Correlation *c, int dx, int dy)
{
  return c->r[(size_t) (dy + c->ry) * (size_t) (2 * c->rx + 1) + (size_t) (dx + c->rx)];
}

/* Normalised autocorrelation of L over offsets up to half the sides
 * (mean removed, each offset's sum divided by its overlap and the
 * variance). Transparent pixels count as the mean. */
static TsStatus
correlate (const TsImage *ex, Correlation *c)
{
  size_t w = ex->width, h = ex->height, n = w * h, fw, fh;
  double sum = 0.0, squares = 0.0, count = 0.0, mean, variance;
  double complex *data;

  c->limit_x = (int) (w / 2);
  c->limit_y = (int) (h / 2);
  /* two more each way for the rings around the outermost offsets */
  c->rx = c->limit_x + 2;
  c->ry = c->limit_y + 2;
  fw = ts_fft_size (w + (size_t) c->rx);
  fh = ts_fft_size (h + (size_t) c->ry);
  if (fw == 0 || fh == 0)
    return TS_ERROR_OUT_OF_MEMORY;
  data = calloc (fw * fh, sizeof *data);
  c->r = malloc ((size_t) (2 * c->rx + 1) * (size_t) (2 * c->ry + 1) * sizeof (double));
  if (!data || !c->r)
    {
      free (data);
      free (c->r);
      c->r = NULL;
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t i = 0; i < n; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] > 0.0f)
      {
        sum += ex->pixels[i * TS_CHANNELS];
        count += 1.0;
      }
  mean = count > 0.0 ? sum / count : 0.0;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        const float *p = ex->pixels + (y * w + x) * TS_CHANNELS;
        double d = p[3] > 0.0f ? p[0] - mean : 0.0;
        data[y * fw + x] = d;
        squares += d * d;
      }
  variance = count > 0.0 ? squares / count : 0.0;
  if (!ts_fft_2d (data, fw, fh, false))
    {
      free (data);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t i = 0; i < fw * fh; i++)
    data[i] = creal (data[i]) * creal (data[i]) + cimag (data[i]) * cimag (data[i]);
  if (!ts_fft_2d (data, fw, fh, true))
    {
      free (data);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (int dy = -c->ry; dy <= c->ry; dy++)
    for (int dx = -c->rx; dx <= c->rx; dx++)
      {
        size_t fx = dx < 0 ? fw - (size_t) -dx : (size_t) dx;
        size_t fy = dy < 0 ? fh - (size_t) -dy : (size_t) dy;
        size_t overlap = (w - (size_t) abs (dx)) * (h - (size_t) abs (dy));
        double *r = &c->r[(size_t) (dy + c->ry) * (size_t) (2 * c->rx + 1) + (size_t) (dx + c->rx)];
        /* A flat exemplar has no lattice: every offset reads 0. */
        *r = variance > 1e-9 ? creal (data[fy * fw + fx]) / ((double) overlap * variance) : 0.0;
      }
  free (data);
  return TS_OK;
}

/* The autocorrelation at a sub-pixel offset (bilinear). */
static double
at_subpixel (const Correlation *c, double x, double y)
{
  int x0 = (int) floor (x), y0 = (int) floor (y);
  double fx = x - x0, fy = y - y0;
  return (1.0 - fy) * ((1.0 - fx) * at (c, x0, y0) + fx * at (c, x0 + 1, y0)) +
         fy * ((1.0 - fx) * at (c, x0, y0 + 1) + fx * at (c, x0 + 1, y0 + 1));
}

/* Whether the texture repeats along (vx, vy): over the offsets d within
 * half the period of the origin (each way), R(d + v) predicts R(d) so
 * that the squared misses are at most 1 - TS_LATTICE_REPEAT_SHARE of
 * R's variance there. An exact repeat gives R(d + v) = R(d). */
static bool
repeats_along (const Correlation *c, double vx, double vy)
{
  int radius = (int) (0.5 * hypot (vx, vy));
  double n = 0.0, sum = 0.0, squares = 0.0, misses = 0.0, scatter;

  for (int y = -radius; y <= radius; y++)
    for (int x = -radius; x <= radius; x++)
      {
        double r, shifted;
        if (fabs (x + vx) > c->limit_x || fabs (y + vy) > c->limit_y)
          continue;
        r = at (c, x, y);
        shifted = at_subpixel (c, x + vx, y + vy);
        n += 1.0;
        sum += r;
        squares += r * r;
        misses += (shifted - r) * (shifted - r);
      }
  /* n times R's variance there, as `misses` sums n squares */
  scatter = n > 0.0 ? squares - sum * sum / n : 0.0;
  return scatter > 1e-12 && misses <= (1.0 - TS_LATTICE_REPEAT_SHARE) * scatter;
}

/* Whether (dx, dy) is a local maximum of the autocorrelation (ties
 * broken by row order, so a plateau gives one peak). */
static bool
is_peak (const Correlation *c, int dx, int dy)
{
  double centre = at (c, dx, dy);
  for (int ny = -1; ny <= 1; ny++)
    for (int nx = -1; nx <= 1; nx++)
      {
        double v;
        if (nx == 0 && ny == 0)
          continue;
        v = at (c, dx + nx, dy + ny);
        if (ny < 0 || (ny == 0 && nx < 0) ? v >= centre : v > centre)
          return false;
      }
  return true;
}

/* The highest and lowest autocorrelation on the ring of offsets two
 * pixels from (dx, dy) (the border of its 5x5 square): just outside a
 * peak's own top. */
static void
ring (const Correlation *c, int dx, int dy, double *high, double *low)
{
  *high = -INFINITY;
  *low = INFINITY;
  for (int ny = -2; ny <= 2; ny++)
    for (int nx = -2; nx <= 2; nx += (ny == -2 || ny == 2) ? 1 : 4)
      {
        double v = at (c, dx + nx, dy + ny);
        *high = fmax (*high, v);
        *low = fmin (*low, v);
      }
}

/* Whether the autocorrelation falls to half of the lower end or below
 * somewhere on the segment between offsets p and q: two separate peaks
 * (a ridge, as stripes have along their length, never falls). */
static bool
separated (const Correlation *c, const int p[2], const int q[2])
{
  double ends = fmin (at (c, p[0], p[1]), at (c, q[0], q[1]));
  int steps = abs (q[0] - p[0]) > abs (q[1] - p[1]) ? abs (q[0] - p[0]) : abs (q[1] - p[1]);

  for (int i = 1; i < steps; i++)
    {
      double t = (double) i / (double) steps;
      int x = (int) lround (p[0] + t * (q[0] - p[0]));
      int y = (int) lround (p[1] + t * (q[1] - p[1]));
      if (at (c, x, y) <= ends / 2.0)
        return true;
    }
  return false;
}

/* Whether the local maximum (dx, dy) repeats the origin's own peak:
 * around it the autocorrelation falls, each way, at least a quarter as
 * much (relative to its height) as it falls around the origin that way
 * (a real texture's periods are blurred copies of the origin's peak). A
 * bump on a ridge (a line of mortar, a stripe) does not: along the ridge
 * it stays level where the origin falls. */
static bool
repeats_origin (const Correlation *c, int dx, int dy)
{
  double r = at (c, dx, dy);
  for (int ny = -2; ny <= 2; ny++)
    for (int nx = -2; nx <= 2; nx += (ny == -2 || ny == 2) ? 1 : 4)
      if (r - at (c, dx + nx, dy + ny) < 0.25 * r * (1.0 - at (c, nx, ny)))
        return false;
  return true;
}

/* Whether the autocorrelation falls around (dx, dy), on every side
 * (`every_way`: a peak) or on some side (a ridge: bands that repeat one
 * way only), at least a quarter as much (relative to its height) as
 * around the origin at its steepest. */
static bool
falls (const Correlation *c, int dx, int dy, bool every_way)
{
  double high, low, r = at (c, dx, dy);
  ring (c, dx, dy, &high, &low);
  return r - (every_way ? high : low) >= 0.25 * r * c->origin_fall;
}

/* The direction of the ridge through (dx, dy): the principal axis of its
 * 5x5 square's offsets weighted by how far each rises above the ring's
 * lowest value. */
static void
ridge_direction (const Correlation *c, int dx, int dy, double dir[2])
{
  double high, low, xx = 0, xy = 0, yy = 0, angle;

  ring (c, dx, dy, &high, &low);
  for (int ny = -2; ny <= 2; ny++)
    for (int nx = -2; nx <= 2; nx++)
      {
        double w = fmax (0.0, at (c, dx + nx, dy + ny) - low);
        xx += w * nx * nx;
        xy += w * nx * ny;
        yy += w * ny * ny;
      }
  angle = 0.5 * atan2 (2.0 * xy, xx - yy);
  dir[0] = cos (angle);
  dir[1] = sin (angle);
}

static bool
inside (const Correlation *c, int dx, int dy)
{
  return abs (dx) <= c->limit_x && abs (dy) <= c->limit_y;
}

/* The peak nearest (x, y) within one pixel, to sub-pixel precision by a
 * parabola through it and its neighbours on each axis; false if none. */
static bool
peak_near (const Correlation *c, double x, double y, double least, double out[2])
{
  int bx = 0, by = 0;
  double best = -INFINITY;

  for (int ny = -1; ny <= 1; ny++)
    for (int nx = -1; nx <= 1; nx++)
      {
        int px = (int) lround (x) + nx, py = (int) lround (y) + ny;
        if (inside (c, px, py) && at (c, px, py) > best)
          {
            best = at (c, px, py);
            bx = px;
            by = py;
          }
      }
  if (!(best >= least) || !is_peak (c, bx, by))
    return false;
  out[0] = bx;
  out[1] = by;
  for (int axis = 0; axis < 2; axis++)
    {
      double lo = axis ? at (c, bx, by - 1) : at (c, bx - 1, by);
      double hi = axis ? at (c, bx, by + 1) : at (c, bx + 1, by);
      double curve = lo - 2.0 * best + hi;
      if (curve < 0.0)
        out[axis] += 0.5 * (lo - hi) / curve;
    }
  return true;
}

/* Refines the periods on every peak of at least half the first
 * period's value that lies within TS_LATTICE_FIT_RADIUS of a lattice
 * point: a least-squares fit of the lattice to the peaks' sub-pixel
 * positions, weighted by their values, twice (the second with the
 * first's points). Far peaks pin a period n times more finely. */
static void
fit_lattice (const Correlation *c, TsLatticeEstimate *out)
{
  double least = out->strength / 2.0;
  size_t k = out->vectors;

  for (int round_ = 0; round_ < 2; round_++)
    {
      const double *a = out->vector[0], *b = out->vector[1];
      double det = k == 2 ? a[0] * b[1] - a[1] * b[0] : a[0] * a[0] + a[1] * a[1];
      double nn = 0, nm = 0, mm = 0, np[2] = { 0, 0 }, mp[2] = { 0, 0 };
      for (int dy = 0; dy <= c->limit_y; dy++)
        for (int dx = -c->limit_x; dx <= c->limit_x; dx++)
          {
            double pos[2], n, m = 0.0, w = at (c, dx, dy);
            /* each peak once: the one whose sub-pixel position rounds here */
            if ((dy == 0 && dx <= 0) || !(w >= least) || !peak_near (c, dx, dy, least, pos) ||
                fabs (pos[0] - dx) > 0.5 || fabs (pos[1] - dy) > 0.5)
              continue;
            if (k == 2)
              {
                n = round ((b[1] * pos[0] - b[0] * pos[1]) / det);
                m = round ((a[0] * pos[1] - a[1] * pos[0]) / det);
              }
            else
              n = round ((a[0] * pos[0] + a[1] * pos[1]) / det);
            if (n == 0.0 && m == 0.0)
              continue;
            if (hypot (pos[0] - n * a[0] - m * (k == 2 ? b[0] : 0.0),
                       pos[1] - n * a[1] - m * (k == 2 ? b[1] : 0.0)) > TS_LATTICE_FIT_RADIUS)
              continue;
            nn += w * n * n;
            nm += w * n * m;
            mm += w * m * m;
            for (int i = 0; i < 2; i++)
              {
                np[i] += w * n * pos[i];
                mp[i] += w * m * pos[i];
              }
          }
      if (k == 1 && nn > 0.0)
        for (int i = 0; i < 2; i++)
          out->vector[0][i] = np[i] / nn;
      else if (k == 2 && nn * mm - nm * nm > 1e-9)
        {
          double d = nn * mm - nm * nm;
          for (int i = 0; i < 2; i++)
            {
              out->vector[0][i] = (mm * np[i] - nm * mp[i]) / d;
              out->vector[1][i] = (nn * mp[i] - nm * np[i]) / d;
            }
        }
    }
}

/* The shortest basis of the lattice a, b span (Lagrange-Gauss). */
static void
reduce_basis (double a[2], double b[2])
{
  for (int i = 0; i < 16; i++)
    {
      double aa = a[0] * a[0] + a[1] * a[1], bb = b[0] * b[0] + b[1] * b[1], m;
      if (bb < aa)
        {
          double t[2] = { a[0], a[1] };
          a[0] = b[0], a[1] = b[1], b[0] = t[0], b[1] = t[1];
          continue;
        }
      m = round ((a[0] * b[0] + a[1] * b[1]) / aa);
      if (m == 0.0)
        break;
      b[0] -= m * a[0];
      b[1] -= m * a[1];
    }
}

/* Whether d plus every multiple of the period `a` (those in the map)
 * stands apart from the origin, as the periods of a lattice do; on
 * stripes one of them runs along the ridge through the origin. */
static bool
periods_apart (const Correlation *c, const int a[2], const int d[2])
{
  const int origin[2] = { 0, 0 };
  for (int m = -c->limit_x - c->limit_y; m <= c->limit_x + c->limit_y; m++)
    {
      int e[2] = { d[0] + m * a[0], d[1] + m * a[1] };
      bool apart = false;
      if (m == 0 || !inside (c, e[0], e[1]))
        continue;
      /* A lattice with a period below the shortest is not one. */
      if ((double) e[0] * e[0] + (double) e[1] * e[1] < TS_LATTICE_SHORTEST * TS_LATTICE_SHORTEST)
        return false;
      if (separated (c, origin, e))
        continue;
      /* Or a peak of the origin's shape on a ridge (a brick's length on
       * its row of mortar). */
      for (int ny = -1; ny <= 1 && !apart; ny++)
        for (int nx = -1; nx <= 1 && !apart; nx++)
          apart = inside (c, e[0] + nx, e[1] + ny) && is_peak (c, e[0] + nx, e[1] + ny) &&
                  falls (c, e[0] + nx, e[1] + ny, true);
      if (!apart)
        return false;
    }
  return true;
}

/* The periods: the shortest peak apart from the origin that repeats
 * its shape and along which the texture repeats, of at least half the
 * highest such peak's value, then the shortest such peak off its line
 * and apart from it. Without such a peak, the nearest ridge of at least
 * half the highest (bands), its period taken across it, if the texture
 * repeats along that. */
static void
find_periods (const Correlation *c, TsLatticeEstimate *out)
{
  const int origin[2] = { 0, 0 };
  double highest = 0.0, highest_ridge = 0.0;
  int best[2][2] = { { 0, 0 }, { 0, 0 } }, ridge[2] = { 0, 0 };
  size_t found = 0;
  bool ridge_found = false;

  for (int pass = 0; pass < 3; pass++)
    for (int dy = 0; dy <= c->limit_y; dy++)
      for (int dx = -c->limit_x; dx <= c->limit_x; dx++)
        {
          int d[2] = { dx, dy };
          double r = at (c, dx, dy), length2 = (double) dx * dx + (double) dy * dy;
          if ((dy == 0 && dx <= 0) || length2 < TS_LATTICE_SHORTEST * TS_LATTICE_SHORTEST ||
              r < TS_LATTICE_LEAST_PEAK || !is_peak (c, dx, dy) || !separated (c, origin, d))
            continue;
          if (!repeats_origin (c, dx, dy))
            {
              /* bands: the nearest ridge of at least half the highest */
              if (pass == 0 && falls (c, dx, dy, false))
                highest_ridge = fmax (highest_ridge, r);
              else if (pass == 1 && r >= highest_ridge / 2.0 && falls (c, dx, dy, false) &&
                       (!ridge_found || length2 < (double) ridge[0] * ridge[0] +
                                                    (double) ridge[1] * ridge[1]))
                {
                  ridge[0] = dx;
                  ridge[1] = dy;
                  ridge_found = true;
                }
              continue;
            }
          /* the costliest test last */
          if (pass == 0)
            {
              if (r > highest && repeats_along (c, dx, dy))
                highest = r;
              continue;
            }
          if (r < highest / 2.0 || (pass == 2 && found == 0))
            continue;
          if (pass == 2)
            {
              double cross = (double) best[0][0] * dy - (double) best[0][1] * dx;
              if (fabs (cross) < TS_LATTICE_OFF_LINE * hypot (best[0][0], best[0][1]) ||
                  !separated (c, best[0], d) || !periods_apart (c, best[0], d))
                continue;
            }
          size_t k = (size_t) pass - 1;
          if ((found <= k ||
               length2 < (double) best[k][0] * best[k][0] + (double) best[k][1] * best[k][1]) &&
              repeats_along (c, dx, dy))
            {
              best[k][0] = dx;
              best[k][1] = dy;
              found = k + 1;
            }
        }
  bool on_ridge = found == 0 && ridge_found;
  if (on_ridge)
    {
      best[0][0] = ridge[0];
      best[0][1] = ridge[1];
      found = 1;
    }
  out->vectors = found;
  if (found == 0)
    return;
  out->strength = at (c, best[0][0], best[0][1]);
  for (size_t k = 0; k < found; k++)
    for (int i = 0; i < 2; i++)
      out->vector[k][i] = best[k][i];
  if (on_ridge)
    {
      /* Bands repeat across their ridge only: the period is the offset
       * without its part along the ridge. */
      double dir[2], along;
      ridge_direction (c, best[0][0], best[0][1], dir);
      along = best[0][0] * dir[0] + best[0][1] * dir[1];
      out->vector[0][0] -= along * dir[0];
      out->vector[0][1] -= along * dir[1];
      if (!repeats_along (c, out->vector[0][0], out->vector[0][1]))
        {
          *out = (TsLatticeEstimate) { 0 };
          return;
        }
    }
  fit_lattice (c, out);
  if (found == 2)
    reduce_basis (out->vector[0], out->vector[1]);
}

TsStatus
ts_lattice_estimate (const TsPyramid *pyramid, TsLatticeEstimate *out)
{
  size_t level = 0;
  Correlation c = { 0 };
  TsStatus status;

  *out = (TsLatticeEstimate) { 0 };
  while (level + 1 < pyramid->levels &&
         (pyramid->level[level].width > TS_LATTICE_ESTIMATE_SIDE ||
          pyramid->level[level].height > TS_LATTICE_ESTIMATE_SIDE))
    level++;
  /* Two periods of the shortest kind must fit. */
  if (pyramid->level[level].width < 4 * TS_LATTICE_SHORTEST ||
      pyramid->level[level].height < 4 * TS_LATTICE_SHORTEST)
    return TS_OK;
  status = correlate (&pyramid->level[level], &c);
  if (status != TS_OK)
    return status;
  double origin_high, origin_low;
  ring (&c, 0, 0, &origin_high, &origin_low);
  c.origin_fall = 1.0 - origin_low;
  find_periods (&c, out);
  free (c.r);
  for (size_t k = 0; k < out->vectors; k++)
    {
      out->vector[k][0] *= (double) ((size_t) 1 << level);
      out->vector[k][1] *= (double) ((size_t) 1 << level);
    }
  return TS_OK;
}
