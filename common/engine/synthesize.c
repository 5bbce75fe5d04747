/* Coarse-to-fine texture optimization driver (Kwatra et al. 2005 with
 * k-coherence search over MRPM candidate sets).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "synthesize.h"
#include "active-region.h"
#include "lattice.h"
#include "level.h"
#include "level-start.h"
#include "occurrence.h"
#include "seam-placement.h"
#include "progress.h"
#include "rng.h"
#include "error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A level stops iterating once fewer output pixels than this change: a
 * fifth of a percent, a few scattered pixels. */
#define TS_CONVERGED_FRACTION 0.002
/* Occurrence penalty per unit of over-use, in exemplar variances: a
 * tenth, so it decides between matches about equally good but never
 * outweighs a visibly better one. It spreads the layout over the
 * exemplar at the coarser levels; the finest level, whose layout is
 * set, goes without: there it drove the matches off the few pixels that
 * thin structures (cracks, coastlines) are copied from, onto even parts
 * (docs/benchmarks.md, "Occurrence penalty at the finest level"). */
#define TS_OCCURRENCE_STRENGTH 0.1f
/* Width of the band around a tile edge whose coherence matters: the
 * 7x7 windows that straddle it. */
#define TS_SEAM_BAND 7

typedef struct
{
  const TsParams *params;
  const uint8_t  *needed;        /* output pixels the caller needs, or NULL */
  TsExemplarMemo *memo;          /* candidate sets kept between calls, or NULL */
  TsProgress      progress;
  TsCancel        cancel;        /* lets the steps ask `progress` midway    */
  const char     *stage;         /* what a midway report says             */
} Run;

/* Asked by OpenMP thread 0 (the caller's thread) from inside the steps. */
static bool
report_midway (void *data)
{
  Run *run = data;
  return ts_progress_report (&run->progress, 0.0, run->stage);
}


/* Under a guide the histogram to match is the exemplar's parts in the
 * shares the target asks for. */
static TsStatus
want_guided_histogram (TsHistogram *histogram, const TsLevelState *state)
{
  float *wanted = malloc (ts_image_pixel_count (state->exemplar) * sizeof (float));
  if (!wanted)
    return TS_ERROR_OUT_OF_MEMORY;
  ts_guide_wanted_usage (state->guide, state->exemplar, wanted);
  ts_histogram_set_wanted (histogram, wanted);
  free (wanted);
  return TS_OK;
}

