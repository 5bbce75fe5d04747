/* Solid texture synthesis from 2D exemplars (Kopf et al. 2007): texture
 * optimization over a cube, coarse to fine; in each slice orientation a
 * search over the neighbourhoods that continue the slice's sources and
 * over all exemplar neighbourhoods (exemplar-index.c), and histogram
 * matching.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"
#include "engine/progress.h"
#include "engine/pyramid.h"
#include "engine/rng.h"
#include "engine/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A level stops iterating once fewer voxels than this change: a fifth
 * of a percent is a few scattered voxels, no visible change. */
#define TS_SOLID_CONVERGED_FRACTION 0.002
/* The coarsest volume level keeps at least this edge where it can:
 * smaller, and a 9-voxel neighbourhood spans most of it, leaving no
 * room to lay shapes out. */
#define TS_SOLID_COARSEST_EDGE 16
/* E-step weight per neighbour a vote continues (estep.c), at the finest
 * level: 1 (a vote continuing one neighbour counts double) cleans thin
 * phases of lone voxels and sharpens; 2 and more blunted spots. At the
 * coarser levels it cost the spots' coherence. Chosen on the truth
 * solids. */
#define TS_SOLID_CONTINUATION 1.0f
/* Weight of the position histogram's excess (position-histogram.c), at
 * the finest level only: at the coarser levels its push to unused
 * positions broke large shapes into small pieces, and twice this weight
 * cost coherence at the finest level too. Not with the cell structure:
 * there the guide and the cell tones already spread the copies, and the
 * push made neighbouring voxels switch sources, a grain in stones and
 * joints. Chosen on the truth solids. */
#define TS_SOLID_POSITION_WEIGHT 3.0f

typedef struct
{
  const TsImage  *input;
  TsImage         working;      /* mirrored for run->mirrored_axis */
  TsPyramid       pyramid;
  int32_t        *opaque;
  size_t          opaque_count;
  float          *excess;
  uint32_t       *position_count;
  float           phase_split;  /* of the current level (phase-split.c) */
  float           joint_split;  /* of the current level, with the cell guide */
  float          *stone_tone;   /* finest level, with the cell guide */
  TsSolidIndex    index;      /* all neighbourhoods of the current pass */
  TsSolidVarianceMap variance; /* their colour variances                */
} Exemplar;

typedef struct
{
  const TsSolidParams *params;
  TsProgress           progress;
  TsCancel             midway;  /* raised by a stop; lets the steps ask midway */
  const char          *stage;   /* what a midway report says */
  Exemplar             exemplar[TS_SOLID_AXES];
  const TsImage       *finest[TS_SOLID_AXES]; /* their pyramids' level 0 */
  int                  exemplar_of[TS_SOLID_AXES]; /* index into exemplar[], -1 = free */
  size_t               exemplars;
  int                  mirrored_axis; /* reads its exemplar mirrored, or -1 */
  size_t               levels;      /* volume levels synthesised */
  TsSolidLevel         level, coarser;
  float               *volume;                     /* the caller's: finest values */
  TsSolidSource       *sources;                    /* the caller's, or NULL */
  TsSolidSource       *own_sources; /* the position histogram's, if no caller's */
  TsSolidCellGuide     cells;       /* with params->cell_structure */
  TsSolidPhasePlan     phases;      /* without the cell structure, with
                                       more than one level */
} Run;

/* A stop asked by the caller also stops the steps still running. */
static bool
report (Run *run, double units, const char *stage)
{
  if (!ts_progress_report (&run->progress, units, stage))
    ts_cancel_request (&run->midway);
  return !ts_cancel_requested (&run->midway);
}

/* Asked by OpenMP thread 0 (the caller's thread) from inside the steps. */
static bool
report_midway (void *data)
{
  Run *run = data;
  return report (run, 0.0, run->stage);
}

static size_t
level_edge (size_t n, size_t level)
{
  return (n + ((size_t) 1 << level) - 1) >> level;
}

static size_t
cube (size_t n)
{
  return n * n * n;
}

