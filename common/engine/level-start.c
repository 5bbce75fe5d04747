/* The sources an output level starts from.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "level-start.h"
#include "quilt-start.h"
#include "rng.h"

#include <stdlib.h>
#include <string.h>

/* Indices of the opaque pixels of an exemplar level. */
TsStatus
ts_level_list_opaque (const TsImage *ex, int32_t **list, size_t *count)
{
  size_t n = ts_image_pixel_count (ex), c = 0;

  *list = malloc (n * sizeof (int32_t));
  if (!*list)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t i = 0; i < n; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] > 0.0f)
      (*list)[c++] = (int32_t) i;
  *count = c;
  return TS_OK;
}

/* Source coordinates and preserve weights of the initial map, resampled
 * to `level` (nearest sample; weights averaged over the block). */
TsStatus
ts_level_initial (const TsParams *params, const TsImage *ex_level, size_t level, size_t w,
                  size_t h, int32_t **source, float **preserve)
{
  size_t out_w = params->output_width, out_h = params->output_height, block = (size_t) 1 << level;

  *source = malloc (w * h * sizeof (int32_t));
  *preserve = params->preserve ? malloc (w * h * sizeof (float)) : NULL;
  if (!*source || (params->preserve && !*preserve))
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t fx = x << level, fy = y << level;
        const int32_t *s = params->initial_source + 2 * (fy * out_w + fx);
        size_t sx = (size_t) s[0] >> level, sy = (size_t) s[1] >> level;
        sx = sx < ex_level->width ? sx : ex_level->width - 1;
        sy = sy < ex_level->height ? sy : ex_level->height - 1;
        (*source)[y * w + x] = (int32_t) (sy * ex_level->width + sx);
        if (*preserve)
          {
            double sum = 0.0;
            size_t n = 0;
            for (size_t by = fy; by < fy + block && by < out_h; by++)
              for (size_t bx = fx; bx < fx + block && bx < out_w; bx++, n++)
                sum += params->preserve[by * out_w + bx];
            (*preserve)[y * w + x] = (float) (sum / (double) n);
          }
      }
  return TS_OK;
}

/* Random exemplar blocks of side `block` (Kwatra et al.'s random patches):
 * unlike single random pixels, their votes agree, so the first E-step does
 * not average the start into the exemplar's mean colour, which would
 * collapse textures with flat areas onto them. */
static void
random_blocks (TsLevelState *state, const TsParams *params, size_t level, size_t block)
{
  const TsImage *ex = state->exemplar;
  uint64_t jitter = ts_random (params->seed, (uint32_t) level, 0, 0, 4);
  size_t ox = (size_t) (jitter % block), oy = (size_t) ((jitter >> 32) % block);

#pragma omp parallel for schedule(static)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) state->height; y++)
    for (size_t x = 0; x < state->width; x++)
      {
        size_t bx = (x + ox) / block, by = ((size_t) y + oy) / block;
        uint64_t r = ts_random (params->seed, (uint32_t) level, 0, by * 65536 + bx, 1);
        int32_t corner = state->opaque[ts_random_below (r, state->opaque_count)];
        size_t sx = (size_t) corner % ex->width + (x + ox) % block;
        size_t sy = (size_t) corner / ex->width + ((size_t) y + oy) % block;
        size_t p = (size_t) y * state->width + x;
        int32_t s;

        sx = sx < ex->width ? sx : ex->width - 1 - (sx - ex->width) % ex->width;
        sy = sy < ex->height ? sy : ex->height - 1 - (sy - ex->height) % ex->height;
        s = (int32_t) (sy * ex->width + sx);
        if (ex->pixels[(size_t) s * TS_CHANNELS + 3] <= 0.0f)
          s = state->opaque[ts_random_below (ts_random (params->seed, (uint32_t) level, 0, p, 5),
                                             state->opaque_count)];
        state->source[p] = s;
      }
}

/* The child (cx, cy) of the coarser exemplar pixel `parent`, or the
 * first opaque one of its children if that one is transparent: a pixel
 * that no matched window reaches keeps its start, which must be a pixel
 * the texture has. */
static int32_t
child_source (const TsImage *ex, int32_t parent, size_t coarser_ex_w, size_t cx, size_t cy)
{
  size_t px = 2 * ((size_t) parent % coarser_ex_w), py = 2 * ((size_t) parent / coarser_ex_w);
  int32_t first = -1;

  for (size_t i = 0; i < 4; i++)
    {
      size_t sx = px + (cx ^ (i & 1)), sy = py + (cy ^ (i >> 1));
      sx = sx < ex->width ? sx : ex->width - 1;
      sy = sy < ex->height ? sy : ex->height - 1;
      int32_t s = (int32_t) (sy * ex->width + sx);
      if (ex->pixels[(size_t) s * TS_CHANNELS + 3] > 0.0f)
        return s;
      if (first < 0)
        first = s;
    }
  return first;
}

/* Starting sources of a level: at the coarsest level the guide's blocks
 * under a guide, else a quilt of large exemplar patches (random exemplar
 * blocks where the initial map replaces it anyway); at the others the
 * children of the coarser level's sources. */
TsStatus
ts_level_start_sources (TsLevelState *state, const TsParams *params, size_t level, size_t block,
                        const int32_t *coarser, size_t coarser_w, size_t coarser_ex_w)
{
  const TsImage *ex = state->exemplar;

  if (!coarser && state->guide && !state->guide->lattice)
    ts_guide_start_blocks (state->guide, ex, state->source, state->width, state->height,
                           params->seed, level, block);
  else if (!coarser && !state->preserve_source)
    {
      TsStatus status = ts_quilt_start (state, params->seed, (uint32_t) level);
      if (status != TS_OK)
        return status;
    }
  else if (!coarser)
    random_blocks (state, params, level, block);
  else
    {
#pragma omp parallel for schedule(static)
      for (ptrdiff_t y = 0; y < (ptrdiff_t) state->height; y++)
        for (size_t x = 0; x < state->width; x++)
          {
            size_t p = (size_t) y * state->width + x;
            int32_t parent = coarser[((size_t) y / 2) * coarser_w + x / 2];
            state->source[p] = child_source (ex, parent, coarser_ex_w, x & 1, (size_t) y & 1);
          }
    }
  if (state->preserve_source && !coarser)
    memcpy (state->source, state->preserve_source, state->width * state->height * sizeof (int32_t));
  /* Fully preserved pixels start (and stay: the E-step skips them) at
   * their initial source, even where a coarser parent moved. */
  for (size_t p = 0; state->preserve && p < state->width * state->height; p++)
    if (state->preserve[p] >= 1.0f)
      state->source[p] = state->preserve_source[p];
  return TS_OK;
}