/* All iterations of all passes of one level. */
static TsStatus
optimize_level (Run *run, TsLevelState *state, const TsLevelPlan *plan, size_t level)
{
  const TsParams *params = run->params;
  size_t pixels = state->width * state->height;
  TsHistogram *histogram = NULL;
  TsOccurrence occurrence;
  uint32_t *usage;
  TsStatus status;
  float occ_strength = level > 0 ? TS_OCCURRENCE_STRENGTH : 0.0f;
  size_t free_pixels = pixels, counted = state->active ? 0 : pixels;
  TsRegionBound region_bound = { 0 };

  /* Convergence is judged on the pixels that may change: with most of
   * the output preserved, a fraction of all pixels would stop the
   * optimization of the rest early. */
  if (state->active)
    for (size_t p = 0; p < pixels; p++)
      counted += state->active[p] != 0;
  if (state->preserve || state->active)
    {
      free_pixels = 0;
      for (size_t p = 0; p < pixels; p++)
        free_pixels += (!state->preserve || state->preserve[p] < 1.0f)
                       && (!state->active || state->active[p]);
    }

  usage = malloc (ts_image_pixel_count (state->exemplar) * sizeof (uint32_t));
  if (!usage)
    return TS_ERROR_OUT_OF_MEMORY;
  status = ts_occurrence_init (&occurrence, state->exemplar, occ_strength);
  if (status != TS_OK)
    {
      free (usage);
      return status;
    }
  state->penalty = occ_strength > 0.0f ? occurrence.penalty : NULL;

  if (ts_region_bound_applies (params))
    {
      status = ts_region_bound_init (&region_bound, state->width, state->height,
                                     state->exemplar->width, state->exemplar->height);
      if (status != TS_OK)
        {
          ts_occurrence_free (&occurrence);
          free (usage);
          return status;
        }
      state->region_bound = &region_bound;
    }

  if (params->histogram_matching)
    {
      histogram = malloc (sizeof *histogram);
      if (!histogram || ts_histogram_init (histogram, state->exemplar) != TS_OK ||
          (state->guide && want_guided_histogram (histogram, state) != TS_OK))
        {
          if (histogram)
            ts_histogram_free (histogram);
          free (histogram);
          ts_occurrence_free (&occurrence);
          ts_region_bound_free (&region_bound);
          free (usage);
          return TS_ERROR_OUT_OF_MEMORY;
        }
    }

  for (size_t pi = 0; pi < plan->passes && status == TS_OK; pi++)
    {
      const TsPass *pass = &plan->pass[pi];
      size_t it;
      for (it = 0; it < pass->max_iterations; it++)
        {
          uint32_t stream = (uint32_t) ts_random (params->seed, (uint32_t) level,
                                                  (uint32_t) (pi * 1000 + it), 0, 2);
          TsAxisGrid gx, gy;
          TsMatch *matches;
          size_t changed;

          /* A new grid offset each iteration hides the grid's regularity. */
          status = ts_axis_grid_init (&gx, state->width, pass->patch / 2, pass->spacing,
                                      stream % pass->spacing, state->wrap_x);
          if (status != TS_OK)
            break;
          status = ts_axis_grid_init (&gy, state->height, pass->patch / 2, pass->spacing,
                                      (stream >> 8) % pass->spacing, state->wrap_y);
          if (status != TS_OK)
            {
              ts_axis_grid_free (&gx);
              break;
            }
          /* The M-step leaves the sources alone: one count serves the
           * penalty now and the histogram after it. */
          if (state->penalty || histogram)
            ts_occurrence_count (state->source, state->active, pixels, usage,
                                 ts_image_pixel_count (state->exemplar));
          if (state->penalty)
            ts_occurrence_update (&occurrence, usage, counted, pass->patch, state->opaque_count);
          if (state->region_bound)
            ts_region_bound_mark (&region_bound, state->source, state->exemplar->width);
          matches = malloc (gx.centres * gy.centres * sizeof (TsMatch));
          status = matches ? ts_mstep (state, &gx, &gy, pass, plan->k_use, stream, matches)
                           : TS_ERROR_OUT_OF_MEMORY;
          /* An iteration of a large level takes long: a cancel between
           * its two steps halves the wait. */
          if (status == TS_OK && !ts_progress_report (&run->progress, 0.0, "optimizing"))
            status = TS_ERROR_CANCELLED;
          if (status == TS_OK)
            {
              if (histogram)
                ts_histogram_update (histogram, usage);
              changed = ts_estep (state, &gx, &gy, matches, histogram);
              if (ts_cancel_requested (state->cancel))
                status = TS_ERROR_CANCELLED;
            }
          free (matches);
          ts_axis_grid_free (&gx);
          ts_axis_grid_free (&gy);
          if (status != TS_OK)
            break;
          if (!ts_progress_report (&run->progress, (double) pixels, "optimizing"))
            {
              status = TS_ERROR_CANCELLED;
              break;
            }
          if ((double) changed < TS_CONVERGED_FRACTION * (double) free_pixels)
            {
              it++;
              break;
            }
        }
      /* Credit the iterations convergence made unnecessary. */
      run->progress.done += (double) (pass->max_iterations - it) * (double) pixels;
    }
  if (histogram)
    ts_histogram_free (histogram);
  free (histogram);
  ts_occurrence_free (&occurrence);
  ts_region_bound_free (&region_bound);
  free (usage);
  state->penalty = NULL;
  state->region_bound = NULL;
  return status;
}

