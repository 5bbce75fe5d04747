/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "guide-style.h"
#include "image.h"
#include "indexing.h"

#include <math.h>
#include <stdlib.h>

void
ts_guide_spread (const float *values, size_t stride, size_t n, const float *alpha, double *mean,
                 double *sd)
{
  double sum = 0.0, sum2 = 0.0, count = 0.0;
  for (size_t i = 0; i < n; i++)
    if (!alpha || alpha[i * TS_CHANNELS] > 0.0f)
      {
        sum += values[i * stride];
        count += 1.0;
      }
  *mean = count > 0.0 ? sum / count : 0.0;
  for (size_t i = 0; i < n; i++)
    if (!alpha || alpha[i * TS_CHANNELS] > 0.0f)
      {
        double d = values[i * stride] - *mean;
        sum2 += d * d;
      }
  *sd = count > 0.0 ? sqrt (sum2 / count) : 0.0;
}

double
ts_tone_to_exemplar (const float *ex_tone, size_t ex_stride, size_t ex_n, const float *alpha,
                     float *tone, size_t stride, size_t n)
{
  double ex_mean, ex_sd, mean, sd;

  ts_guide_spread (ex_tone, ex_stride, ex_n, alpha, &ex_mean, &ex_sd);
  ts_guide_spread (tone, stride, n, NULL, &mean, &sd);
  double gain = sd > 1e-6 ? ex_sd / sd : 1.0;
  for (size_t i = 0; i < n; i++)
    tone[i * stride] = (float) ((tone[i * stride] - mean) * gain + ex_mean);
  return ex_sd;
}

/* One pass along rows (`across`) or columns: `in` and `out` hold one
 * value per pixel, `in_stride` and `out_stride` floats apart; `wrap`
 * reads past that pass's borders from the other side. */
static void
blur_pass (const float *in, size_t in_stride, float *out, size_t out_stride, size_t w, size_t h,
           const double *kernel, int radius, bool across, bool wrap)
{
#pragma omp parallel for schedule(static)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) h; y++)
    for (size_t x = 0; x < w; x++)
      {
        double s = 0.0;
        for (int k = -radius; k <= radius; k++)
          {
            size_t sx = across ? ts_border_index ((ptrdiff_t) x + k, w, wrap) : x;
            size_t sy = across ? (size_t) y : ts_border_index (y + k, h, wrap);
            s += kernel[k + radius] * in[(sy * w + sx) * in_stride];
          }
        out[((size_t) y * w + x) * out_stride] = (float) s;
      }
}

