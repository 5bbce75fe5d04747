/* Patch-based start of the coarsest level (image quilting, Efros &
 * Freeman 2001), laid out as source coordinates so that the finer levels
 * inherit it by coordinate upsampling.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "quilt-start.h"
#include "active-region.h"
#include "image.h"
#include "rng.h"

#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Patch side over the exemplar level's shorter side: large enough to
 * hold a few lattice periods of a near-regular exemplar, small enough
 * that a patch is a quarter of the exemplar, never the whole of it. */
#define TS_QUILT_PATCH_DIVISOR 2
/* Overlap over patch side: wide enough to see the lattice's phase. */
#define TS_QUILT_OVERLAP_DIVISOR 4
/* Candidates whose overlap error is within this fraction of the best
 * one's are equally good (Efros & Freeman's tolerance); a seeded pick
 * among them gives variety. */
#define TS_QUILT_TOLERANCE 0.1

typedef struct
{
  size_t patch, overlap, step;   /* set by layout_patches           */
  size_t cand_w, cand_h;   /* exemplar corners a whole patch fits at */
  size_t cols, rows;       /* patches across the output              */
} Layout;

/* The patch, overlap and step on an exemplar level (the rest of the
 * layout is set where the output's size is known). */
static void
layout_patches (const TsImage *ex, Layout *g)
{
  size_t side = ex->width < ex->height ? ex->width : ex->height;

  g->patch = side / TS_QUILT_PATCH_DIVISOR >= 3 ? side / TS_QUILT_PATCH_DIVISOR : side;
  g->overlap = g->patch / TS_QUILT_OVERLAP_DIVISOR >= 1 ? g->patch / TS_QUILT_OVERLAP_DIVISOR : 1;
  if (g->overlap >= g->patch)
    g->overlap = g->patch - 1;   /* a 1-pixel patch has no overlap */
  g->step = g->patch - g->overlap;
}

static size_t
patches_along (size_t n, const Layout *g)
{
  return n <= g->patch ? 1 : 1 + (n - g->patch + g->step - 1) / g->step;
}

static float
pixel_sq_distance (const float *a, const float *b)
{
  float s = 0.0f;
  for (size_t c = 0; c < TS_CHANNELS; c++)
    {
      float d = a[c] - b[c];
      s += d * d;
    }
  return s;
}

/* Sum of squared differences, over the overlap of the patch at output
 * (ox, oy) of size pw x ph, between what is laid there and the exemplar
 * patch at (cx, cy); once the sum passes `bound`, the partial sum. */
static float
overlap_error (const TsLevelState *state, size_t ox, size_t oy, size_t pw, size_t ph,
               size_t overlap, bool left, bool top, size_t cx, size_t cy, float bound)
{
  const TsImage *ex = state->exemplar;
  float sum = 0.0f;

  for (size_t y = 0; y < ph; y++)
    {
      size_t x_end = (top && y < overlap) ? pw : (left ? (overlap < pw ? overlap : pw) : 0);
      const int32_t *laid = state->source + (oy + y) * state->width + ox;
      const float *cand = ts_image_pixel (ex, cx, cy + y);
      for (size_t x = 0; x < x_end; x++)
        sum += pixel_sq_distance (ex->pixels + (size_t) laid[x] * TS_CHANNELS,
                                  cand + x * TS_CHANNELS);
      if (sum > bound)
        break;
    }
  return sum;
}

/* True if corner (cx, cy) would only continue the neighbour whose corner
 * is (nx, ny), shifted by (dx, dy): the exemplar pasted larger than one
 * patch. */
static bool
continues (size_t cx, size_t cy, const int32_t *neighbour, size_t dx, size_t dy, size_t overlap)
{
  ptrdiff_t ex = (ptrdiff_t) cx - ((ptrdiff_t) neighbour[0] + (ptrdiff_t) dx);
  ptrdiff_t ey = (ptrdiff_t) cy - ((ptrdiff_t) neighbour[1] + (ptrdiff_t) dy);
  return (ex < 0 ? -ex : ex) <= (ptrdiff_t) overlap && (ey < 0 ? -ey : ey) <= (ptrdiff_t) overlap;
}

