/* Parameters of image completion: defaults, validation (the one place)
 * and the memory estimate.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"
#include "engine/error.h"
#include "engine/schedule.h"

#include <string.h>

/* Bytes per pixel of the part of the image a heal works on: target (16),
 * hole, valid and activity flags, indices, matches, distances and weights
 * (about 20 more where active), the integral image (4), and the coarser
 * levels (a third more). */
#define TS_HEAL_BYTES_PER_PIXEL 64.0
#define TS_HEAL_BYTES_PER_SOURCE_PIXEL 32.0

void
ts_heal_params_init (TsHealParams *params)
{
  TsParams defaults;

  ts_params_init (&defaults);
  memset (params, 0, sizeof *params);
  params->context = 0;
  params->sample_from = TS_HEAL_ALL_AROUND;
  params->quality = defaults.quality;
  params->seed = defaults.seed;
  params->memory_limit = defaults.memory_limit;
}

/* `is_source`: the separate source image rather than the image to heal
 * (two messages, so each translates as a whole). */
static TsStatus
check_image (const TsImage *image, bool is_source, TsError *error)
{
  if (image->width == 0 || image->height == 0 || !image->pixels)
    return is_source ? ts_fail (error, TS_ERROR_EMPTY_EXEMPLAR,
                                "the source image has no pixels (%zux%zu)",
                                image->width, image->height)
                     : ts_fail (error, TS_ERROR_EMPTY_EXEMPLAR, "the image has no pixels (%zux%zu)",
                                image->width, image->height);
  if (image->width > TS_MAX_OUTPUT_SIDE || image->height > TS_MAX_OUTPUT_SIDE)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the image is %zux%zu; its sides must be at most %d pixels",
                    image->width, image->height, TS_MAX_OUTPUT_SIDE);
  return TS_OK;
}

static TsStatus
validate_without_memory (const TsHealParams *params, const TsImage *image, const uint8_t *hole,
                         const TsImage *source, TsError *error)
{
  TsStatus status;

  if (!params || !image || !hole)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no parameters, image or hole given");
  if ((status = check_image (image, false, error)) != TS_OK)
    return status;
  if (source && (status = check_image (source, true, error)) != TS_OK)
    return status;
  if ((status = ts_validate_search_params (params->quality, params->patch_size, 0, error)) != TS_OK)
    return status;
  if ((status = ts_validate_search_params (params->quality, params->fine_patch_size, 0, error)) != TS_OK)
    return status;
  if (params->sample_from != TS_HEAL_ALL_AROUND && params->sample_from != TS_HEAL_SIDES &&
      params->sample_from != TS_HEAL_ABOVE_BELOW)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "unknown sample-from choice %d",
                    (int) params->sample_from);
  if (params->context > TS_HEAL_MAX_CONTEXT)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the context must be 0 (the whole image) to %d pixels, got %zu",
                    TS_HEAL_MAX_CONTEXT, params->context);
  return TS_OK;
}

TsStatus
ts_heal_estimate_memory (const TsHealParams *params, const TsImage *image, const uint8_t *hole,
                         const TsImage *source, size_t *bytes, TsError *error)
{
  TsStatus status = validate_without_memory (params, image, hole, source, error);
  size_t x0 = image ? image->width : 0, y0 = image ? image->height : 0, x1 = 0, y1 = 0;
  size_t rx0, ry0, rx1, ry1;
  double estimate;

  if (status != TS_OK)
    return status;
  for (size_t y = 0; y < image->height; y++)
    for (size_t x = 0; x < image->width; x++)
      if (hole[y * image->width + x])
        {
          x0 = x < x0 ? x : x0;
          x1 = x + 1 > x1 ? x + 1 : x1;
          y0 = y < y0 ? y : y0;
          y1 = y + 1;
        }
  if (x1 == 0)
    return ts_store_estimate (0.0, bytes, error);
  ts_heal_region (params, image->width, image->height, x0, y0, x1, y1, &rx0, &ry0, &rx1, &ry1);
  estimate = (double) (rx1 - rx0) * (double) (ry1 - ry0) * TS_HEAL_BYTES_PER_PIXEL;
  if (source)
    estimate += (double) source->width * (double) source->height * TS_HEAL_BYTES_PER_SOURCE_PIXEL;
  return ts_store_estimate (estimate, bytes, error);
}

TsStatus
ts_heal_params_validate (const TsHealParams *params, const TsImage *image, const uint8_t *hole,
                         const TsImage *source, TsError *error)
{
  size_t bytes, limit, patch;
  TsHealLevel level;
  TsHealArea area;
  TsHealCrop crop;
  TsStatus status = ts_heal_estimate_memory (params, image, hole, source, &bytes, error);

  if (status != TS_OK)
    return status;
  limit = params->memory_limit ? params->memory_limit : ts_default_memory_limit ();
  if (bytes > limit)
    return ts_fail (error, TS_ERROR_TOO_LARGE,
                    "healing this hole would need about %.1f MiB, more than the limit of "
                    "%.1f MiB; set a context or raise the memory limit",
                    (double) bytes / 1048576.0, (double) limit / 1048576.0);

  /* Is there anything to copy from? The same indexing as the heal. */
  status = ts_heal_prepare_finest (params, image, hole, source, &level, &area, &crop);
  if (status != TS_OK)
    {
      ts_heal_level_free (&level);
      return ts_fail (error, status, "%s", ts_status_string (status));
    }
  patch = 2 * level.radius + 1;
  if (crop.empty || level.valid_count > 0)
    {
      ts_heal_level_free (&level);
      return TS_OK;
    }
  ts_heal_level_free (&level);
  if (source)
    return ts_fail (error, TS_ERROR_NOTHING_TO_SAMPLE,
                    "the source image holds no %zux%zu patch of opaque pixels to fill the hole from",
                    patch, patch);
  if (params->context > 0 && params->context < patch)
    return ts_fail (error, TS_ERROR_NOTHING_TO_SAMPLE,
                    "the context of %zu pixels is too small to hold a %zux%zu patch of known "
                    "pixels beside the hole; make it at least %zu, or 0 for the whole image",
                    params->context, patch, patch, patch);
  return ts_fail (error, TS_ERROR_NOTHING_TO_SAMPLE,
                  "there is nothing to fill the hole from: no %zux%zu patch of known pixels "
                  "lies where sources are allowed; make the hole smaller, the context "
                  "larger (0 = the whole image) or sample from all around",
                  patch, patch);
}