/* The solid schedule (plan.c) for the smallest exemplar at `level`. */
static void
plan_level (const Run *run, size_t level, TsLevelPlan *plan)
{
  size_t ex_w = SIZE_MAX, ex_h = SIZE_MAX, n = level_edge (run->params->size, level);

  for (size_t e = 0; e < run->exemplars; e++)
    {
      const TsImage *ex = &run->exemplar[e].pyramid.level[level];
      ex_w = ex->width < ex_w ? ex->width : ex_w;
      ex_h = ex->height < ex_h ? ex->height : ex_h;
    }
  ts_solid_plan_level (run->params, level, run->levels, n, ex_w, ex_h,
                       run->phases.pieces == TS_SOLID_LIGHT_PIECES, plan);
}

static double
planned_work (const Run *run)
{
  double total = 0;
  for (size_t l = 0; l < run->levels; l++)
    {
      TsLevelPlan plan;
      double voxels = (double) cube (level_edge (run->params->size, l));
      plan_level (run, l, &plan);
      total += voxels;
      for (size_t p = 0; p < plan.passes; p++)
        total += (double) plan.pass[p].max_iterations * voxels;
    }
  return total;
}

static void
level_free (TsSolidLevel *level, const float *keep)
{
  if (level->value != keep)
    free (level->value);
  for (int a = 0; a < TS_SOLID_AXES; a++)
    free (level->source[a]);
  memset (level, 0, sizeof *level);
}

static void
run_free (Run *run)
{
  level_free (&run->level, run->volume);
  level_free (&run->coarser, run->volume);
  free (run->own_sources);
  ts_solid_phase_plan_free (&run->phases);
  ts_solid_cell_guide_free (&run->cells);
  for (size_t e = 0; e < run->exemplars; e++)
    {
      Exemplar *ex = &run->exemplar[e];
      ts_image_free (&ex->working);
      ts_pyramid_free (&ex->pyramid);
      free (ex->opaque);
      free (ex->excess);
      free (ex->position_count);
      free (ex->stone_tone);
      ts_solid_index_free (&ex->index);
      ts_solid_variance_map_free (&ex->variance);
    }
}

/* With one image on all three orientations, a mirrored copy for
 * TS_SOLID_MIRRORED_AXIS if the image's lines fall (handedness.c). */
static TsStatus
choose_handedness (Run *run)
{
  const TsImage *shared = &run->exemplar[0].working;
  Exemplar *copy = &run->exemplar[1];
  TsStatus status;

  run->mirrored_axis = -1;
  for (int a = 0; a < TS_SOLID_AXES; a++)
    if (run->exemplar_of[a] != 0)
      return TS_OK;
  if (ts_solid_diagonal_bias (shared) > -TS_SOLID_MIRROR_BIAS)
    return TS_OK;
  status = ts_image_alloc (&copy->working, shared->width, shared->height);
  if (status != TS_OK)
    return status;
  memcpy (copy->working.pixels, shared->pixels,
          ts_image_pixel_count (shared) * TS_CHANNELS * sizeof (float));
  ts_solid_mirror_image (&copy->working);
  copy->input = run->exemplar[0].input;
  run->exemplar_of[TS_SOLID_MIRRORED_AXIS] = (int) run->exemplars++;
  run->mirrored_axis = TS_SOLID_MIRRORED_AXIS;
  return TS_OK;
}