/* Minimum-error path through `cost` (n_along x n_across, row-major along
 * the path) from one end to the other, moving at most one step across
 * per step along; stores the path's position across in `path`. */
static void
min_cut (float *cost, size_t n_along, size_t n_across, size_t *path)
{
  for (size_t a = 1; a < n_along; a++)
    for (size_t c = 0; c < n_across; c++)
      {
        float best = cost[(a - 1) * n_across + c];
        if (c > 0 && cost[(a - 1) * n_across + c - 1] < best)
          best = cost[(a - 1) * n_across + c - 1];
        if (c + 1 < n_across && cost[(a - 1) * n_across + c + 1] < best)
          best = cost[(a - 1) * n_across + c + 1];
        cost[a * n_across + c] += best;
      }
  size_t at = 0;
  for (size_t c = 1; c < n_across; c++)
    if (cost[(n_along - 1) * n_across + c] < cost[(n_along - 1) * n_across + at])
      at = c;
  path[n_along - 1] = at;
  for (size_t a = n_along - 1; a-- > 0;)
    {
      size_t best = at;
      if (at > 0 && cost[a * n_across + at - 1] < cost[a * n_across + best])
        best = at - 1;
      if (at + 1 < n_across && cost[a * n_across + at + 1] < cost[a * n_across + best])
        best = at + 1;
      at = best;
      path[a] = at;
    }
}

typedef struct
{
  float  *error;     /* per candidate corner                    */
  float  *cost;      /* patch x overlap, a cut's error map      */
  size_t *path;      /* patch entries                           */
  bool   *keep;      /* patch x patch: the laid pixel stays     */
  uint32_t *usage;   /* per candidate corner: patches laid near it */
} Scratch;

/* Marks the pixels of the new patch that stay as laid: those before the
 * minimum-error cuts through the left and top overlaps. */
static void
cut_overlaps (const TsLevelState *state, const Layout *g, Scratch *s, size_t ox, size_t oy,
              size_t pw, size_t ph, bool left, bool top, size_t cx, size_t cy)
{
  const TsImage *ex = state->exemplar;
  size_t ov_x = g->overlap < pw ? g->overlap : pw, ov_y = g->overlap < ph ? g->overlap : ph;

  for (size_t i = 0; i < pw * ph; i++)
    s->keep[i] = false;
  if (left && ov_x > 0)
    {
      for (size_t y = 0; y < ph; y++)
        for (size_t x = 0; x < ov_x; x++)
          s->cost[y * ov_x + x] = pixel_sq_distance (
            ex->pixels + (size_t) state->source[(oy + y) * state->width + ox + x] * TS_CHANNELS,
            ts_image_pixel (ex, cx + x, cy + y));
      min_cut (s->cost, ph, ov_x, s->path);
      for (size_t y = 0; y < ph; y++)
        for (size_t x = 0; x < s->path[y]; x++)
          s->keep[y * pw + x] = true;
    }
  if (top && ov_y > 0)
    {
      for (size_t x = 0; x < pw; x++)
        for (size_t y = 0; y < ov_y; y++)
          s->cost[x * ov_y + y] = pixel_sq_distance (
            ex->pixels + (size_t) state->source[(oy + y) * state->width + ox + x] * TS_CHANNELS,
            ts_image_pixel (ex, cx + x, cy + y));
      min_cut (s->cost, pw, ov_y, s->path);
      for (size_t x = 0; x < pw; x++)
        for (size_t y = 0; y < s->path[x]; y++)
          s->keep[y * pw + x] = true;
    }
}

/* Chooses the exemplar corner of patch (i, j): any at the first patch,
 * else a seeded pick among those whose overlap error is within the
 * tolerance of the best one and, of those, the least used (so the quilt
 * draws on the whole exemplar), leaving out corners that merely continue
 * the left or upper neighbour unless nothing else is left. */
