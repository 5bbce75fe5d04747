/* Solid synthesis parameters: defaults, validation and the memory
 * estimate checked before anything is allocated.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "solid.h"
#include "engine/schedule.h"
#include "engine/error.h"

#include <string.h>

static const char *const axis_names[3] = { "x", "y", "z" };

void
ts_solid_params_init (TsSolidParams *params)
{
  memset (params, 0, sizeof *params);
  params->size = 128;
  params->periodic = true;
  params->quality = TS_DEFAULT_QUALITY;
  params->histogram_matching = true;
  params->cell_structure = TS_CELL_STRUCTURE_AUTO;
}

void
ts_solid_resolve_params (const TsSolidParams *params, const TsImage *const exemplars[3],
                         TsSolidParams *resolved)
{
  *resolved = *params;
  resolved->cell_structure = ts_solid_uses_cell_structure (params, exemplars)
                               ? TS_CELL_STRUCTURE_ON
                               : TS_CELL_STRUCTURE_OFF;
}

static TsStatus
check_exemplar (const TsImage *ex, int axis, bool cell_structure, TsError *error)
{
  size_t n;
  bool opaque = false;

  if (ex->width == 0 || ex->height == 0 || !ex->pixels)
    return ts_fail (error, TS_ERROR_EMPTY_EXEMPLAR,
                    "the exemplar of the slices across %s has no pixels (%zux%zu)",
                    axis_names[axis], ex->width, ex->height);
  if (ex->width > TS_MAX_OUTPUT_SIDE || ex->height > TS_MAX_OUTPUT_SIDE)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the exemplar of the slices across %s is %zux%zu; its sides must be at most %d pixels",
                    axis_names[axis], ex->width, ex->height, TS_MAX_OUTPUT_SIDE);
  if (ex->width < TS_MIN_PATCH_SIZE || ex->height < TS_MIN_PATCH_SIZE)
    return ts_fail (error, TS_ERROR_EXEMPLAR_TOO_SMALL,
                    "the exemplar of the slices across %s is %zux%zu pixels; it needs at least %dx%d",
                    axis_names[axis], ex->width, ex->height, TS_MIN_PATCH_SIZE, TS_MIN_PATCH_SIZE);
  n = ex->width * ex->height;
  for (size_t i = 0; i < n && !opaque; i++)
    opaque = ex->pixels[i * TS_CHANNELS + 3] > 0.0f;
  if (!opaque)
    return ts_fail (error, TS_ERROR_TRANSPARENT_EXEMPLAR,
                    "the exemplar of the slices across %s is fully transparent: "
                    "there is nothing to copy from", axis_names[axis]);
  /* The cell structure carries its distances in the working alpha. */
  if (cell_structure && !ts_solid_fully_opaque (ex))
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the cell structure needs opaque exemplars; the exemplar of the slices "
                    "across %s has transparent pixels", axis_names[axis]);
  return TS_OK;
}

static TsStatus
validate_without_memory (const TsSolidParams *params, const TsImage *const exemplars[3],
                         TsError *error)
{
  int given = 0;
  TsStatus status;

  if (!params || !exemplars)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no parameters or no exemplars given");
  if (params->size < TS_SOLID_MIN_SIZE || params->size > TS_SOLID_MAX_SIZE)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the volume size must be %d to %d voxels, got %zu",
                    TS_SOLID_MIN_SIZE, TS_SOLID_MAX_SIZE, params->size);
  status = ts_validate_search_params (params->quality, params->patch_size, params->max_iterations,
                                      error);
  if (status != TS_OK)
    return status;
  if (params->cell_structure != TS_CELL_STRUCTURE_OFF && params->cell_structure != TS_CELL_STRUCTURE_ON
      && params->cell_structure != TS_CELL_STRUCTURE_AUTO)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the cell structure must be off (%d), on (%d) or automatic (%d), got %d",
                    TS_CELL_STRUCTURE_OFF, TS_CELL_STRUCTURE_ON, TS_CELL_STRUCTURE_AUTO,
                    (int) params->cell_structure);
  for (int a = 0; a < 3; a++)
    if (exemplars[a])
      {
        status = check_exemplar (exemplars[a], a,
                                 params->cell_structure == TS_CELL_STRUCTURE_ON, error);
        if (status != TS_OK)
          return status;
        given++;
      }
  if (given < 2)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "a solid texture needs exemplars for at least two slice orientations, got %d",
                    given);
  return TS_OK;
}

bool
ts_solid_uses_positions (const TsSolidParams *params)
{
  return params->histogram_matching && !params->cell_structure;
}

static double
estimate_bytes (const TsSolidParams *params, const TsImage *const exemplars[3], int threads)
{
  double n3 = (double) params->size * (double) params->size * (double) params->size;
  double bytes = 0;

  for (int a = 0; a < 3; a++)
    if (exemplars[a])
      {
        double ex = (double) exemplars[a]->width * (double) exemplars[a]->height;
        bytes += ex * 16.0 * 4.0 / 3.0;             /* working pyramid          */
        bytes += (double) threads * ex * 4.0 + ex * 12.0; /* stamps, opaque, excesses */
        bytes += ex * (8.0 * 4.0 + 4.0 + 12.0 + 8.0); /* index: points, centres, nodes, build */
        bytes += ex * 8.0;                          /* variance map and its median */
        if (params->cell_structure)
          bytes += ex * 8.0;                        /* stone tones, sorted shades */
        else
          bytes += ex * 22.0; /* phase distances; the light pieces' scratch */
      }
  /* Finest level: the result volume (which holds the values), three
   * sources, the matches of three orientations on a grid of spacing 2 in
   * every second slice and the batch map; plus the coarser level's
   * values and sources. */
  bytes += n3 * (16.0 + 12.0 + 3.0 * 8.0 / 8.0 + 1.0);
  bytes += n3 / 8.0 * (16.0 + 12.0);
  if (params->record_sources || ts_solid_uses_positions (params))
    bytes += n3 * sizeof (TsSolidSource); /* the sources asked for or the
                                              position histogram's own */
  if (params->cell_structure)
    bytes += n3 * (sizeof (float) + 3.0 + 4.0); /* the guide's distances, slants, cells */
  else
    bytes += n3 * 13.0; /* the phase guide (phase-guide.c): the walls' scratch at the
                           finest level's start, then its 4-byte field */
  return bytes + 16.0 * 1024 * 1024;
}

TsStatus
ts_solid_estimate_memory (const TsSolidParams *params, const TsImage *const exemplars[3],
                          size_t *bytes, TsError *error)
{
  TsStatus status = validate_without_memory (params, exemplars, error);
  TsSolidParams resolved;
  double estimate;

  if (status != TS_OK)
    return status;
  ts_solid_resolve_params (params, exemplars, &resolved);
  estimate = estimate_bytes (&resolved, exemplars, ts_schedule_threads ());
  return ts_store_estimate (estimate, bytes, error);
}

TsStatus
ts_solid_params_validate (const TsSolidParams *params, const TsImage *const exemplars[3],
                          TsError *error)
{
  size_t bytes, limit;
  TsStatus status = ts_solid_estimate_memory (params, exemplars, &bytes, error);

  if (status != TS_OK)
    return status;
  limit = params->memory_limit ? params->memory_limit : ts_default_memory_limit ();
  if (bytes > limit)
    return ts_fail (error, TS_ERROR_TOO_LARGE,
                    "a %zu^3 volume would need about %.1f MiB, more than the limit of "
                    "%.1f MiB; choose a smaller size or raise the memory limit",
                    params->size, (double) bytes / 1048576.0, (double) limit / 1048576.0);
  return TS_OK;
}
