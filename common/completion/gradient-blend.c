/* Hiding the seams of the fill in the gradient domain (Pérez et al.
 * 2003): the filled pixels keep the colour steps their sources had beside
 * them, and their values follow from those steps and the known pixels
 * around the hole (see ts_heal_gradient_blend).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Sweeps of over-relaxed Gauss-Seidel. The start (the outline offsets)
 * already holds the slow components, so few sweeps do: ten times as
 * many change the result by less than the measures resolve. */
#define TS_HEAL_BLEND_MIN_SWEEPS 24
#define TS_HEAL_BLEND_MAX_SWEEPS 40
/* Weight of the step between two filled neighbours copied from different
 * places (a seam), against 1 within a copy or next to a known pixel:
 * small, so the seam's jump is spread thinly over the copies, which keep
 * their own steps; at equal weight the blend smoothed the copies'
 * detail away. */
#define TS_HEAL_SEAM_WEIGHT 0.01f

/* Screening of the blend: weight of a copied pixel's pull to its own
 * value, TS_HEAL_SCREEN * g^2 / (g^2 + KAPPA^2) with g^2 its source's mean
 * squared L step (Lab units): busy copies (steps well above KAPPA) hold
 * to their own values and stay whole, while smooth backgrounds (steps
 * below it) still blend into the surroundings; one screening for every
 * pixel did one or the other. Fitted to the bundled heal cases
 * (docs/design.md, Known limits). */
#define TS_HEAL_SCREEN 0.2f
#define TS_HEAL_SCREEN_KAPPA 6.0f

static const int step_x[4] = { 1, -1, 0, 0 }, step_y[4] = { 0, 0, 1, -1 };

/* The colour step from the source pixel `s` to its neighbour one step
 * (dx, dy) away, into `g`; false when that neighbour is outside. */
static bool
source_step (const TsHealLevel *l, size_t s, int dx, int dy, float *g)
{
  size_t sw = l->source_width, sh = l->source_height;
  ptrdiff_t x = (ptrdiff_t) (s % sw) + dx, y = (ptrdiff_t) (s / sw) + dy;
  const float *a = l->source + s * TS_CHANNELS, *b;

  if (x < 0 || y < 0 || x >= (ptrdiff_t) sw || y >= (ptrdiff_t) sh)
    return false;
  b = l->source + ((size_t) y * sw + (size_t) x) * TS_CHANNELS;
  for (int c = 0; c < 3; c++)
    g[c] = a[c] - b[c];
  return true;
}

static float
screening (const TsHealLevel *l, size_t s)
{
  float g2 = 0.0f, g[3];

  for (int k = 0; k < 4; k++)
    if (source_step (l, s, step_x[k], step_y[k], g))
      g2 += 0.25f * g[0] * g[0];
  return TS_HEAL_SCREEN * g2 / (g2 + TS_HEAL_SCREEN_KAPPA * TS_HEAL_SCREEN_KAPPA);
}

/* The equation of one hole pixel p: value = (constant + weighted sum of
 * its hole neighbours' values) / total weight. The constant holds the
 * known neighbours' values and every neighbour's wanted step p - q, each
 * times its weight (`weight`, per direction). */
static float
pixel_equation (const TsHealLevel *l, const int32_t *picked, size_t x, size_t y, float *constant,
                float *weight)
{
  size_t w = l->width, h = l->height, p = y * w + x;
  float total = 0.0f;

  constant[0] = constant[1] = constant[2] = 0.0f;
  for (int k = 0; k < 4; k++)
    {
      ptrdiff_t qx = (ptrdiff_t) x + step_x[k], qy = (ptrdiff_t) y + step_y[k];
      float g[3] = { 0, 0, 0 }, from_p[3] = { 0, 0, 0 }, from_q[3];
      size_t q, wanted = 0;
      float wk;
      weight[k] = 0.0f;
      if (qx < 0 || qy < 0 || qx >= (ptrdiff_t) w || qy >= (ptrdiff_t) h)
        continue;
      q = (size_t) qy * w + (size_t) qx;
      wk = !l->hole[q] || picked[q] == picked[p] + step_x[k] + step_y[k] * (ptrdiff_t) l->source_width ? 1.0f : TS_HEAL_SEAM_WEIGHT;
      weight[k] = wk;
      /* The stronger of the steps p's and q's sources had there (q's seen
       * from the other side): a mean of two unrelated steps would flatten
       * the fill wherever neighbours come from different places. */
      if (source_step (l, (size_t) picked[p], step_x[k], step_y[k], from_p))
        {
          memcpy (g, from_p, sizeof g);
          wanted = 1;
        }
      if (l->hole[q] && source_step (l, (size_t) picked[q], -step_x[k], -step_y[k], from_q))
        {
          float a = from_p[0] * from_p[0] + from_p[1] * from_p[1] + from_p[2] * from_p[2];
          float b = from_q[0] * from_q[0] + from_q[1] * from_q[1] + from_q[2] * from_q[2];
          if (!wanted || b > a)
            for (int c = 0; c < 3; c++)
              g[c] = -from_q[c];
          wanted = 1;
        }
      for (int c = 0; c < 3; c++)
        {
          constant[c] += wk * (wanted ? g[c] : 0.0f);
          if (!l->hole[q])
            constant[c] += l->target[q * TS_CHANNELS + c];
        }
      total += wk;
    }
  return total;
}

