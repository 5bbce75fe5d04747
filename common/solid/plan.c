/* The solid engine's schedule: the 2D one (engine/schedule.c), with the
 * same neighbourhood fitting, but its own neighbourhood sizes, iteration
 * counts, small neighbourhoods only at the middle levels, at the finest
 * level a sparser grid of large neighbourhoods, and a search breadth
 * set by the quality.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

/* Default neighbourhood sides: large first, then small. */
#define TS_SOLID_PATCH 9
#define TS_SOLID_FINE_PATCH 5
/* Least spacing, within a slice, of the large neighbourhoods at a
 * finest level of at least TS_SOLID_SPARSE_EDGE voxels (the 2D
 * schedule's patch / 4 gives 2). With 3 a voxel gets 13.5 votes instead
 * of 30 in that pass's E-step and the M-step searches 4/9 as many
 * centres: 128^3 took 22-27 s instead of 30-33, with the truth solids'
 * figures within their seed-to-seed spread (solid history, stop 52). At 64^3,
 * a run of a few seconds, it blunted the cells (sharpness 0.909 ->
 * 0.896 x the truth's, below test-solid-shapes' 0.90), so smaller
 * volumes keep 2. */
#define TS_SOLID_FINEST_SPACING 3
#define TS_SOLID_SPARSE_EDGE 128
/* Finest level's iterations per pass (2D: 2); the third brings 128^3
 * cells' completeness from 1.17x to 1.13x the truth's, the fourth
 * brings their coherence back under 1.15x the truth's with the position
 * histogram (1.16-1.17x with 3 iterations). */
#define TS_SOLID_FINEST_ITERATIONS 4
/* ...but 8 for its small-neighbourhood pass, the one that closes the
 * mortar around 128^3 cells' stones: with it the middle levels need only
 * 2 iterations per pass, and fewer middle iterations are what keeps
 * blobs' spots from merging (128^3, seeds 1-5: blobs' sharpness mean
 * 0.89 -> 0.92 x the truth's, cells' coherence 1.13 -> 1.12 x; 14 ->
 * 18 s). */
#define TS_SOLID_FINEST_SMALL_ITERATIONS 8
/* ...and 12 for exemplars whose light phase lies in separate pieces
 * (stones in mortar, phase-guide.c): its walls at necks leave joints
 * that more small iterations close. 128^3 cells, seeds 1-6: coherence
 * 1.136 -> 1.097 x the truth's (seed 5 1.17 -> 1.14, the last aim
 * missed), sharpness 0.983 -> 0.968 x; 128^3 from the noise of the
 * solid-memory benchmark 19.6 -> 25.5 s. Not for spots (blobs, grains:
 * seed 2's sharpness 0.91 -> 0.90 x, their phases thicker). */
#define TS_SOLID_FINEST_JOINT_ITERATIONS 12
/* Iterations per pass of the levels between the coarsest and the finest
 * (2D: 3). Each one merges more of 128^3 blobs' spots. While the finest
 * small pass ran 4, the cells needed 4 here to settle their stone layout
 * (3 took their coherence to 1.16 x the truth's); now the finest level
 * settles it, and only 1 here unsettles it again (mean 1.14 x). */
#define TS_SOLID_MIDDLE_ITERATIONS 2

/* Index leaves visited per quality step: the default quality (2) visits
 * 6. The solid engine's search effort is this breadth, not the 2D
 * engine's k-coherence candidates (solid history, stop 57: MRPM's candidates
 * added to it cost 18 % more time at 128^3, met no missed aim and took
 * 128^3 cells' seed-4 sharpness below 0.9 x the truth's). */
#define TS_SOLID_LEAVES_PER_QUALITY 3

size_t
ts_solid_index_leaves (int quality)
{
  return (size_t) (quality > 1 ? quality : 1) * TS_SOLID_LEAVES_PER_QUALITY;
}

void
ts_solid_plan_level (const TsSolidParams *sp, size_t level, size_t levels, size_t n, size_t ex_w,
                     size_t ex_h, bool joints, TsLevelPlan *plan)
{
  TsParams p;
  bool sparse = level == 0 && n >= TS_SOLID_SPARSE_EDGE;
  bool middle = level > 0 && level + 1 < levels;

  ts_params_init (&p);
  p.quality = sp->quality;
  p.max_iterations = sp->max_iterations;
  /* With the automatic neighbourhood sizes the middle levels run only
   * the small ones (one pass): their large pass merged 128^3 blobs'
   * spots into fewer, thicker bodies (seeds 1-4: blobs' sharpness mean
   * 0.90 -> 0.94 x the truth's, cells' coherence 1.10 -> 1.11 x; aims
   * missed 2 -> 1 of 50). At stop 23, with 4 middle iterations per
   * pass, it unsettled the cells; the finest level has since taken
   * their layout over (solid history, stop 53). A 64^3 volume from a 64^2
   * exemplar, as in the tests, has no middle level. */
  p.patch_size = sp->patch_size ? sp->patch_size : (middle ? TS_SOLID_FINE_PATCH : TS_SOLID_PATCH);
  p.fine_patch_size = p.patch_size < TS_SOLID_FINE_PATCH ? p.patch_size : TS_SOLID_FINE_PATCH;
  p.wrap_x = p.wrap_y = sp->periodic;
  /* A neighbourhood no wider than the volume level itself. */
  ts_schedule_level (&p, level, levels, ex_w < n + 4 ? ex_w : n + 4, ex_h, plan);
  for (size_t i = 0; i < plan->passes; i++)
    {
      TsPass *pass = &plan->pass[i];
      if (sparse && pass->patch > TS_SOLID_FINE_PATCH && pass->spacing < TS_SOLID_FINEST_SPACING)
        pass->spacing = TS_SOLID_FINEST_SPACING;
      if (sp->max_iterations)
        continue;
      if (level == 0 && levels > 1)
        pass->max_iterations = i == 0  ? TS_SOLID_FINEST_ITERATIONS
                               : joints ? TS_SOLID_FINEST_JOINT_ITERATIONS
                                        : TS_SOLID_FINEST_SMALL_ITERATIONS;
      else if (middle)
        pass->max_iterations = TS_SOLID_MIDDLE_ITERATIONS;
    }
}