static size_t
choose_corner (const TsLevelState *state, const Layout *g, Scratch *s, const int32_t *corner,
               size_t i, size_t j, uint64_t r)
{
  size_t ncand = g->cand_w * g->cand_h;
  size_t ox = j * g->step, oy = i * g->step;
  size_t pw = state->width - ox < g->patch ? state->width - ox : g->patch;
  size_t ph = state->height - oy < g->patch ? state->height - oy : g->patch;
  bool left = j > 0, top = i > 0;
  const int32_t *left_corner = left ? corner + 2 * (i * g->cols + j - 1) : NULL;
  const int32_t *top_corner = top ? corner + 2 * ((i - 1) * g->cols + j) : NULL;

  if (!left && !top)
    return (size_t) ts_random_below (r, ncand);

  /* A corner that only continues a neighbour is left out (FLT_MAX). A
   * sum is cut short once it passes the tolerance around the thread's
   * best so far: the best of all is no larger, so such a corner could
   * not be picked either, and the pick is the same as with whole sums. */
#pragma omp parallel
  {
    float mine = FLT_MAX;
#pragma omp for schedule(static)
    for (ptrdiff_t c = 0; c < (ptrdiff_t) ncand; c++)
      {
        size_t cx = (size_t) c % g->cand_w, cy = (size_t) c / g->cand_w;
        if ((left && continues (cx, cy, left_corner, g->step, 0, g->overlap)) ||
            (top && continues (cx, cy, top_corner, 0, g->step, g->overlap)))
          {
            s->error[c] = FLT_MAX;
            continue;
          }
        s->error[c] = overlap_error (state, ox, oy, pw, ph, g->overlap, left, top, cx, cy,
                                     mine * (1.0f + (float) TS_QUILT_TOLERANCE));
        mine = s->error[c] < mine ? s->error[c] : mine;
      }
  }

  float best = FLT_MAX;
  for (size_t c = 0; c < ncand; c++)
    best = s->error[c] < best ? s->error[c] : best;
  if (best == FLT_MAX)
    return (size_t) ts_random_below (r, ncand);
  float limit = best * (1.0f + (float) TS_QUILT_TOLERANCE);
  uint32_t least = UINT32_MAX;
  size_t eligible = 0;
  for (size_t c = 0; c < ncand; c++)
    if (s->error[c] <= limit && s->usage[c] < least)
      least = s->usage[c];
  for (size_t c = 0; c < ncand; c++)
    eligible += s->error[c] <= limit && s->usage[c] == least;
  size_t pick = (size_t) ts_random_below (r, eligible);
  for (size_t c = 0; c < ncand; c++)
    if (s->error[c] <= limit && s->usage[c] == least && pick-- == 0)
      return c;
  return (size_t) ts_random_below (r, ncand);
}

/* Whether the canvas patch at (ox, oy), pw x ph, covers a pixel of
 * `active` (a mask of the level, `shift` pixels right of and below the
 * canvas's corner), or there is no mask. */
static bool
patch_active (const TsLevelState *level_state, size_t shift, size_t ox, size_t oy, size_t pw,
              size_t ph)
{
  if (!level_state->active)
    return true;
  if (ox + pw <= shift || oy + ph <= shift)
    return false;
  return ts_active_any (level_state->active, level_state->width, level_state->height,
                        ox > shift ? ox - shift : 0, oy > shift ? oy - shift : 0,
                        ox + pw - shift, oy + ph - shift);
}

/* Lays the quilt over the whole of `state` (its sources). Patches that
 * cover no active pixel of `level_state` are laid at a seeded corner
 * without matching: nothing needed is near them. */