static double
planned_work (const TsParams *params, const TsPyramid *pyramid)
{
  double total = 0;
  for (size_t l = 0; l < pyramid->levels; l++)
    {
      TsLevelPlan plan;
      double pixels = (double) ts_level_side (params->output_width, l) *
                      (double) ts_level_side (params->output_height, l);
      ts_schedule_level (params, l, pyramid->levels, pyramid->level[l].width,
                         pyramid->level[l].height, &plan);
      total += pixels; /* MRPM of the level, about one iteration's work */
      for (size_t p = 0; p < plan.passes; p++)
        total += (double) plan.pass[p].max_iterations * pixels;
    }
  return total;
}

typedef struct
{
  TsImage         working;
  TsPyramid       pyramid;
  TsCandidateSet  candidates, coarser_candidates;   /* without a memo */
  const TsCandidateSet *coarser_set;                 /* the coarser level's */
  TsLevelState    state;
  int32_t        *opaque;
  int32_t        *coarser_source;
  size_t          coarser_width, coarser_ex_width;
  int32_t        *initial_source;
  float          *initial_preserve;
  float          *disagreement;
  TsGuidePyramid  guides;
  TsGuideLevel    guide_level;
  TsActiveRegion  active;
} Work;

static void
work_free_level (Work *w)
{
  free (w->opaque);
  free (w->initial_source);
  free (w->initial_preserve);
  ts_guide_level_free (&w->guide_level);
  ts_active_region_free (&w->active);
  w->opaque = NULL;
  w->initial_source = NULL;
  w->initial_preserve = NULL;
}

static void
work_free (Work *w)
{
  work_free_level (w);
  free (w->state.source);
  free (w->coarser_source);
  free (w->disagreement);
  ts_candidate_set_free (&w->candidates);
  ts_candidate_set_free (&w->coarser_candidates);
  ts_pyramid_free (&w->pyramid);
  ts_guide_pyramid_free (&w->guides);
  ts_image_free (&w->working);
}

/* Rolls a finished wrap-around result so its tile edges run where the
 * synthesis is most coherent. */
static TsStatus
place_tile_edges (TsLevelState *state)
{
  size_t sx, sy;
  TsStatus status = ts_seam_best_shift (state->disagreement, state->width, state->height,
                                        state->wrap_x, state->wrap_y, TS_SEAM_BAND, &sx, &sy);
  if (status == TS_OK)
    status = ts_seam_roll (state->source, state->width, state->height, sizeof (int32_t), sx, sy);
  return status;
}

