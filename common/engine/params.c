/* Parameter defaults, validation (the one place), memory estimate.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "guide-params.h"
#include "image.h"
#include "region-bound.h"
#include "schedule.h"
#include "error.h"
#include "i18n.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* The default quality, 2, gives the best median coherence and
 * completeness over the bundled exemplars, and is fast; higher ones
 * are slower and no better. */

void
ts_params_init (TsParams *params)
{
  memset (params, 0, sizeof *params);
  params->output_width = 512;
  params->output_height = 512;
  params->quality = TS_DEFAULT_QUALITY;
  /* Keeping the output's colour histogram to the exemplar's stops
   * common colours crowding out rare ones: better completeness,
   * coherence and sharpness at the same copy figure, over the bundled
   * exemplars. */
  params->histogram_matching = true;
}

size_t
ts_default_memory_limit (void)
{
  long pages = sysconf (_SC_PHYS_PAGES), page_size = sysconf (_SC_PAGESIZE);
  size_t gib = (size_t) 1 << 30, limit = gib;

  if (pages > 0 && page_size > 0)
    {
      double quarter = (double) pages * (double) page_size / 4.0;
      if (quarter > (double) limit)
        limit = quarter >= (double) SIZE_MAX ? SIZE_MAX : (size_t) quarter;
    }
  return limit;
}

static bool
exemplar_has_opaque_pixel (const TsImage *exemplar)
{
  size_t n = exemplar->width * exemplar->height;
  for (size_t i = 0; i < n; i++)
    {
      /* As the engine reads it: a non-finite alpha counts as 0. */
      float alpha = exemplar->pixels[i * TS_CHANNELS + 3];
      if (alpha > 0.0f && isfinite (alpha))
        return true;
    }
  return false;
}

TsStatus
ts_validate_search_params (int quality, int patch_size, int max_iterations, TsError *error)
{
  if (quality < TS_MIN_QUALITY || quality > TS_MAX_QUALITY)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "quality must be %d to %d, got %d",
                    TS_MIN_QUALITY, TS_MAX_QUALITY, quality);
  if (patch_size != 0 &&
      (patch_size < TS_MIN_PATCH_SIZE || patch_size > TS_MAX_PATCH_SIZE || patch_size % 2 == 0))
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "patch size must be 0 (automatic) or odd, %d to %d; got %d",
                    TS_MIN_PATCH_SIZE, TS_MAX_PATCH_SIZE, patch_size);
  if (max_iterations < 0 || max_iterations > TS_MAX_ITERATIONS)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "iterations must be 0 (automatic) to %d, got %d",
                    TS_MAX_ITERATIONS, max_iterations);
  return TS_OK;
}

TsStatus
ts_store_estimate (double estimate, size_t *bytes, TsError *error)
{
  if (!bytes)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no place to store the estimate");
  *bytes = estimate >= (double) SIZE_MAX ? SIZE_MAX : (size_t) estimate;
  return TS_OK;
}

static TsStatus
validate_without_memory (const TsParams *params, const TsImage *exemplar, TsError *error)
{
  TsStatus status;

  if (!params || !exemplar)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no parameters or no exemplar given");
  if (exemplar->width == 0 || exemplar->height == 0 || !exemplar->pixels)
    return ts_fail (error, TS_ERROR_EMPTY_EXEMPLAR, "the exemplar has no pixels (%zux%zu)",
                    exemplar->width, exemplar->height);
  if (exemplar->width > TS_MAX_OUTPUT_SIDE || exemplar->height > TS_MAX_OUTPUT_SIDE)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the exemplar is %zux%zu; its sides must be at most %d pixels",
                    exemplar->width, exemplar->height, TS_MAX_OUTPUT_SIDE);
  if (params->output_width < 1 || params->output_width > TS_MAX_OUTPUT_SIDE ||
      params->output_height < 1 || params->output_height > TS_MAX_OUTPUT_SIDE)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the output size %zux%zu is out of range: width and height must be 1 to %d",
                    params->output_width, params->output_height, TS_MAX_OUTPUT_SIDE);
  status = ts_validate_search_params (params->quality, params->patch_size, params->max_iterations,
                                      error);
  if (status != TS_OK)
    return status;
  if (params->fine_patch_size != 0 &&
      (params->fine_patch_size < TS_MIN_PATCH_SIZE || params->fine_patch_size > TS_MAX_PATCH_SIZE ||
       params->fine_patch_size % 2 == 0))
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "fine patch size must be 0 (automatic) or odd, %d to %d; got %d",
                    TS_MIN_PATCH_SIZE, TS_MAX_PATCH_SIZE, params->fine_patch_size);
  if (params->patch_size != 0 && params->fine_patch_size > params->patch_size)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "fine patch size (%d) must not exceed patch size (%d)",
                    params->fine_patch_size, params->patch_size);
  if (params->preserve && !params->initial_source)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "preserve weights need an initial source map");
  if (exemplar->width < TS_MIN_PATCH_SIZE || exemplar->height < TS_MIN_PATCH_SIZE)
    return ts_fail (error, TS_ERROR_EXEMPLAR_TOO_SMALL,
                    "the exemplar is %zux%zu pixels; it needs at least %dx%d "
                    "(the smallest neighbourhood)",
                    exemplar->width, exemplar->height, TS_MIN_PATCH_SIZE, TS_MIN_PATCH_SIZE);
  if (!exemplar_has_opaque_pixel (exemplar))
    return ts_fail (error, TS_ERROR_TRANSPARENT_EXEMPLAR,
                    "the exemplar is fully transparent: there is nothing to copy from");
  status = ts_guides_validate (params, exemplar, error);
  if (status != TS_OK)
    return status;
  if (params->initial_source)
    {
      size_t n = params->output_width * params->output_height;
      for (size_t i = 0; i < n; i++)
        {
          int32_t x = params->initial_source[2 * i], y = params->initial_source[2 * i + 1];
          if (x < 0 || y < 0 || (size_t) x >= exemplar->width || (size_t) y >= exemplar->height)
            return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                            "initial source (%d, %d) of output pixel %zu lies outside the exemplar",
                            (int) x, (int) y, i);
          if (params->preserve && !(params->preserve[i] >= 0.0f && params->preserve[i] <= 1.0f))
            return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                            "preserve weight of output pixel %zu is not in [0, 1]", i);
        }
    }
  return TS_OK;
}