static TsStatus
quilt (TsLevelState *state, uint32_t seed, uint32_t level, const TsLevelState *level_state,
       size_t shift)
{
  const TsImage *ex = state->exemplar;
  Layout g;
  Scratch s = { 0 };
  int32_t *corner;
  TsStatus status = TS_OK;

  layout_patches (ex, &g);
  g.cand_w = ex->width - g.patch + 1;
  g.cand_h = ex->height - g.patch + 1;
  g.cols = patches_along (state->width, &g);
  g.rows = patches_along (state->height, &g);

  corner = malloc (g.cols * g.rows * 2 * sizeof (int32_t));
  s.error = malloc (g.cand_w * g.cand_h * sizeof (float));
  s.cost = malloc (g.patch * g.patch * sizeof (float));
  s.path = malloc (g.patch * sizeof (size_t));
  s.keep = malloc (g.patch * g.patch * sizeof (bool));
  s.usage = calloc (g.cand_w * g.cand_h, sizeof (uint32_t));
  if (!corner || !s.error || !s.cost || !s.path || !s.keep || !s.usage)
    status = TS_ERROR_OUT_OF_MEMORY;

  for (size_t i = 0; i < g.rows && status == TS_OK; i++)
    {
      if (ts_cancel_poll (state->cancel))
        {
          status = TS_ERROR_CANCELLED;
          break;
        }
      for (size_t j = 0; j < g.cols; j++)
        {
          uint64_t r = ts_random (seed, level, 0, i * g.cols + j, 6);
          size_t ox = j * g.step, oy = i * g.step;
          size_t pw = state->width - ox < g.patch ? state->width - ox : g.patch;
          size_t ph = state->height - oy < g.patch ? state->height - oy : g.patch;
          bool matched = patch_active (level_state, shift, ox, oy, pw, ph);
          size_t c = matched ? choose_corner (state, &g, &s, corner, i, j, r)
                             : (size_t) ts_random_below (r, g.cand_w * g.cand_h);
          size_t cx = c % g.cand_w, cy = c / g.cand_w;

          for (size_t uy = cy > g.overlap ? cy - g.overlap : 0; matched && uy <= cy + g.overlap && uy < g.cand_h; uy++)
            for (size_t ux = cx > g.overlap ? cx - g.overlap : 0; ux <= cx + g.overlap && ux < g.cand_w; ux++)
              s.usage[uy * g.cand_w + ux]++;
          corner[2 * (i * g.cols + j)] = (int32_t) cx;
          corner[2 * (i * g.cols + j) + 1] = (int32_t) cy;
          cut_overlaps (state, &g, &s, ox, oy, pw, ph, matched && j > 0, matched && i > 0, cx, cy);
          for (size_t y = 0; y < ph; y++)
            for (size_t x = 0; x < pw; x++)
              if (!s.keep[y * pw + x])
                state->source[(oy + y) * state->width + ox + x] =
                  (int32_t) ((cy + y) * ex->width + cx + x);
        }
    }

  free (corner);
  free (s.error);
  free (s.cost);
  free (s.path);
  free (s.keep);
  free (s.usage);
  return status;
}

/* The first row and column of patches are matched on one side only: an
 * oriented texture then stacks one strip of the exemplar all down the
 * column (or along the row), a visible repeat. So the quilt is laid from
 * one patch step above and left of the output, and those are cut off. */
TsStatus
ts_quilt_start (TsLevelState *state, uint32_t seed, uint32_t level)
{
  const TsImage *ex = state->exemplar;
  TsLevelState canvas = *state;
  TsStatus status;
  Layout g;
  size_t margin;

  layout_patches (ex, &g);
  margin = g.step;
  canvas.width = state->width + margin;
  canvas.height = state->height + margin;
  canvas.active = canvas.active_centres = NULL;
  canvas.source = malloc (canvas.width * canvas.height * sizeof (int32_t));
  if (!canvas.source)
    return TS_ERROR_OUT_OF_MEMORY;
  status = quilt (&canvas, seed, level, state, margin);
  for (size_t y = 0; status == TS_OK && y < state->height; y++)
    memcpy (state->source + y * state->width, canvas.source + (y + margin) * canvas.width + margin,
            state->width * sizeof (int32_t));
  free (canvas.source);

  /* Transparent exemplar pixels are never a start: a random opaque one. */
  for (size_t p = 0; status == TS_OK && p < state->width * state->height; p++)
    if (ex->pixels[(size_t) state->source[p] * TS_CHANNELS + 3] <= 0.0f)
      state->source[p] = state->opaque[ts_random_below (ts_random (seed, level, 0, p, 5),
                                                        state->opaque_count)];
  return status;
}