static TsStatus
synthesize_level (Run *run, Work *w, size_t level)
{
  const TsParams *params = run->params;
  const TsImage *ex = &w->pyramid.level[level];
  TsLevelState *state = &w->state;
  TsMrpmOptions options;
  TsLevelPlan plan;
  TsStatus status;

  ts_schedule_level (params, level, w->pyramid.levels, ex->width, ex->height, &plan);
  ts_mrpm_options_init (&options);
  /* Fewer re-ranks were measured on plain synthesis only; under a
   * caller's guides style transfer followed the target less closely. */
  if (params->guides)
    options.rerank = options.rerank_coarsest;
  run->stage = "matching exemplar";
  /* A memo's set of this level, if it has one, saves the matching. */
  TsCandidateSet *set = run->memo ? &run->memo->sets[level] : &w->candidates;
  if (!run->memo || !set->index || set->k != plan.k_level)
    {
      ts_candidate_set_free (set);
      status = ts_mrpm_level (&w->pyramid, level, level + 1 < w->pyramid.levels ? w->coarser_set : NULL,
                              plan.k_level, &options, &run->cancel, set);
      if (status != TS_OK)
        return status;
    }
  ts_candidate_set_free (&w->coarser_candidates);
  if (!ts_progress_report (&run->progress, (double) ts_level_side (params->output_width, level) *
                           (double) ts_level_side (params->output_height, level),
                           "matching exemplar"))
    return TS_ERROR_CANCELLED;
  run->stage = "optimizing";

  memset (state, 0, sizeof *state);
  state->exemplar = ex;
  state->candidates = set;
  state->width = ts_level_side (params->output_width, level);
  state->height = ts_level_side (params->output_height, level);
  state->wrap_x = params->wrap_x;
  state->wrap_y = params->wrap_y;
  state->cancel = &run->cancel;
  /* A lattice guide leaves some levels free (lattice-guide.c). */
  if (w->guides.levels && (w->guides.labels || w->guides.exemplar[level].value.pixels))
    {
      if ((status = ts_guide_level_init (&w->guides, level, ex, &w->guide_level)) != TS_OK)
        return status;
      state->guide = &w->guide_level;
    }
  /* Where the texture alone lays out the structures (the coarser
   * levels, no guide), each pixel follows the copy its neighbourhoods
   * agree on: the vote nearest their mean picked, where they disagreed,
   * in-between tones that blurred thin structures away. Under a guide,
   * the guide lays them out, and there agreeing copies held a lattice's
   * phase less well. The finest level keeps the vote nearest the mean,
   * which hides the seams between copies in smooth gradients
   * (docs/benchmarks.md, "Consensus votes at the coarser levels"). */
  state->consensus = level > 0 && !state->guide;
  if ((status = ts_level_list_opaque (ex, &w->opaque, &state->opaque_count)) != TS_OK)
    return status;
  state->opaque = w->opaque;
  if (state->opaque_count == 0)
    return TS_ERROR_TRANSPARENT_EXEMPLAR;
  state->source = malloc (state->width * state->height * sizeof (int32_t));
  if (!state->source)
    return TS_ERROR_OUT_OF_MEMORY;
  if (params->initial_source)
    {
      status = ts_level_initial (params, ex, level, state->width, state->height,
                                 &w->initial_source, &w->initial_preserve);
      if (status != TS_OK)
        return status;
      state->preserve_source = w->initial_source;
      state->preserve = w->initial_preserve;
    }
  if (run->needed)
    {
      size_t patch = plan.pass[0].patch;
      for (size_t p = 1; p < plan.passes; p++)
        patch = plan.pass[p].patch > patch ? plan.pass[p].patch : patch;
      status = ts_active_region_init (&w->active, run->needed, params->output_width,
                                      params->output_height, level, state->width, state->height,
                                      patch / 2, params->wrap_x, params->wrap_y);
      if (status != TS_OK)
        return status;
      state->active = w->active.pixels;
      state->active_centres = w->active.centres;
    }
  status = ts_level_start_sources (state, params, level, plan.pass[0].patch, w->coarser_source,
                                   w->coarser_width, w->coarser_ex_width);
  if (status != TS_OK)
    return status;

  /* Tile edges are placed by rolling the result, which would move it
   * off a guide's layout. */
  if (level == 0 && (params->wrap_x || params->wrap_y) && !params->initial_source &&
      !params->guides)
    {
      w->disagreement = calloc (state->width * state->height, sizeof (float));
      if (!w->disagreement)
        return TS_ERROR_OUT_OF_MEMORY;
      state->disagreement = w->disagreement;
    }
  status = optimize_level (run, state, &plan, level);
  if (status == TS_OK && state->disagreement)
    status = place_tile_edges (state);
  if (status != TS_OK)
    return status;

  /* The finished level seeds the next; candidates move down too. */
  free (w->coarser_source);
  w->coarser_source = state->source;
  w->coarser_width = state->width;
  w->coarser_ex_width = ex->width;
  state->source = NULL;
  w->coarser_candidates = w->candidates;
  memset (&w->candidates, 0, sizeof w->candidates);
  w->coarser_set = run->memo ? set : &w->coarser_candidates;
  if (level > 0)
    work_free_level (w);
  return TS_OK;
}

