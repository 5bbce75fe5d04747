/* Style transfer's last step: the result's tone (its lightness blurred
 * as the style guides blur it) moved towards the picture's, so the
 * picture's light and shade show where no layout of the exemplar's
 * texture could follow them (beans as bright as the gaps between them
 * are dark). The grain, finer than the blur, stays the exemplar's.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "style-tone.h"
#include "guide-style.h"

#include <math.h>
#include <stdlib.h>

/* One float per pixel: `values` (`stride` floats apart) times `scale`,
 * blurred into a tone; a tileable side wraps. NULL if out of memory. */
static float *
tone_of (const float *values, size_t stride, float scale, size_t width, size_t height,
         bool wrap_x, bool wrap_y)
{
  size_t n = width * height;
  float *tone = malloc ((n ? n : 1) * sizeof (float));

  if (!tone)
    return NULL;
  for (size_t i = 0; i < n; i++)
    tone[i] = values[i * stride] * scale;
  if (ts_blur_values (tone, 1, width, height, TS_STYLE_GUIDE_BLUR, wrap_x, wrap_y) != TS_OK)
    {
      free (tone);
      return NULL;
    }
  return tone;
}

/* How far the tone moves for a guide weight: weight / (1 + weight), the
 * guide's share against the texture's coherence (0 leaves the result as
 * synthesised). */
static double
tone_strength (double guide_weight)
{
  return guide_weight > 0.0 && isfinite (guide_weight) ? guide_weight / (1.0 + guide_weight) : 0.0;
}

TsStatus
ts_style_tone (const TsGuides *guides, const TsImage *exemplar, bool wrap_x, bool wrap_y,
               TsImage *output)
{
  size_t w = output->width, h = output->height, n = w * h;
  size_t ex_n = exemplar->width * exemplar->height;
  double strength = tone_strength (guides->weight);
  float *ex_tone = NULL, *target_tone = NULL, *result_tone = NULL;

  if (strength <= 0.0)
    return TS_OK;
  /* As the style guides read them: the exemplar's tone with mirrored
   * borders; the picture's and the result's wrap where the result tiles,
   * so the shift does too. */
  ex_tone = tone_of (exemplar->pixels, TS_CHANNELS, 0.01f, exemplar->width, exemplar->height,
                     false, false);
  if (ex_tone)
    target_tone = tone_of (guides->target_guide, 1, 1.0f, w, h, wrap_x, wrap_y);
  if (target_tone)
    result_tone = tone_of (output->pixels, TS_CHANNELS, 0.01f, w, h, wrap_x, wrap_y);
  bool ok = result_tone != NULL;
  if (ok)
    {
      /* The picture's tone moved to the exemplar's mean and spread, as
       * the style guides move it. */
      ts_tone_to_exemplar (ex_tone, 1, ex_n, exemplar->pixels + 3, target_tone, 1, n);
      for (size_t i = 0; i < n; i++)
        {
          float *p = output->pixels + i * TS_CHANNELS;
          double shift = strength * ((double) target_tone[i] - result_tone[i]) * 100.0;
          if (p[3] > 0.0f && isfinite (shift))
            p[0] = (float) fmin (fmax (p[0] + shift, 0.0), 100.0);
        }
    }
  free (ex_tone);
  free (target_tone);
  free (result_tone);
  return ok ? TS_OK : TS_ERROR_OUT_OF_MEMORY;
}