/* Working pyramids of the distinct exemplars, all with the same depth. */
static TsStatus
prepare_exemplars (Run *run, const TsImage *const exemplars[3])
{
  size_t levels = SIZE_MAX;
  TsStatus status = TS_OK;

  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      run->exemplar_of[a] = -1;
      if (!exemplars[a])
        continue;
      for (int b = 0; b < a; b++)
        if (exemplars[b] == exemplars[a])
          run->exemplar_of[a] = run->exemplar_of[b];
      if (run->exemplar_of[a] < 0)
        {
          run->exemplar_of[a] = (int) run->exemplars;
          run->exemplar[run->exemplars++].input = exemplars[a];
        }
    }
  for (size_t e = 0; e < run->exemplars; e++)
    {
      size_t d = ts_schedule_levels (run->exemplar[e].input);
      levels = d < levels ? d : levels;
    }
  while (levels > 1 && level_edge (run->params->size, levels - 1) < TS_SOLID_COARSEST_EDGE)
    levels--;
  run->levels = levels;
  for (size_t e = 0; e < run->exemplars && status == TS_OK; e++)
    status = ts_image_to_working (run->exemplar[e].input, &run->exemplar[e].working);
  if (status == TS_OK)
    status = choose_handedness (run);
  for (size_t e = 0; e < run->exemplars && status == TS_OK; e++)
    {
      Exemplar *ex = &run->exemplar[e];
      if (run->params->cell_structure)
        status = ts_solid_cell_guide_exemplar (&ex->working, &run->cells, &ex->stone_tone,
                                               &run->midway);
      if (status == TS_OK)
        status = ts_pyramid_build (&ex->working, run->levels, &ex->pyramid);
      if (status == TS_OK && run->params->cell_structure)
        ts_solid_cell_guide_finest (&ex->pyramid.level[0]);
      run->finest[e] = &ex->pyramid.level[0];
    }
  if (status == TS_OK && !run->params->cell_structure && run->levels > 1)
    status = ts_solid_phase_plan (&run->phases, run->finest, run->exemplars, run->exemplar_of);
  if (status != TS_OK)
    return status;
  return run->params->cell_structure
           ? ts_solid_cell_guide_seed (&run->cells, run->params->size, run->params->seed)
           : TS_OK;
}

/* Opaque lists, histogram excesses and phase splits of every exemplar at
 * `level`, and the views that point at them. */
static TsStatus
prepare_views (Run *run, size_t level)
{
  for (size_t e = 0; e < run->exemplars; e++)
    {
      Exemplar *ex = &run->exemplar[e];
      const TsImage *img = &ex->pyramid.level[level];
      size_t pixels = ts_image_pixel_count (img);
      free (ex->opaque);
      free (ex->excess);
      free (ex->position_count);
      ex->opaque = malloc (pixels * sizeof (int32_t));
      ex->excess = malloc (pixels * sizeof (float));
      ex->position_count = malloc (pixels * sizeof (uint32_t));
      if (!ex->opaque || !ex->excess || !ex->position_count)
        return TS_ERROR_OUT_OF_MEMORY;
      ex->opaque_count = 0;
      for (size_t i = 0; i < pixels; i++)
        {
          ex->excess[i] = 0.0f;
          if (img->pixels[i * TS_CHANNELS + 3] > 0.0f)
            ex->opaque[ex->opaque_count++] = (int32_t) i;
        }
      if (ex->opaque_count == 0)
        return TS_ERROR_TRANSPARENT_EXEMPLAR;
      ts_solid_splits (img, &ex->phase_split, &ex->joint_split);
      if (!run->params->cell_structure)
        ex->joint_split = -INFINITY;
    }
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      TsSolidView *view = &run->level.view[a];
      memset (view, 0, sizeof *view);
      if (run->exemplar_of[a] < 0)
        continue;
      Exemplar *ex = &run->exemplar[run->exemplar_of[a]];
      view->exemplar = &ex->pyramid.level[level];
      view->opaque = ex->opaque;
      view->opaque_count = ex->opaque_count;
      view->excess = run->params->histogram_matching ? ex->excess : NULL;
      view->position_count = ex->position_count;
      view->phase_split = ex->phase_split;
      view->joint_split = ex->joint_split;
      view->stone_tone = level == 0 ? ex->stone_tone : NULL;
    }
  return TS_OK;
}