/* Bytes of one pyramid of images whose finest level has `pixels` pixels
 * and `bytes_per_pixel` bytes each (a geometric series bounded by 4/3). */
static double
pyramid_bytes (double pixels, double bytes_per_pixel)
{
  return pixels * bytes_per_pixel * 4.0 / 3.0;
}

static double
estimate_bytes (const TsParams *params, const TsImage *exemplar, int threads)
{
  double ex = (double) exemplar->width * (double) exemplar->height;
  double out = (double) params->output_width * (double) params->output_height;
  double k = (double) ts_schedule_max_candidates (params->quality);
  double bytes = 0;

  bytes += pyramid_bytes (ex, 16.0);                   /* working exemplar pyramid */
  bytes += 2.0 * ex * (k * 4.0 + 16.0);                /* two candidate levels + MRPM features */
  bytes += (double) threads * ex * 4.0;                /* dedup stamps */
  bytes += ex * (16.0 + 1.0);                          /* an M-step's mirrored exemplar and
                                                          clipped-window flags (its margin of
                                                          a few pixels is in the fixed overhead) */
  /* Per output pixel, measured ~21 B at 4096x4096 (docs/benchmarks.md): the caller's result (16), sources (4), the coarser level's
   * sources (1) and sparse matches (2), and the host's converted copy of
   * the result (16, the ops' GEGL buffer). */
  bytes += out * (16.0 + 4.0 + 1.0 + 2.0 + 16.0);
  if (ts_region_bound_applies (params))
    bytes += out * 10.0;  /* coherent regions: flags, links, queue, sets */
  if (params->wrap_x || params->wrap_y)
    bytes += out * 4.0;                                /* seam disagreement   */
  if (params->source_map)
    bytes += out * 8.0;
  if (params->initial_source)
    bytes += pyramid_bytes (out, 8.0 + 4.0);
  bytes += ts_guides_estimate_bytes (params, exemplar);
  return bytes + 16.0 * 1024 * 1024;                   /* fixed overhead */
}

TsStatus
ts_estimate_memory (const TsParams *params, const TsImage *exemplar, size_t *bytes, TsError *error)
{
  TsStatus status = validate_without_memory (params, exemplar, error);
  double estimate;

  if (status != TS_OK)
    return status;
  estimate = estimate_bytes (params, exemplar, ts_schedule_threads ());
  return ts_store_estimate (estimate, bytes, error);
}

TsStatus
ts_params_validate (const TsParams *params, const TsImage *exemplar, TsError *error)
{
  size_t bytes, limit;
  TsStatus status = ts_estimate_memory (params, exemplar, &bytes, error);

  if (status != TS_OK)
    return status;
  limit = params->memory_limit ? params->memory_limit : ts_default_memory_limit ();
  if (bytes > limit)
    return ts_fail (error, TS_ERROR_TOO_LARGE,
                    "a %zux%zu output from a %zux%zu exemplar would need about %.1f MiB, "
                    "more than the limit of %.1f MiB; choose a smaller size or raise the memory limit",
                    params->output_width, params->output_height, exemplar->width,
                    exemplar->height, (double) bytes / 1048576.0, (double) limit / 1048576.0);
  return TS_OK;
}