TsStatus
ts_blur_values (float *values, size_t stride, size_t w, size_t h, double sigma, bool wrap_x,
                bool wrap_y)
{
  int radius = (int) ceil (3.0 * sigma);
  double *kernel = malloc ((size_t) (2 * radius + 1) * sizeof (double)), total = 0.0;
  size_t n = w * h;
  float *tmp = malloc ((n > 0 ? n : 1) * sizeof (float));

  if (!kernel || !tmp)
    {
      free (kernel);
      free (tmp);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (int k = -radius; k <= radius; k++)
    total += kernel[k + radius] = exp (-0.5 * k * k / (sigma * sigma));
  for (int k = 0; k <= 2 * radius; k++)
    kernel[k] /= total;
  blur_pass (values, stride, tmp, 1, w, h, kernel, radius, true, wrap_x);
  blur_pass (tmp, 1, values, stride, w, h, kernel, radius, false, wrap_y);
  free (kernel);
  free (tmp);
  return TS_OK;
}

/* Channel `c` of `image` blurred in place by a Gaussian of `sigma`
 * pixels, borders mirrored. */
static TsStatus
blur_channel (TsImage *image, size_t c, double sigma)
{
  return ts_blur_values (image->pixels + c, TS_CHANNELS, image->width, image->height, sigma,
                         false, false);
}

/* The target asks, at each tone, for the exemplar's mean contrast at
 * that tone (in TS_STYLE_TONE_STEPS steps of its range, linearly
 * between them): the grain the exemplar usually has there, neither its
 * evenest nor its busiest parts. A step without exemplar pixels takes
 * `overall`, the mean over all. */
static TsStatus
target_contrast (const TsImage *exemplar, const TsImage *ex_guide, TsImage *target_guide,
                 double overall)
{
  size_t ex_n = ts_image_pixel_count (ex_guide), out_n = ts_image_pixel_count (target_guide);
  const float *e = ex_guide->pixels;
  float *t = target_guide->pixels, low = INFINITY, high = -INFINITY;
  double sum[TS_STYLE_TONE_STEPS] = { 0 }, count[TS_STYLE_TONE_STEPS] = { 0 };
  double mean[TS_STYLE_TONE_STEPS];

  for (size_t i = 0; i < ex_n; i++)
    if (exemplar->pixels[i * TS_CHANNELS + 3] > 0.0f)
      {
        low = fminf (low, e[i * TS_CHANNELS]);
        high = fmaxf (high, e[i * TS_CHANNELS]);
      }
  double range = (double) high - (double) low;
  double step = range > 0.0 && isfinite (range) ? range / (TS_STYLE_TONE_STEPS - 1) : 1.0;
  for (size_t i = 0; i < ex_n; i++)
    if (exemplar->pixels[i * TS_CHANNELS + 3] > 0.0f)
      {
        /* Each pixel counts towards its two nearest steps, by nearness. */
        /* Clamped before the cast: extreme values may overflow to
         * infinities, and a cast out of range is undefined. */
        double at = fmin (fmax ((e[i * TS_CHANNELS] - low) / step, 0.0), TS_STYLE_TONE_STEPS - 1);
        size_t k = (size_t) at < TS_STYLE_TONE_STEPS - 1 ? (size_t) at : TS_STYLE_TONE_STEPS - 2;
        double f = fmin (fmax (at - (double) k, 0.0), 1.0);
        sum[k] += (1.0 - f) * e[i * TS_CHANNELS + 1];
        count[k] += 1.0 - f;
        sum[k + 1] += f * e[i * TS_CHANNELS + 1];
        count[k + 1] += f;
      }
  for (size_t k = 0; k < TS_STYLE_TONE_STEPS; k++)
    mean[k] = count[k] > 0.0 ? sum[k] / count[k] : overall;
  for (size_t i = 0; i < out_n; i++)
    {
      double at = fmin (fmax ((t[i * TS_CHANNELS] - low) / step, 0.0), TS_STYLE_TONE_STEPS - 1);
      size_t k = (size_t) at < TS_STYLE_TONE_STEPS - 1 ? (size_t) at : TS_STYLE_TONE_STEPS - 2;
      double f = at - (double) k;
      t[i * TS_CHANNELS + 1] = (float) ((1.0 - f) * mean[k] + f * mean[k + 1]);
    }
  return TS_OK;
}

TsStatus
ts_style_guides (const TsImage *exemplar, TsImage *ex_guide, TsImage *target_guide)
{
  size_t ex_n = ts_image_pixel_count (ex_guide), out_n = ts_image_pixel_count (target_guide);
  const float *alpha = exemplar->pixels + 3;
  double c_mean, c_sd;
  float *e = ex_guide->pixels, *t = target_guide->pixels;

  /* Channel 1 keeps the lightness while channel 0 is blurred into the
   * tone; their squared difference, blurred alike, is the grain's
   * local variance. */
  for (size_t i = 0; i < ex_n; i++)
    e[i * TS_CHANNELS + 1] = e[i * TS_CHANNELS];
  if (blur_channel (ex_guide, 0, TS_STYLE_GUIDE_BLUR) != TS_OK
      || blur_channel (target_guide, 0, TS_STYLE_GUIDE_BLUR) != TS_OK)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t i = 0; i < ex_n; i++)
    {
      float d = e[i * TS_CHANNELS + 1] - e[i * TS_CHANNELS];
      e[i * TS_CHANNELS + 1] = d * d;
    }
  if (blur_channel (ex_guide, 1, TS_STYLE_GUIDE_BLUR) != TS_OK)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t i = 0; i < ex_n; i++)
    e[i * TS_CHANNELS + 1] = sqrtf (fmaxf (e[i * TS_CHANNELS + 1], 0.0f));

  /* The target's tone moved to the exemplar's mean and spread, so each
   * part of it finds texture of its tone. */
  double ex_sd = ts_tone_to_exemplar (e, TS_CHANNELS, ex_n, alpha, t, TS_CHANNELS, out_n);

  /* The contrast counts in the tone's units, scaled to the tone's
   * spread: a contrast off by its usual spread costs as much as a tone
   * off by its usual spread, times TS_STYLE_CONTRAST_WEIGHT. */
  ts_guide_spread (e + 1, TS_CHANNELS, ex_n, alpha, &c_mean, &c_sd);
  double scale = c_sd > 1e-6 ? TS_STYLE_CONTRAST_WEIGHT * ex_sd / c_sd : 0.0;
  for (size_t i = 0; i < ex_n; i++)
    e[i * TS_CHANNELS + 1] = (float) (e[i * TS_CHANNELS + 1] * scale);
  return target_contrast (exemplar, ex_guide, target_guide, c_mean * scale);
}