static TsStatus
level_alloc (Run *run, size_t level)
{
  TsSolidLevel *l = &run->level;
  size_t n = level_edge (run->params->size, level), voxels = cube (n);

  l->n = n;
  l->periodic = run->params->periodic;
  l->value = level == 0 ? run->volume : malloc (voxels * TS_CHANNELS * sizeof (float));
  l->chosen = level == 0 ? run->sources : NULL;
  if (!l->value)
    return TS_ERROR_OUT_OF_MEMORY;
  l->position_weight = ts_solid_uses_positions (run->params) && level == 0 ? TS_SOLID_POSITION_WEIGHT : 0.0f;
  if (l->position_weight > 0.0f && !l->chosen)
    {
      l->chosen = run->own_sources = malloc (voxels * sizeof (TsSolidSource));
      if (!l->chosen)
        return TS_ERROR_OUT_OF_MEMORY;
    }
  for (int a = 0; a < TS_SOLID_AXES; a++)
    if (run->exemplar_of[a] >= 0 && !(l->source[a] = malloc (voxels * sizeof (int32_t))))
      return TS_ERROR_OUT_OF_MEMORY;
  return TS_OK;
}

/* Every voxel's E-step batch for this iteration: a random voxel order at
 * batch granularity, the same for any thread count. */
static void
assign_batches (uint8_t *batch_of, size_t voxels, uint32_t seed, uint32_t stream)
{
#pragma omp parallel for schedule(static) if (voxels >= TS_SOLID_PARALLEL_EDGE * TS_SOLID_PARALLEL_EDGE * TS_SOLID_PARALLEL_EDGE)
  for (ptrdiff_t p = 0; p < (ptrdiff_t) voxels; p++)
    batch_of[p] = (uint8_t) ts_random_below (ts_random (seed, stream, 0, (uint64_t) p, 9),
                                             TS_SOLID_BATCHES);
}

typedef struct
{
  TsAxisGrid    gu, gv;
  TsSolidMatch *matches[TS_SOLID_AXES];
  size_t        t_offset[TS_SOLID_AXES]; /* each orientation's searched slices */
} Iteration;

static void
iteration_free (Iteration *it)
{
  ts_axis_grid_free (&it->gu);
  ts_axis_grid_free (&it->gv);
  for (int a = 0; a < TS_SOLID_AXES; a++)
    free (it->matches[a]);
}

/* One M-step (all orientations) and one E-step (all batches); sets
 * *changed to the number of voxels whose value changed. */
static TsStatus
iterate (Run *run, const TsPass *pass, uint32_t stream, uint8_t *batch_of,
         TsSolidHistogram *histogram, size_t *changed)
{
  TsSolidLevel *l = &run->level;
  size_t n = l->n, voxels = cube (n), radius = pass->patch / 2;
  size_t leaves = ts_solid_index_leaves (run->params->quality);
  double share = (double) voxels / (double) (TS_SOLID_AXES + 1);
  Iteration it;
  TsSolidHistogramDelta delta;
  TsStatus status;

  memset (&it, 0, sizeof it);
  memset (delta, 0, sizeof delta);
  *changed = 0;
  /* A new grid offset each iteration hides the grid's regularity. */
  status = ts_axis_grid_init (&it.gu, n, radius, pass->spacing, stream % pass->spacing, l->periodic);
  if (status == TS_OK)
    status = ts_axis_grid_init (&it.gv, n, radius, pass->spacing, (stream >> 8) % pass->spacing,
                                l->periodic);
  for (int a = 0; a < TS_SOLID_AXES && status == TS_OK; a++)
    {
      if (!l->source[a])
        continue;
      /* Each orientation its own slices of the sparse grid. */
      it.t_offset[a] = (stream >> (16 + a)) % TS_SOLID_SLICE_SPACING;
      /* The E-step copied the exemplar's distances; the volume's are
       * fixed, and at the finest level measured in this orientation's
       * slices. */
      if (run->cells.field)
        ts_solid_cell_guide_apply (&run->cells, l->value, a);
      it.matches[a] = malloc (ts_solid_match_slices (n) * it.gu.centres * it.gv.centres
                              * sizeof (TsSolidMatch));
      status = it.matches[a] ? ts_solid_mstep (l, a, &it.gu, &it.gv, pass, leaves, it.t_offset[a],
                                               stream + (uint32_t) a, it.matches[a], &run->midway)
                             : TS_ERROR_OUT_OF_MEMORY;
      if (status == TS_OK && !report (run, share, "optimizing volume"))
        status = TS_ERROR_CANCELLED;
    }
  if (status == TS_OK)
    assign_batches (batch_of, voxels, run->params->seed, stream);
  /* The cells' tones as the M-step left them, fixed for all batches. */
  if (status == TS_OK && l->cell_of)
    ts_solid_cell_tones (&run->cells, l);
  for (uint8_t b = 0; b < TS_SOLID_BATCHES && status == TS_OK; b++)
    {
      if (histogram)
        ts_solid_histogram_excess (histogram, l);
      if (histogram && l->position_weight > 0.0f)
        ts_solid_position_excess (l);
      *changed += ts_solid_estep (l, &it.gu, &it.gv, it.matches, it.t_offset, batch_of, b,
                                  histogram, delta, &run->midway);
      if (histogram)
        ts_solid_histogram_apply (histogram, delta);
      if (ts_cancel_poll (&run->midway))
        status = TS_ERROR_CANCELLED;
    }
  if (status == TS_OK && !report (run, share, "optimizing volume"))
    status = TS_ERROR_CANCELLED;
  iteration_free (&it);
  return status;
}

