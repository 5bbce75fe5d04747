/* ts_synthesize: checks the call, then takes one of two routes, texture
 * by numbers in layers (guide-layers.c) or one optimization over the
 * whole output (synthesize.c).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "guide-layers.h"
#include "guide-params.h"
#include "style-tone.h"
#include "synthesize.h"
#include "error.h"

TsStatus
ts_synthesize (const TsParams *params, const TsImage *exemplar, TsImage *output,
               TsProgressFunc progress, void *user_data, TsError *error)
{
  TsStatus status = ts_params_validate (params, exemplar, error);

  if (status != TS_OK)
    return status;
  if (!output || !output->pixels || output->width != params->output_width ||
      output->height != params->output_height)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "the output image must be allocated with %zux%zu pixels",
                    params->output_width, params->output_height);
  if (ts_guide_layers_apply (params, exemplar))
    return ts_guide_layers_synthesize (params, exemplar, output, progress, user_data, error);
  status = ts_synthesize_optimized (params, exemplar, output, progress, user_data, error);
  if (status == TS_OK && params->guides && !params->guides->exemplar_guide)
    {
      status = ts_style_tone (params->guides, exemplar, params->wrap_x, params->wrap_y, output);
      if (status != TS_OK)
        return ts_fail (error, status, "%s", ts_status_string (status));
    }
  return status;
}
