/* The solid engine's schedule: the 2D one (engine/schedule.c), with the
 * same neighbourhood fitting, but its own neighbourhood sizes, iteration
 * counts, small neighbourhoods only at the middle levels, at the finest
 * level a sparser grid of large neighbourhoods, and a search breadth
 * set by the quality.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

/* Default neighbourhood sides: large first, to lay out shapes a few
 * features wide, then small, to draw their edges. */
#define TS_SOLID_PATCH 9
#define TS_SOLID_FINE_PATCH 5
/* Least spacing, within a slice, of the large neighbourhoods at a
 * finest level of at least TS_SOLID_SPARSE_EDGE voxels (the 2D
 * schedule's patch / 4 gives 2). With 3 a voxel gets 13.5 votes instead
 * of 30 in that pass's E-step and the M-step searches 4/9 as many
 * centres: a large volume runs about a quarter faster, with quality
 * within the seed-to-seed spread. Small volumes are fast anyway, and
 * there the fewer votes blunted the cells, so they keep 2; where the
 * edge lies between is fitted (docs/design.md, Known limits). */
#define TS_SOLID_FINEST_SPACING 3
#define TS_SOLID_SPARSE_EDGE 128
/* Finest level's iterations per pass (2D: 2): a volume converges more
 * slowly than an image, its three orientations pulling apart; a third
 * iteration improves completeness and a fourth coherence, the gains
 * smaller with each. Chosen on the truth solids. */
#define TS_SOLID_FINEST_ITERATIONS 4
/* ...but 8 for its small-neighbourhood pass, the one that closes the
 * mortar around the stones: with it the middle levels need only 2
 * iterations per pass, and fewer middle iterations are what keeps spots
 * from merging; the cost is about a quarter more time. */
#define TS_SOLID_FINEST_SMALL_ITERATIONS 8
/* ...and 12 for exemplars whose light phase lies in separate pieces
 * (stones in mortar, phase-guide.c): its walls at necks leave joints
 * that more small iterations close, for better coherence at a little
 * sharpness and about 30 % more time. Not for spots, which only
 * thicken with more iterations. */
#define TS_SOLID_FINEST_JOINT_ITERATIONS 12
/* Iterations per pass of the levels between the coarsest and the finest
 * (2D: 3). Each one merges more spots; the finest level's long small
 * pass settles the cells' layout, and 2 here is the fewest that still
 * hands it a settled one (with 1 the cells' layout came unsettled). */
#define TS_SOLID_MIDDLE_ITERATIONS 2

/* Index leaves visited per quality step: the default quality (2) visits
 * 6. The solid engine's search effort is this breadth, not the 2D
 * engine's k-coherence candidates: those added to it cost about a fifth
 * more time, improved no figure and blunted the cells. */
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
   * the small ones (one pass): a large pass there merges spots into
   * fewer, thicker bodies, and the coarsest and finest levels already
   * lay the shapes out. A 64^3 volume from a 64^2 exemplar, as in the
   * tests, has no middle level. */
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
