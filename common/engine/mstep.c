/* M-step: k-coherence search of the best exemplar neighbourhood for each
 * output neighbourhood centre.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "clones.h"
#include "level.h"
#include "kcoherence.h"
#include "rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Kwatra et al.'s robust energy exponent. */
#define TS_ENERGY_EXPONENT 0.8f

static void
gather (const TsLevelState *state, ptrdiff_t cx, ptrdiff_t cy, size_t radius, float *out)
{
  const float *ex = state->exemplar->pixels;
  ptrdiff_t r = (ptrdiff_t) radius;

  if (cx >= r && cy >= r && cx + r < (ptrdiff_t) state->width && cy + r < (ptrdiff_t) state->height)
    {
      /* Inside: no border rule to apply. */
      for (ptrdiff_t dy = -r; dy <= r; dy++)
        {
          const int32_t *row = state->source + (size_t) (cy + dy) * state->width + (size_t) (cx - r);
          for (size_t i = 0; i < 2 * radius + 1; i++, out += TS_CHANNELS)
            memcpy (out, ex + (size_t) row[i] * TS_CHANNELS, TS_CHANNELS * sizeof (float));
        }
      return;
    }
  for (ptrdiff_t dy = -(ptrdiff_t) radius; dy <= (ptrdiff_t) radius; dy++)
    {
      const int32_t *row = state->source + ts_border_index (cy + dy, state->height, state->wrap_y)
                           * state->width;
      for (ptrdiff_t dx = -(ptrdiff_t) radius; dx <= (ptrdiff_t) radius; dx++)
        {
          size_t x = ts_border_index (cx + dx, state->width, state->wrap_x);
          memcpy (out, ex + (size_t) row[x] * TS_CHANNELS, TS_CHANNELS * sizeof (float));
          out += TS_CHANNELS;
        }
    }
}

/* True if every pixel of the neighbourhood is fully preserved: its match
 * could only vote for pixels that never change. */
static bool
frozen (const TsLevelState *state, ptrdiff_t cx, ptrdiff_t cy, size_t radius)
{
  for (ptrdiff_t dy = -(ptrdiff_t) radius; dy <= (ptrdiff_t) radius; dy++)
    {
      size_t y = ts_border_index (cy + dy, state->height, state->wrap_y);
      for (ptrdiff_t dx = -(ptrdiff_t) radius; dx <= (ptrdiff_t) radius; dx++)
        if (state->preserve[y * state->width + ts_border_index (cx + dx, state->width, state->wrap_x)] < 1.0f)
          return false;
    }
  return true;
}

/* What the proposals of one M-step read instead of dividing exemplar
 * indices: each exemplar pixel's coordinates, and its first k_use
 * k-coherence candidates as centres already clamped for this patch. */
typedef struct
{
  int32_t       *x, *y;
  int32_t       *lists;   /* k entries per exemplar pixel, -1 after the last */
  size_t         k;
  uint8_t       *clipped; /* per pixel: 1 if its window crosses the border;
                             NULL when every centre keeps its window inside */
} Proposals;

static void
proposals_free (Proposals *p)
{
  free (p->x);
  free (p->y);
  free (p->lists);
  free (p->clipped);
}