TsStatus
ts_heal_gradient_blend (const TsHealLevel *l, const int32_t *picked, float *offset)
{
  size_t w = l->width, h = l->height, n = w * h, depth, sweeps;
  float *value = malloc ((n ? n : 1) * 3 * sizeof (float));
  float *constant = malloc ((n ? n : 1) * 3 * sizeof (float));
  float *count = calloc (n ? n : 1, sizeof (float));
  float *weights = calloc (n ? n : 1, 4 * sizeof (float));
  double omega;

  if (!value || !constant || !count || !weights)
    {
      free (weights);
      free (value);
      free (constant);
      free (count);
      return TS_ERROR_OUT_OF_MEMORY;
    }
#pragma omp parallel for schedule(static) if (l->hole_pixels >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t p = (size_t) y * w + x;
        if (!l->hole[p])
          continue;
        count[p] = pixel_equation (l, picked, x, (size_t) y, constant + p * 3, weights + p * 4);
        /* Screened (Bhat et al. 2008): the copy itself pulls with a weight
         * that grows with its texture, so in busy texture the correction
         * stays near the seams and the copy's windows stay whole; in
         * smooth parts it still spreads. */
        float screen = screening (l, (size_t) picked[p]);
        count[p] += screen;
        for (int c = 0; c < 3; c++)
          {
            constant[p * 3 + c] += screen * l->source[(size_t) picked[p] * TS_CHANNELS + c];
            value[p * 3 + c] = l->source[(size_t) picked[p] * TS_CHANNELS + c] + offset[p * 3 + c];
          }
      }
  /* Only the hole's bounding box holds unknowns. */
  size_t bx0, by0, bx1, by1;
  ts_heal_hole_bounds (l->hole, w, h, &bx0, &by0, &bx1, &by1);
  /* Over-relaxation tuned to the hole's depth, red then black pixels, on
   * one thread: 80 half-sweeps of a few 10^4 pixels cost less than the
   * barriers between them once another process shares the cores
   * (1024^2 with a 200^2 hole, 2 threads: 1.40 s in parallel, 0.86 s so). */
  depth = ts_heal_hole_depth (l);
  sweeps = 4 * depth + TS_HEAL_BLEND_MIN_SWEEPS;
  if (sweeps > TS_HEAL_BLEND_MAX_SWEEPS)
    sweeps = TS_HEAL_BLEND_MAX_SWEEPS;
  omega = 2.0 / (1.0 + sin (3.14159265358979 / (double) (2 * depth + 2)));
  for (size_t sweep = 0; sweep < 2 * sweeps; sweep++)
    {
      size_t colour = sweep & 1;
      for (ptrdiff_t y = (ptrdiff_t) by0; y < (ptrdiff_t) by1; y++)
        for (size_t x = bx0 + (((size_t) y + bx0 + colour) & 1); x < bx1; x += 2)
          {
            size_t p = (size_t) y * w + x;
            float sum[3];
            if (!l->hole[p] || count[p] <= 0.0f)
              continue;
            memcpy (sum, constant + p * 3, sizeof sum);
            for (int k = 0; k < 4; k++)
              {
                ptrdiff_t qx = (ptrdiff_t) x + step_x[k], qy = y + step_y[k];
                size_t q;
                if (qx < 0 || qy < 0 || qx >= (ptrdiff_t) w || qy >= (ptrdiff_t) h)
                  continue;
                q = (size_t) qy * w + (size_t) qx;
                if (l->hole[q])
                  for (int c = 0; c < 3; c++)
                    sum[c] += weights[p * 4 + (size_t) k] * value[q * 3 + c];
              }
            for (int c = 0; c < 3; c++)
              {
                float v = sum[c] / count[p];
                value[p * 3 + c] += (float) omega * (v - value[p * 3 + c]);
              }
          }
    }
#pragma omp parallel for schedule(static) if (l->hole_pixels >= TS_HEAL_PARALLEL_MIN)
  for (ptrdiff_t p = 0; p < (ptrdiff_t) n; p++)
    if (l->hole[p])
      for (int c = 0; c < 3; c++)
        offset[(size_t) p * 3 + c] =
          value[(size_t) p * 3 + c] - l->source[(size_t) picked[p] * TS_CHANNELS + c];
  free (value);
  free (constant);
  free (count);
  free (weights);
  return TS_OK;
}
