/* Making an existing image tileable by re-synthesising its edges
 * (ts_make_tileable); see plan.h for the idea.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "plan.h"
#include "cuts.h"
#include "shift.h"
#include "engine/image.h"
#include "engine/schedule.h"
#include "engine/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Default band on each side of a wrap edge, an eighth of the side: room
 * for the cut to wander around features, while the middle three
 * quarters along each wrapped direction stay exactly as they were. */
#define TS_TILEABLE_DEFAULT_SEAM_WIDTH 0.125
/* Iterations per pass and level when the caller leaves them automatic:
 * only the pixels near the cuts are optimized, so more than a synthesis
 * uses are affordable; 6 heal the cuts about as well as 10, fewer
 * slightly worse. */
#define TS_TILEABLE_ITERATIONS 6

void
ts_tileable_params_init (TsTileableParams *params)
{
  TsParams defaults;

  ts_params_init (&defaults);
  memset (params, 0, sizeof *params);
  params->direction = TS_TILEABLE_BOTH;
  params->seam_width = TS_TILEABLE_DEFAULT_SEAM_WIDTH;
  params->quality = defaults.quality;
  params->seed = defaults.seed;
  params->patch_size = defaults.patch_size;
  params->fine_patch_size = defaults.fine_patch_size;
  params->max_iterations = defaults.max_iterations;
  params->histogram_matching = defaults.histogram_matching;
  params->memory_limit = defaults.memory_limit;
}

static void
fill_synthesis_params (const TsTileableParams *tp, const TsImage *input, TsParams *params)
{
  ts_params_init (params);
  params->output_width = input->width;
  params->output_height = input->height;
  params->wrap_x = ts_tileable_wraps_x (tp->direction);
  params->wrap_y = ts_tileable_wraps_y (tp->direction);
  params->quality = tp->quality;
  params->seed = tp->seed;
  params->patch_size = tp->patch_size;
  params->fine_patch_size = tp->fine_patch_size;
  params->max_iterations = tp->max_iterations ? tp->max_iterations : TS_TILEABLE_ITERATIONS;
  params->histogram_matching = tp->histogram_matching;
  params->memory_limit = tp->memory_limit;
  params->source_map = tp->source_map;
}

static bool
has_opaque_pixel (const TsImage *image)
{
  size_t n = image->width * image->height;
  for (size_t i = 0; i < n; i++)
    if (image->pixels[i * TS_CHANNELS + 3] > 0.0f)
      return true;
  return false;
}

TsStatus
ts_tileable_params_validate (const TsTileableParams *params, const TsImage *input,
                             TsError *error)
{
  TsParams synthesis;

  if (!params || !input)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no parameters or no input image given");
  if (params->direction != TS_TILEABLE_BOTH && params->direction != TS_TILEABLE_HORIZONTAL &&
      params->direction != TS_TILEABLE_VERTICAL)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "unknown direction %d", (int) params->direction);
  if (!(params->seam_width >= TS_TILEABLE_MIN_SEAM_WIDTH &&
        params->seam_width <= TS_TILEABLE_MAX_SEAM_WIDTH))
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "seam width must be %g to %g, got %g",
                    TS_TILEABLE_MIN_SEAM_WIDTH, TS_TILEABLE_MAX_SEAM_WIDTH, params->seam_width);
  if (input->width == 0 || input->height == 0 || !input->pixels)
    return ts_fail (error, TS_ERROR_EMPTY_EXEMPLAR, "the input has no pixels (%zux%zu)",
                    input->width, input->height);
  if ((ts_tileable_wraps_x (params->direction) && input->width < TS_TILEABLE_MIN_SIDE) ||
      (ts_tileable_wraps_y (params->direction) && input->height < TS_TILEABLE_MIN_SIDE) ||
      input->width < TS_MIN_PATCH_SIZE || input->height < TS_MIN_PATCH_SIZE)
    return ts_fail (error, TS_ERROR_EXEMPLAR_TOO_SMALL,
                    "the input is %zux%zu pixels, too small to make tileable: it needs at "
                    "least %d pixels along each direction that wraps (and %d along the other)",
                    input->width, input->height, TS_TILEABLE_MIN_SIDE, TS_MIN_PATCH_SIZE);
  if (input->width > TS_MAX_OUTPUT_SIDE || input->height > TS_MAX_OUTPUT_SIDE)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the input is %zux%zu; its sides must be at most %d pixels",
                    input->width, input->height, TS_MAX_OUTPUT_SIDE);
  if (!has_opaque_pixel (input))
    return ts_fail (error, TS_ERROR_TRANSPARENT_EXEMPLAR,
                    "the input is fully transparent: there is nothing to make tileable");
  /* Quality, patch sizes, iterations and the memory estimate. */
  fill_synthesis_params (params, input, &synthesis);
  return ts_params_validate (&synthesis, input, error);
}

TsStatus
ts_make_tileable (const TsTileableParams *params, const TsImage *input, TsImage *output,
                  TsProgressFunc progress, void *user_data, TsError *error)
{
  TsParams synthesis;
  TsTileablePlan plan;
  TsImage working = { 0, 0, NULL };
  int32_t *source = NULL;
  float *preserve = NULL;
  size_t n;
  bool engine_said = false;
  TsStatus status = ts_tileable_params_validate (params, input, error);

  if (status != TS_OK)
    return status;
  if (!output || !output->pixels || output->width != input->width ||
      output->height != input->height)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "the output image must be allocated with the input's size, %zux%zu",
                    input->width, input->height);

  n = input->width * input->height;
  ts_tileable_plan_init (params, input, &plan);
  source = malloc (2 * n * sizeof (int32_t));
  preserve = malloc (n * sizeof (float));
  status = source && preserve ? ts_image_to_working (input, &working) : TS_ERROR_OUT_OF_MEMORY;
  if (status == TS_OK)
    status = ts_tileable_choose_shift (&working, &plan);
  if (status == TS_OK)
    status = ts_tileable_place_cuts (&working, &plan);
  ts_image_free (&working);
  if (status == TS_OK)
    status = ts_tileable_maps (&plan, source, preserve);
  if (status == TS_OK)
    {
      fill_synthesis_params (params, input, &synthesis);
      synthesis.initial_source = source;
      synthesis.preserve = preserve;
      status = ts_synthesize (&synthesis, input, output, progress, user_data, error);
      engine_said = status != TS_OK;   /* `error` already says why */
    }
  free (source);
  free (preserve);
  ts_tileable_plan_clear (&plan);
  if (status != TS_OK && !engine_said)
    return ts_fail (error, status, "%s", ts_status_string (status));
  return status;
}