static TsStatus
proposals_init (Proposals *p, const TsImage *ex, const TsCandidateSet *cands, size_t k_use,
                size_t radius, size_t margin)
{
  size_t w = ex->width, h = ex->height, n = w * h;

  p->k = k_use < cands->k ? k_use : cands->k;
  p->x = malloc (n * sizeof (int32_t));
  p->y = malloc (n * sizeof (int32_t));
  p->lists = malloc ((n * p->k > 0 ? n * p->k : 1) * sizeof (int32_t));
  p->clipped = margin < radius ? malloc (n) : NULL;
  if (!p->x || !p->y || !p->lists || (margin < radius && !p->clipped))
    {
      proposals_free (p);
      return TS_ERROR_OUT_OF_MEMORY;
    }
#pragma omp parallel for schedule(static) if (n * p->k >= 65536)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) n; i++)
    {
      const int32_t *list = cands->index + (size_t) i * cands->k;
      int32_t *out = p->lists + (size_t) i * p->k;
      size_t j = 0;

      size_t x = (size_t) i % w, y = (size_t) i / w;
      p->x[i] = (int32_t) x;
      p->y[i] = (int32_t) y;
      if (p->clipped)
        p->clipped[i] = x < radius || y < radius || x + radius >= w || y + radius >= h;
      for (; j < p->k && list[j] >= 0; j++)
        {
          size_t qx = ts_clamp_centre ((ptrdiff_t) ((size_t) list[j] % w), w, margin);
          size_t qy = ts_clamp_centre ((ptrdiff_t) ((size_t) list[j] / w), h, margin);
          out[j] = (int32_t) (qy * w + qx);
        }
      for (; j < p->k; j++)
        out[j] = -1;
    }
  return TS_OK;
}

/* The exemplar with a margin of `pad` pixels mirrored around it, where
 * windows that cross its border read their outside part. */
static float *
mirror_padded (const TsImage *ex, size_t pad)
{
  size_t w = ex->width, h = ex->height, stride = w + 2 * pad;
  float *out = malloc (stride * (h + 2 * pad) * TS_CHANNELS * sizeof (float));

  if (!out)
    return NULL;
#pragma omp parallel for schedule(static) if (w * h >= 65536)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) (h + 2 * pad); y++)
    {
      const float *row = ex->pixels + ts_mirror (y - (ptrdiff_t) pad, h) * w * TS_CHANNELS;
      float *dst = out + (size_t) y * stride * TS_CHANNELS;
      for (size_t x = 0; x < stride; x++)
        memcpy (dst + x * TS_CHANNELS, row + ts_mirror ((ptrdiff_t) x - (ptrdiff_t) pad, w) * TS_CHANNELS,
                TS_CHANNELS * sizeof (float));
    }
  return out;
}

/* The exemplar pixel `source`, shifted by (-dx, -dy), as a proposed
 * centre, and the k-coherence candidates of that position. */
TS_CLONE_INLINE void
propose (TsSearch *s, const Proposals *p, int32_t source, ptrdiff_t dx, ptrdiff_t dy)
{
  size_t w = s->exemplar->width, h = s->exemplar->height;
  ptrdiff_t cx = p->x[source] - dx, cy = p->y[source] - dy;
  size_t lx = cx < 0 ? 0 : (cx >= (ptrdiff_t) w ? w - 1 : (size_t) cx);
  size_t ly = cy < 0 ? 0 : (cy >= (ptrdiff_t) h ? h - 1 : (size_t) cy);
  const int32_t *list = p->lists + (ly * w + lx) * p->k;

  ts_search_consider_centre (s, ts_clamp_centre (cy, h, s->margin) * w
                                + ts_clamp_centre (cx, w, s->margin));
  for (size_t i = 0; i < p->k && list[i] >= 0; i++)
    ts_search_consider_centre (s, (size_t) list[i]);
}

/* propose, unless this search has had the same proposal: in a coherent
 * region all neighbours propose one centre, and a repeat would consider
 * the same candidates in the same order, every one already seen.
 * `proposed` holds the visit of each exemplar pixel's last proposal
 * (cleared with the stamps when the visit counter wraps). */
TS_CLONE_INLINE void
propose_once (TsSearch *s, uint32_t *proposed, const Proposals *p, int32_t source,
              ptrdiff_t dx, ptrdiff_t dy)
{
  size_t w = s->exemplar->width, h = s->exemplar->height;
  ptrdiff_t cx = p->x[source] - dx, cy = p->y[source] - dy;

  if (cx >= 0 && cy >= 0 && cx < (ptrdiff_t) w && cy < (ptrdiff_t) h)
    {
      uint32_t *mark = proposed + (size_t) cy * w + (size_t) cx;
      if (*mark == s->visit)
        return;
      *mark = s->visit;
    }
  propose (s, p, source, dx, dy);
}

