/* Image completion driver (ts_heal): coarse to fine, the hole first
 * filled from its border inwards, then texture optimization with the
 * known pixels as hard constraints (Wexler et al. 2007) and PatchMatch
 * search at every level.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-level.h"
#include "engine/error.h"
#include "engine/progress.h"

#include <stdlib.h>
#include <string.h>

/* Each level halves the image: 12 levels shrink it 4096 times, more
 * than any hole needs. */
#define TS_HEAL_MAX_LEVELS 12
/* The coarsest level is reached when no hole pixel is farther than this
 * from a known one. Deeper than a patch: levels coarser than that hold
 * too little texture to lay out, and their smooth border fill only leads
 * the finer levels to flat sources. */
#define TS_HEAL_COARSEST_DEPTH 12
/* A coarser level needs this many valid source centres to be worth it. */
#define TS_HEAL_MIN_SOURCES 16
/* Sweeps of ts_heal_consolidate at most: the labels settle within a
 * few sweeps, and more change nothing measurable. */
#define TS_HEAL_CONSOLIDATE_SWEEPS 10
/* Iterations stop once fewer hole pixels than this fraction change: a
 * fifth of a percent, a few scattered pixels. */
#define TS_HEAL_CONVERGED 0.002

typedef struct
{
  TsProgress progress;
  TsCancel   cancel;
} Run;

static bool
report_midway (void *data)
{
  Run *run = data;
  return ts_progress_report (&run->progress, 0.0, "healing");
}

static size_t
iterations_for (const TsHealParams *params, size_t level, size_t levels)
{
  size_t q = (size_t) params->quality;
  if (level + 1 == levels)
    return 6 + 2 * q;   /* the coarsest level lays out the structure */
  return level == 0 ? 2 + q : 3 + q;
}

static TsHealArea
coarser_area (const TsHealArea *a)
{
  TsHealArea c = *a;
  c.x0 = a->x0 / 2;
  c.y0 = a->y0 / 2;
  c.x1 = (a->x1 + 1) / 2;
  c.y1 = (a->y1 + 1) / 2;
  c.hx0 = a->hx0 / 2;
  c.hy0 = a->hy0 / 2;
  c.hx1 = (a->hx1 + 1) / 2;
  c.hy1 = (a->hy1 + 1) / 2;
  return c;
}

/* Coarser levels until the hole is shallow, while each still has
 * sources. Returns the number of levels. */
static TsStatus
build_pyramid (const TsHealParams *params, TsHealLevel *levels, const TsHealArea *finest,
               size_t *count)
{
  size_t depth = ts_heal_hole_depth (&levels[0]);
  TsHealArea area = *finest;

  *count = 1;
  while (*count < TS_HEAL_MAX_LEVELS && (depth >> (*count - 1)) > TS_HEAL_COARSEST_DEPTH)
    {
      TsHealLevel *fine = &levels[*count - 1], *coarse = &levels[*count];
      TsStatus status = ts_heal_level_downsample (fine, coarse);
      size_t side;

      area = coarser_area (&area);
      coarse->radius = ts_heal_coarse_radius (params);
      side = 2 * coarse->radius + 1;
      if (status == TS_OK && (coarse->source_width < side || coarse->source_height < side))
        {
          ts_heal_level_free (coarse);
          break;
        }
      if (status == TS_OK)
        status = ts_heal_level_index (coarse, &area);
      if (status != TS_OK)
        return status;
      if (coarse->valid_count < TS_HEAL_MIN_SOURCES)
        {
          ts_heal_level_free (coarse);
          break;
        }
      (*count)++;
    }
  return TS_OK;
}

static TsStatus
optimize_level (const TsHealParams *params, Run *run, TsHealLevel *l, size_t level, size_t levels,
                int32_t *picked, uint32_t *pass)
{
  size_t iterations = iterations_for (params, level, levels);
  bool finest = level == 0;

  for (size_t it = 0; it < iterations; it++)
    {
      size_t changed;
      TsStatus status = TS_OK;
      /* Two passes: every other iteration scans rows, then columns. */
      for (int k = 0; k < 2 && status == TS_OK; k++)
        status = ts_heal_search_pass (l, params->seed, (uint32_t) level, (*pass)++,
                                      (size_t) params->quality, &run->cancel);
      if (status != TS_OK)
        return status;
      /* Picking at every level keeps the coarse levels' texture: their
       * blurred means would draw the finer searches to flat sources. */
      changed = ts_heal_vote (l, true, finest ? picked : NULL, &run->cancel);
      if (changed == SIZE_MAX)
        return TS_ERROR_OUT_OF_MEMORY;
      ts_heal_update_distances (l, &run->cancel);
      if (ts_cancel_requested (&run->cancel) ||
          !ts_progress_report (&run->progress, (double) l->active_count, "healing"))
        return TS_ERROR_CANCELLED;
      if (it >= 1 && (double) changed < TS_HEAL_CONVERGED * (double) l->hole_pixels)
        {
          run->progress.done += (double) (iterations - it - 1) * (double) l->active_count;
          break;
        }
    }
  return TS_OK;
}