static void
write_result (const TsParams *params, const Work *w, TsImage *output)
{
  const TsImage *ex = &w->pyramid.level[0];
  size_t n = params->output_width * params->output_height;

  /* The result is the finest level's sources, looked up in the exemplar
   * (alpha back to [0, 1] as ts_image_from_working does). */
#pragma omp parallel for schedule(static)
  for (ptrdiff_t p = 0; p < (ptrdiff_t) n; p++)
    {
      float *o = output->pixels + (size_t) p * TS_CHANNELS;
      memcpy (o, ex->pixels + (size_t) w->coarser_source[p] * TS_CHANNELS, TS_CHANNELS * sizeof (float));
      o[3] /= TS_ALPHA_SCALE;
      if (params->source_map)
        {
          params->source_map[2 * p] = (int32_t) ((size_t) w->coarser_source[p] % ex->width);
          params->source_map[2 * p + 1] = (int32_t) ((size_t) w->coarser_source[p] / ex->width);
        }
    }
}

void
ts_exemplar_memo_free (TsExemplarMemo *memo)
{
  for (size_t l = 0; l < memo->levels; l++)
    ts_candidate_set_free (&memo->sets[l]);
  free (memo->sets);
  memo->sets = NULL;
  memo->levels = 0;
}

TsStatus
ts_synthesize_optimized (const TsParams *params, const TsImage *exemplar, TsImage *output,
                         TsProgressFunc progress, void *user_data, TsError *error)
{
  return ts_synthesize_needed (params, exemplar, NULL, NULL, output, progress, user_data, error);
}

TsStatus
ts_synthesize_needed (const TsParams *params, const TsImage *exemplar, const uint8_t *needed,
                      TsExemplarMemo *memo, TsImage *output, TsProgressFunc progress,
                      void *user_data, TsError *error)
{
  Run run = { .params = params, .needed = needed,
             .progress = { .func = progress, .user_data = user_data },
             .stage = "matching exemplar" };
  Work w;
  TsStatus status;

  ts_cancel_init (&run.cancel, progress ? report_midway : NULL, &run);

  memset (&w, 0, sizeof w);
  status = ts_image_to_working (exemplar, &w.working);
  if (status == TS_OK)
    status = ts_pyramid_build (&w.working, ts_schedule_levels (exemplar), &w.pyramid);
  if (status == TS_OK && memo && !memo->levels)
    {
      memo->sets = calloc (w.pyramid.levels, sizeof *memo->sets);
      memo->levels = memo->sets ? w.pyramid.levels : 0;
      if (!memo->sets)
        status = TS_ERROR_OUT_OF_MEMORY;
    }
  /* A memo of another exemplar's pyramid is left alone. */
  if (status == TS_OK && memo && memo->levels == w.pyramid.levels)
    run.memo = memo;
  if (status == TS_OK && params->guides)
    status = ts_guide_pyramid_build (params, exemplar, &w.pyramid, &w.guides);
  else if (status == TS_OK && !params->initial_source)
    {
      /* A near-regular exemplar guides the synthesis by its own lattice. */
      TsLatticeEstimate lattice;
      status = ts_lattice_estimate (&w.pyramid, &lattice);
      if (status == TS_OK)
        status = ts_lattice_guide_build (&lattice, &w.pyramid, params->output_width,
                                         params->output_height, params->wrap_x, params->wrap_y,
                                         &w.guides);
    }
  if (status == TS_OK)
    {
      run.progress.total = planned_work (params, &w.pyramid);
      for (size_t l = w.pyramid.levels; l-- > 0 && status == TS_OK;)
        status = synthesize_level (&run, &w, l);
    }
  if (status == TS_OK)
    {
      write_result (params, &w, output);
      ts_progress_report (&run.progress, 0, "done");
    }
  work_free (&w);
  if (status != TS_OK)
    return ts_fail (error, status, "%s", ts_status_string (status));
  return TS_OK;
}
