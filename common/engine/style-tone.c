/* Style transfer's last step: the result's tone (its lightness blurred
 * as the style guides blur it) moved towards the picture's, so the
 * picture's light and shade show where no layout of the exemplar's
 * texture could follow them (beans as bright as the gaps between them
 * are dark). The grain, finer than the blur, stays the exemplar's.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "style-tone.h"
#include "guide-style.h"
#include "image.h"

#include <math.h>
#include <stdlib.h>

/* An image whose channel 0 is `values` (one float per pixel, `stride`
 * apart, times `scale`), blurred into a tone; a tileable side wraps. */
static TsStatus
tone_of (const float *values, size_t stride, float scale, size_t width, size_t height,
         bool wrap_x, bool wrap_y, TsImage *tone)
{
  TsStatus status = ts_image_alloc (tone, width, height);
  size_t n = width * height;

  if (status != TS_OK)
    return status;
  for (size_t i = 0; i < n; i++)
    tone->pixels[i * TS_CHANNELS] = values[i * stride] * scale;
  return ts_style_blur (tone, 0, TS_STYLE_GUIDE_BLUR, wrap_x, wrap_y);
}

double
ts_style_tone_strength (double guide_weight)
{
  return guide_weight > 0.0 && isfinite (guide_weight) ? guide_weight / (1.0 + guide_weight) : 0.0;
}

TsStatus
ts_style_tone (const TsGuides *guides, const TsImage *exemplar, bool wrap_x, bool wrap_y,
               TsImage *output)
{
  size_t w = output->width, h = output->height, n = w * h;
  size_t ex_n = exemplar->width * exemplar->height;
  double strength = ts_style_tone_strength (guides->weight);
  TsImage ex_tone = { 0 }, target_tone = { 0 }, result_tone = { 0 };
  double ex_mean, ex_sd, t_mean, t_sd;
  TsStatus status;

  if (strength <= 0.0)
    return TS_OK;
  /* As the style guides read them: the exemplar's tone with mirrored
   * borders; the picture's and the result's wrap where the result tiles,
   * so the shift does too. */
  status = tone_of (exemplar->pixels, TS_CHANNELS, 0.01f, exemplar->width, exemplar->height,
                    false, false, &ex_tone);
  if (status == TS_OK)
    status = tone_of (guides->target_guide, 1, 1.0f, w, h, wrap_x, wrap_y, &target_tone);
  if (status == TS_OK)
    status = tone_of (output->pixels, TS_CHANNELS, 0.01f, w, h, wrap_x, wrap_y, &result_tone);
  if (status == TS_OK)
    {
      /* The picture's tone moved to the exemplar's mean and spread, as
       * the style guides move it. */
      ts_guide_spread (ex_tone.pixels, TS_CHANNELS, ex_n, exemplar->pixels + 3, &ex_mean, &ex_sd);
      ts_guide_spread (target_tone.pixels, TS_CHANNELS, n, NULL, &t_mean, &t_sd);
      double gain = t_sd > 1e-6 ? ex_sd / t_sd : 1.0;
      for (size_t i = 0; i < n; i++)
        {
          float *p = output->pixels + i * TS_CHANNELS;
          double want = (target_tone.pixels[i * TS_CHANNELS] - t_mean) * gain + ex_mean;
          double shift = strength * (want - result_tone.pixels[i * TS_CHANNELS]) * 100.0;
          if (p[3] > 0.0f && isfinite (shift))
            p[0] = (float) fmin (fmax (p[0] + shift, 0.0), 100.0);
        }
    }
  ts_image_free (&ex_tone);
  ts_image_free (&target_tone);
  ts_image_free (&result_tone);
  return status;
}