static TsStatus
run_levels (const TsHealParams *params, Run *run, TsHealLevel *levels, size_t count,
            int32_t *picked)
{
  uint32_t pass = 0;
  TsStatus status = TS_OK;

  for (size_t l = 0; l < count; l++)
    run->progress.total += (double) iterations_for (params, l, count)
                           * (double) levels[l].active_count;
  for (size_t l = count; l-- > 0 && status == TS_OK;)
    {
      TsHealLevel *level = &levels[l];
      if (l + 1 == count)
        {
          status = ts_heal_fill_from_border (level);
          ts_heal_random_matches (level, params->seed, (uint32_t) l);
        }
      else
        {
          ts_heal_upsample_target (&levels[l + 1], level);
          ts_heal_upsample_matches (&levels[l + 1], level, params->seed, (uint32_t) l);
          ts_heal_level_free (&levels[l + 1]);
        }
      if (status != TS_OK)
        break;
      ts_heal_update_distances (level, &run->cancel);
      if (l + 1 < count && ts_heal_vote (level, false, NULL, &run->cancel) == SIZE_MAX)
        status = TS_ERROR_OUT_OF_MEMORY;
      else
        {
          ts_heal_update_distances (level, &run->cancel);
          status = optimize_level (params, run, level, l, count, picked, &pass);
        }
    }
  return status;
}

/* Output: the image, and in the hole the picked source pixels as given. */
static void
write_result (const TsImage *image, const TsImage *source, const TsHealLevel *finest,
              const TsHealCrop *crop, const int32_t *picked, const float *offset,
              TsImage *output, int32_t *source_map)
{
  size_t w = image->width, n = w * image->height, cw = finest->width;

  memcpy (output->pixels, image->pixels, n * TS_CHANNELS * sizeof (float));
  if (source_map)
    for (size_t p = 0; p < n; p++)
      source_map[p] = -1;
  for (size_t y = 0; y < finest->height; y++)
    for (size_t x = 0; x < cw; x++)
      {
        size_t p = y * cw + x, q = (y + crop->y0) * w + x + crop->x0, s;
        if (!finest->hole[p])
          continue;
        s = (size_t) picked[p];
        if (!source)   /* an index of the crop: back into the image */
          s = (s / cw + crop->y0) * w + s % cw + crop->x0;
        memcpy (output->pixels + q * TS_CHANNELS, (source ? source : image)->pixels + s * TS_CHANNELS,
                TS_CHANNELS * sizeof (float));
        for (int c = 0; c < 3; c++)
          output->pixels[q * TS_CHANNELS + c] += offset[p * 3 + c];
        if (source_map)
          source_map[q] = (int32_t) s;
      }
}

TsStatus
ts_heal (const TsHealParams *params, const TsImage *image, const uint8_t *hole,
         const TsImage *source, TsImage *output, int32_t *source_map, TsProgressFunc progress,
         void *user_data, TsError *error)
{
  Run run = { .progress = { .func = progress, .user_data = user_data } };
  TsHealLevel levels[TS_HEAL_MAX_LEVELS];
  TsHealArea area;
  TsHealCrop crop;
  int32_t *picked = NULL;
  float *offset = NULL;
  size_t count = 0;
  TsStatus status = ts_heal_params_validate (params, image, hole, source, error);

  if (status != TS_OK)
    return status;
  if (!output || !output->pixels || output->width != image->width ||
      output->height != image->height)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "the output image must be allocated with the image's size, %zux%zu",
                    image->width, image->height);
  ts_cancel_init (&run.cancel, progress ? report_midway : NULL, &run);
  memset (levels, 0, sizeof levels);
  status = ts_heal_prepare_finest (params, image, hole, source, &levels[0], &area, &crop);
  if (status == TS_OK && crop.empty)
    {
      /* Nothing to fill: the image as it is. */
      write_result (image, source, &levels[0], &crop, NULL, NULL, output, source_map);
      ts_heal_level_free (&levels[0]);
      return TS_OK;
    }
  if (status == TS_OK)
    {
      picked = malloc (levels[0].width * levels[0].height * sizeof (int32_t));
      status = picked ? build_pyramid (params, levels, &area, &count) : TS_ERROR_OUT_OF_MEMORY;
    }
  if (status == TS_OK)
    {
      for (size_t p = 0; p < levels[0].width * levels[0].height; p++)
        picked[p] = -1;
      status = run_levels (params, &run, levels, count, picked);
    }
  /* Whole copies where the seams allow: fewer, cheaper seams between
   * the picked pixels' copies. */
  if (status == TS_OK &&
      ts_heal_consolidate (&levels[0], picked, TS_HEAL_CONSOLIDATE_SWEEPS) == SIZE_MAX)
    status = TS_ERROR_OUT_OF_MEMORY;
  if (status == TS_OK)
    {
      offset = malloc (levels[0].width * levels[0].height * 3 * sizeof (float));
      status = offset ? ts_heal_outline_offsets (&levels[0], picked, offset) : TS_ERROR_OUT_OF_MEMORY;
      if (status == TS_OK)
        status = ts_heal_gradient_blend (&levels[0], picked, offset);
    }
  if (status == TS_OK)
    {
      write_result (image, source, &levels[0], &crop, picked, offset, output, source_map);
      ts_progress_report (&run.progress, 0.0, "done");
    }
  for (size_t l = 0; l < TS_HEAL_MAX_LEVELS; l++)
    ts_heal_level_free (&levels[l]);
  free (picked);
  free (offset);
  if (status != TS_OK)
    return ts_fail (error, status, "%s", ts_status_string (status));
  return TS_OK;
}