TS_VECTOR_CLONES static void
search_centre (TsSearch *s, uint32_t *proposed, const Proposals *p, const TsLevelState *state,
               const TsPass *pass, uint32_t seed_stream, ptrdiff_t cx, ptrdiff_t cy,
               size_t centre_index)
{
  ptrdiff_t r = (ptrdiff_t) s->radius, step = (ptrdiff_t) pass->propose_step;
  ptrdiff_t first = -(r / step) * step;
  size_t own = (size_t) cy * state->width + (size_t) cx;
  /* Away from the borders the neighbours need no border rule. */
  bool inside = cx >= r && cy >= r && cx + r < (ptrdiff_t) state->width
                && cy + r < (ptrdiff_t) state->height;

  /* The centre's own source first: usually the best, so the early abort
   * of every later candidate has a tight bound. */
  if (state->source[own] >= 0)
    propose_once (s, proposed, p, state->source[own], 0, 0);
  for (ptrdiff_t dy = first; dy <= r; dy += step)
    {
      size_t y = inside ? (size_t) (cy + dy) : ts_border_index (cy + dy, state->height, state->wrap_y);
      const int32_t *row = state->source + y * state->width;
      for (ptrdiff_t dx = first; dx <= r; dx += step)
        {
          size_t x = inside ? (size_t) (cx + dx) : ts_border_index (cx + dx, state->width, state->wrap_x);
          int32_t source = row[x];
          if (source >= 0)
            propose_once (s, proposed, p, source, dx, dy);
        }
    }
  if (state->preserve_source)
    propose (s, p, state->preserve_source[own], 0, 0);
  if (s->best_centre < 0)
    {
      /* Nothing usable around (transparent sources): a random opaque
       * pixel keeps the search going. */
      uint64_t r64 = ts_random (seed_stream, 0, 0, centre_index, 7);
      int32_t q = state->opaque[ts_random_below (r64, state->opaque_count)];
      ts_search_consider (s, p->x[q], p->y[q]);
    }
}

/* A few random exemplar pixels (g->proposals) whose guide matches the
 * target's at the centre, and their k-coherence candidates. */
static void
propose_by_guide (TsSearch *s, const Proposals *p, const TsLevelState *state,
                  uint32_t seed_stream, ptrdiff_t cx, ptrdiff_t cy, size_t centre_index)
{
  const TsGuideLevel *g = state->guide;
  size_t bin = ts_guide_target_bin (g, (size_t) cx, (size_t) cy);
  size_t first = g->bin_start[bin], members = g->bin_start[bin + 1] - first;

  for (uint32_t i = 0; i < (uint32_t) g->proposals; i++)
    {
      uint64_t r = ts_random (seed_stream, 0, i, centre_index, 8);
      propose (s, p, g->bin_member[first + ts_random_below (r, members)], 0, 0);
    }
}

