/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "schedule.h"
#include "pyramid.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* Most k-coherence candidates at any level: k grows by 3 per coarser
 * level, and the tables hold k per exemplar pixel, so this bounds their
 * memory at deep pyramids. */
#define TS_MAX_K_LEVEL 30
/* Iterations per pass at the finest level: it starts from the coarser
 * level's converged layout and only refines edges. */
#ifndef TS_FINEST_ITERATIONS
#define TS_FINEST_ITERATIONS 2
#endif

int
ts_schedule_threads (void)
{
#ifdef _OPENMP
  return omp_get_max_threads ();
#else
  return 1;
#endif
}

/* k-1 similar neighbourhoods at the finest level, 3 more per coarser level. */
static size_t
k_for_level (int quality, size_t level)
{
  size_t k = (size_t) quality + 3 * level;
  return k > TS_MAX_K_LEVEL ? TS_MAX_K_LEVEL : k;
}

size_t
ts_schedule_max_candidates (int quality)
{
  return k_for_level (quality, 32);
}

size_t
ts_schedule_levels (const TsImage *exemplar)
{
  return ts_pyramid_depth_for (exemplar->width, exemplar->height, TS_COARSEST_SIDE);
}

/* Largest odd size <= want that leaves at least a few valid centres in an
 * ex_w x ex_h exemplar level. */
static size_t
fit_patch (size_t want, size_t ex_w, size_t ex_h)
{
  size_t side = ex_w < ex_h ? ex_w : ex_h;
  size_t limit = side >= 6 ? side - 4 : side;  /* keep >= 5 centres per row */

  if (want > limit)
    want = limit;
  if (want % 2 == 0)
    want--;
  return want < 1 ? 1 : want;
}

static void
set_pass (TsPass *pass, size_t patch, size_t iterations)
{
  pass->patch = patch;
  /* A quarter of the neighbourhood (Kwatra et al.), rounded to the
   * nearest, but never every pixel: 2 is as good and four times
   * cheaper. */
  size_t quarter = (patch + 2) / 4;
  pass->spacing = quarter > 2 ? quarter : (patch >= 3 ? 2 : 1);
  pass->max_iterations = iterations;
  pass->propose_step = patch >= 7 ? 2 : 1;
}

void
ts_schedule_level (const TsParams *params, size_t level, size_t levels,
                   size_t ex_w, size_t ex_h, TsLevelPlan *plan)
{
  /* Smaller coarse neighbourhoods cut plain results into more, smaller
   * copies at the same coherence; a wrap-around result has no free
   * border to settle its layout against and keeps larger ones, which
   * made it clearly more coherent. */
  bool wrap = params->wrap_x || params->wrap_y;
  size_t coarse_large = wrap ? 11 : 9, coarse_small = wrap ? 7 : 5;
  size_t large = params->patch_size ? (size_t) params->patch_size : (level == 0 ? 11 : coarse_large);
  size_t small = params->fine_patch_size ? (size_t) params->fine_patch_size
                 : (level == 0 ? 7 : coarse_small);
  /* The coarsest level sets the layout from a random start and needs the
   * most iterations; finer levels start close to converged. */
  size_t iterations = params->max_iterations ? (size_t) params->max_iterations
                      : (level + 1 == levels ? 6 : (level == 0 ? TS_FINEST_ITERATIONS : 3));

  if (small > large)
    small = large;
  large = fit_patch (large, ex_w, ex_h);
  small = fit_patch (small, ex_w, ex_h);

  plan->k_level = k_for_level (params->quality, level);
  plan->k_use = plan->k_level;
  plan->passes = 0;
  set_pass (&plan->pass[plan->passes++], large, iterations);
  if (small < large)
    set_pass (&plan->pass[plan->passes++], small, iterations);
}