/* Every exemplar's index of all neighbourhoods of `patch` at `level` and
 * their variances, and the views that search and weigh with them. */
static TsStatus
index_exemplars (Run *run, size_t level, size_t patch)
{
  for (size_t e = 0; e < run->exemplars; e++)
    {
      Exemplar *ex = &run->exemplar[e];
      TsStatus status;
      ts_solid_index_free (&ex->index);
      status = ts_solid_index_build (&ex->pyramid, level, patch, &run->midway, &ex->index);
      if (status == TS_OK)
        status = ts_solid_variance_map_build (&ex->pyramid.level[level], patch / 2, level > 0,
                                              &ex->variance);
      if (status != TS_OK)
        return status;
    }
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      Exemplar *ex = run->exemplar_of[a] < 0 ? NULL : &run->exemplar[run->exemplar_of[a]];
      run->level.view[a].variance = ex ? &ex->variance : NULL;
      run->level.view[a].index = ex && ex->index.patch != 0 ? &ex->index : NULL;
    }
  return TS_OK;
}

static TsStatus
optimize_level (Run *run, size_t level, const TsLevelPlan *plan)
{
  size_t voxels = cube (run->level.n);
  uint8_t *batch_of = malloc (voxels);
  TsSolidHistogram histogram;
  TsStatus status = batch_of ? TS_OK : TS_ERROR_OUT_OF_MEMORY;

  if (run->params->histogram_matching)
    ts_solid_histogram_init (&histogram, &run->level);
  if (run->params->histogram_matching && run->level.position_weight > 0.0f)
    ts_solid_position_count (&run->level);
  for (size_t pi = 0; pi < plan->passes && status == TS_OK; pi++)
    {
      const TsPass *pass = &plan->pass[pi];
      size_t it;
      /* Indexing all of a large exemplar's neighbourhoods is the level's
       * exemplar matching: midway reports say so. */
      run->stage = "matching exemplar";
      status = index_exemplars (run, level, pass->patch);
      run->stage = "optimizing volume";
      for (it = 0; it < pass->max_iterations && status == TS_OK; it++)
        {
          uint32_t stream = (uint32_t) ts_random (run->params->seed, (uint32_t) level,
                                                  (uint32_t) (pi * 1000 + it), 0, 2);
          size_t changed;
          status = iterate (run, pass, stream, batch_of,
                            run->params->histogram_matching ? &histogram : NULL, &changed);
          if (status == TS_OK && (double) changed < TS_SOLID_CONVERGED_FRACTION * (double) voxels)
            {
              it++;
              break;
            }
        }
      /* Credit the iterations convergence made unnecessary. */
      run->progress.done += (double) (pass->max_iterations - it) * (double) voxels;
    }
  if (status == TS_OK && level == 0)
    status = ts_solid_remove_specks (&run->level);
  free (batch_of);
  return status;
}