TsStatus
ts_mstep (const TsLevelState *state, const TsAxisGrid *gx, const TsAxisGrid *gy,
          const TsPass *pass, size_t k_use, uint32_t seed_stream, TsMatch *matches)
{
  const TsImage *ex = state->exemplar;
  size_t radius = pass->patch / 2, count = gx->centres * gy->centres;
  size_t ex_pixels = ts_image_pixel_count (ex);
  float pixels_per_patch = (float) (pass->patch * pass->patch);
  int failed = 0;
  Proposals proposals;

  /* Centres anywhere in the exemplar, the part of a window outside it
   * compared with the exemplar mirrored, and votes only from the part
   * inside: with whole windows only, the exemplar's border band is only
   * ever copied as the rim of a window and is used far below its share
   * (completeness and variety suffer most on small exemplars). Guided
   * levels keep whole windows: a label or value guide is compared window
   * by window, and under a lattice guide clipped windows broke the
   * courses (docs/benchmarks.md, "Windows over the exemplar's border"). */
  size_t margin = state->guide ? radius : 0;
  float *mirrored = margin < radius ? mirror_padded (ex, radius) : NULL;

  if ((margin < radius && !mirrored)
      || proposals_init (&proposals, ex, state->candidates, k_use, radius, margin) != TS_OK)
    {
      free (mirrored);
      return TS_ERROR_OUT_OF_MEMORY;
    }
#pragma omp parallel
  {
    TsSearch s = { .exemplar = ex, .patch = pass->patch, .radius = radius,
                   .penalty = state->penalty, .best_centre = -1,
                   .clipped = proposals.clipped, .mirrored = mirrored,
                   .margin = margin };
    float *neighbourhood = malloc (pass->patch * pass->patch * TS_CHANNELS * sizeof (float));
    s.stamp = calloc (ex_pixels, sizeof (uint32_t));
    uint32_t *proposed = calloc (ex_pixels, sizeof (uint32_t));
    TsGuideQuery guide_query = { 0 };
    s.neighbourhood = neighbourhood;
    if (state->guide && ts_guide_query_init (&guide_query, state->guide, pass->patch) == TS_OK)
      s.guide = &guide_query;
    if (!neighbourhood || !s.stamp || !proposed || (state->guide && !s.guide))
      {
#pragma omp atomic write
        failed = 1;
      }

#pragma omp for schedule(dynamic, 8)
    for (ptrdiff_t i = 0; i < (ptrdiff_t) count; i++)
      {
        int stop;
#pragma omp atomic read
        stop = failed;
        /* The clock is read at the start of each chunk of 8 centres
         * only: read per centre it cost thread 0 a few percent. */
        if (stop || (i % 8 == 0 ? ts_cancel_poll (state->cancel)
                                : ts_cancel_requested (state->cancel)))
          continue;
        size_t jx = (size_t) i % gx->centres, jy = (size_t) i / gx->centres;
        ptrdiff_t cx = ts_axis_grid_centre (gx, jx), cy = ts_axis_grid_centre (gy, jy);

        if ((state->preserve && frozen (state, cx, cy, radius))
            || (state->active_centres
                && !state->active_centres[ts_border_index (cy, state->height, state->wrap_y) * state->width
                                          + ts_border_index (cx, state->width, state->wrap_x)]))
          {
            matches[i].centre = -1;
            matches[i].clipped = false;
            matches[i].weight = 0.0f;
            continue;
          }
        gather (state, cx, cy, radius, neighbourhood);
        if (s.visit == UINT32_MAX)   /* ts_search_begin wraps it to 0 */
          memset (proposed, 0, ex_pixels * sizeof (uint32_t));
        ts_search_begin (&s, ex_pixels);
        if (s.guide)
          ts_guide_query_gather (s.guide, cx, cy, state->wrap_x, state->wrap_y);
        /* A centre cut off an oversized coherent region may not keep
         * its offset: its own source counts as already tried. */
        if (ts_region_bound_is_cut (state->region_bound, (size_t) cy * state->width + (size_t) cx))
          s.stamp[state->source[(size_t) cy * state->width + (size_t) cx]] = s.visit;
        search_centre (&s, proposed, &proposals, state, pass, seed_stream, cx, cy, (size_t) i);
        if (s.guide)
          propose_by_guide (&s, &proposals, state, seed_stream, cx, cy, (size_t) i);
        matches[i].centre = s.best_centre;
        matches[i].clipped = s.clipped && s.best_centre >= 0 && s.clipped[s.best_centre];
        /* |x - z|^(r-2) on the per-pixel RMS distance; the epsilon bounds
         * the weight of perfect matches. */
        matches[i].weight = powf (s.best / pixels_per_patch + 1e-2f,
                                  (TS_ENERGY_EXPONENT - 2.0f) * 0.5f);
      }
    free (neighbourhood);
    free (s.stamp);
    free (proposed);
    ts_guide_query_free (&guide_query);
  }
  proposals_free (&proposals);
  free (mirrored);
  if (failed)
    return TS_ERROR_OUT_OF_MEMORY;
  return ts_cancel_requested (state->cancel) ? TS_ERROR_CANCELLED : TS_OK;
}