static TsStatus
synthesize_level (Run *run, size_t level)
{
  TsLevelPlan plan;
  TsStatus status;

  /* The finished level becomes the parent of this one. */
  level_free (&run->coarser, run->volume);
  run->coarser = run->level;
  memset (&run->level, 0, sizeof run->level);

  plan_level (run, level, &plan);
  run->stage = "matching exemplar";
  status = prepare_views (run, level);
  if (status == TS_OK && !report (run, (double) cube (level_edge (run->params->size, level)),
                                  "matching exemplar"))
    status = TS_ERROR_CANCELLED;
  run->stage = "optimizing volume";
  if (status == TS_OK)
    status = level_alloc (run, level);
  if (status != TS_OK)
    return status;
  if (level + 1 == run->levels)
    ts_solid_start_random_blocks (&run->level, level, plan.pass[0].patch, run->params->seed,
                                  run->params->cell_structure);
  else
    ts_solid_start_from_coarser (&run->level, &run->coarser, level, run->params->seed,
                                 &run->midway);
  level_free (&run->coarser, run->volume);
  if (ts_cancel_poll (&run->midway))
    return TS_ERROR_CANCELLED;
  if (run->params->cell_structure)
    status = ts_solid_cell_guide_level (&run->cells, run->level.n, &run->midway);
  else if (level == 0 && run->levels > 1)
    status = ts_solid_phase_plan_start (&run->phases, &run->level, run->finest, run->exemplar_of,
                                        &run->midway);
  if (status != TS_OK)
    return status;
  run->level.continuation = level == 0 ? TS_SOLID_CONTINUATION : 0.0f;
  run->level.no_lone_voxels = level == 0;
  run->level.shear = run->params->cell_structure || level >= TS_SOLID_SHEAR_LEVELS ? 0.0f : TS_SOLID_SHEAR;
  run->level.cell_of = run->cells.cell_of;
  run->level.cell_tone = NULL;
  return optimize_level (run, level, &plan);
}

TsStatus
ts_synthesize_solid_with_sources (const TsSolidParams *params, const TsImage *const exemplars[3],
                                  float *volume, TsSolidSource *sources, TsProgressFunc progress,
                                  void *user_data, TsError *error)
{
  Run run;
  TsSolidParams resolved;
  TsStatus status = ts_solid_params_validate (params, exemplars, error);

  if (status != TS_OK)
    return status;
  ts_solid_resolve_params (params, exemplars, &resolved);
  params = &resolved;
  if (!volume)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no volume to write into");
  if (!sources != !params->record_sources)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "sources are written exactly when record_sources is set");
  memset (&run, 0, sizeof run);
  run.mirrored_axis = -1;
  run.sources = sources;
  run.params = params;
  run.progress.func = progress;
  run.progress.user_data = user_data;
  run.volume = volume;
  run.stage = "matching exemplar";
  ts_cancel_init (&run.midway, progress ? report_midway : NULL, &run);
  status = prepare_exemplars (&run, exemplars);
  if (status == TS_OK)
    {
      run.progress.total = planned_work (&run);
      for (size_t l = run.levels; l-- > 0 && status == TS_OK;)
        status = synthesize_level (&run, l);
    }
  if (status == TS_OK && sources && run.mirrored_axis >= 0)
    ts_solid_unmirror_sources (sources, cube (params->size), run.mirrored_axis,
                               run.exemplar[run.exemplar_of[run.mirrored_axis]].working.width);
  if (status == TS_OK)
    {
      size_t voxels = cube (params->size);
      for (size_t p = 0; p < voxels; p++)
        volume[p * TS_CHANNELS + 3] = params->cell_structure
                                        ? 1.0f /* opaque exemplars; alpha held distances */
                                        : volume[p * TS_CHANNELS + 3] / TS_ALPHA_SCALE;
      report (&run, 0, "done");
    }
  run_free (&run);
  if (status != TS_OK)
    return ts_fail (error, status, "%s", ts_status_string (status));
  return TS_OK;
}
