/* E-step: robust voting of the matched neighbourhoods, keeping the vote
 * closest to the weighted mean or the source with the most vote weight
 * (sharp output, exact source coordinates).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "clones.h"
#include "level.h"

#include <math.h>
#include <string.h>

/* Votes are kept in a local list so the second pass (nearest to the mean)
 * need not gather them again; only degenerate cases (tiny mirrored outputs
 * with huge neighbourhoods) overflow it and fall back to gathering twice. */
#define TS_LOCAL_VOTES 256

typedef struct
{
  float   sum[TS_CHANNELS];
  float   weight;
  float   best_distance;
  float   mean[TS_CHANNELS];
  int32_t best_source;
  bool    choosing;   /* second pass: pick the vote closest to the mean */
  bool    overflow;   /* more votes than the list holds                 */
  size_t  count;
  /* The listed votes' sources and values, one array per channel, so
   * that their distances to the mean are computed side by side. */
  int32_t source[TS_LOCAL_VOTES];
  float   value[TS_CHANNELS][TS_LOCAL_VOTES];
  float   vote_weight[TS_LOCAL_VOTES];
} Votes;

static void
votes_reset (Votes *v)
{
  memset (v->sum, 0, sizeof v->sum);
  v->weight = 0.0f;
  v->choosing = false;
  v->overflow = false;
  v->count = 0;
}

static inline float
distance_to_mean (const Votes *v, float v0, float v1, float v2, float v3)
{
  float e0 = v0 - v->mean[0], e1 = v1 - v->mean[1], e2 = v2 - v->mean[2], e3 = v3 - v->mean[3];
  return ((e0 * e0 + e1 * e1) + e2 * e2) + e3 * e3;
}

static void
choose (Votes *v, const float *value, int32_t source)
{
  float d = distance_to_mean (v, value[0], value[1], value[2], value[3]);
  if (d < v->best_distance)
    {
      v->best_distance = d;
      v->best_source = source;
    }
}

/* The listed vote nearest the mean, the first of equals (as `choose`
 * one by one would find it): all distances first, then their minimum. */
TS_CLONE_INLINE void
choose_listed (Votes *v)
{
  float d[TS_LOCAL_VOTES], least = INFINITY;

  for (size_t i = 0; i < v->count; i++)
    d[i] = distance_to_mean (v, v->value[0][i], v->value[1][i], v->value[2][i], v->value[3][i]);
  for (size_t i = 0; i < v->count; i++)
    least = d[i] < least ? d[i] : least;
  if (!(least < v->best_distance))
    return;
  for (size_t i = 0; i < v->count; i++)
    if (d[i] == least)
      {
        v->best_distance = least;
        v->best_source = v->source[i];
        return;
      }
}

/* Slots of the table that sums each source's votes: a power of two at
 * least twice the votes a pixel usually has, so probes stay short. */
#define TS_CONSENSUS_SLOTS 64

/* The listed source with the most vote weight, the first listed of
 * equals: the copy the covering neighbourhoods agree on. Each source's
 * weights add up in list order, in a small hash table (more votes than
 * half its slots fall back to comparing the list with itself). */
static void
choose_consensus (Votes *v)
{
  int32_t key[TS_CONSENSUS_SLOTS];
  float sum[TS_CONSENSUS_SLOTS];
  uint16_t listed[TS_CONSENSUS_SLOTS];
  float most = -1.0f, first = 0.0f;
  size_t winner = 0;

  /* Most often the first listed source holds a clear majority (with
   * margin for the sums' rounding): then it has the most. */
  for (size_t i = 0; i < v->count; i++)
    if (v->source[i] == v->source[0])
      first += v->vote_weight[i];
  if (v->count > 0 && first > 0.5001f * v->weight)
    most = first;
  else if (v->count <= TS_CONSENSUS_SLOTS / 2)
    {
      for (size_t s = 0; s < TS_CONSENSUS_SLOTS; s++)
        key[s] = -1;
      for (size_t i = 0; i < v->count; i++)
        {
          uint32_t h = ((uint32_t) v->source[i] * 2654435761u) >> 26;
          while (key[h] >= 0 && key[h] != v->source[i])
            h = (h + 1) & (TS_CONSENSUS_SLOTS - 1);
          if (key[h] < 0)
            {
              key[h] = v->source[i];
              sum[h] = 0.0f;
              listed[h] = (uint16_t) i;
            }
          sum[h] += v->vote_weight[i];
        }
      for (size_t s = 0; s < TS_CONSENSUS_SLOTS; s++)
        if (key[s] >= 0 && (sum[s] > most || (sum[s] == most && listed[s] < winner)))
          {
            most = sum[s];
            winner = listed[s];
          }
    }
  else
    for (size_t i = 0; i < v->count; i++)
      {
        size_t j = 0;
        float total = 0.0f;
        while (j < i && v->source[j] != v->source[i])
          j++;
        if (j < i)
          continue;   /* counted at its first listing */
        for (; j < v->count; j++)
          if (v->source[j] == v->source[i])
            total += v->vote_weight[j];
        if (total > most)
          {
            most = total;
            winner = i;
          }
      }
  if (most < 0.0f)
    return;
  v->best_source = v->source[winner];
  v->best_distance = distance_to_mean (v, v->value[0][winner], v->value[1][winner],
                                       v->value[2][winner], v->value[3][winner]);
}

/* Appends a vote to the list, or notes that it is full. */
static inline void
list_vote (Votes *v, size_t *count, bool *overflow, int32_t source, const float *value,
           float weight)
{
  size_t i = *count;
  if (i < TS_LOCAL_VOTES)
    {
      v->source[i] = source;
      v->vote_weight[i] = weight;
      for (int c = 0; c < TS_CHANNELS; c++)
        v->value[c][i] = value[c];
      *count = i + 1;
    }
  else
    *overflow = true;
}

/* `any_alpha`: count a transparent value too (the data term, so that
 * preserved transparent pixels stay transparent); matched neighbourhoods
 * never vote for transparency. */
static void
add_vote (Votes *v, const TsImage *ex, int32_t source, float weight, bool any_alpha)
{
  const float *value = ex->pixels + (size_t) source * TS_CHANNELS;

  if ((value[3] <= 0.0f && !any_alpha) || !(weight > 0.0f))
    return;
  if (v->choosing)
    {
      choose (v, value, source);
      return;
    }
  for (int c = 0; c < TS_CHANNELS; c++)
    v->sum[c] += weight * value[c];
  v->weight += weight;
  list_vote (v, &v->count, &v->overflow, source, value, weight);
}

/* Every vote of the matched neighbourhoods covering (px, py), in a fixed
 * order. First pass: weighted sums, kept in locals so they stay in
 * registers (the same additions in the same order as one by one); second
 * pass (`choosing`, only when the list overflowed): the vote nearest the
 * mean. */
TS_CLONE_INLINE void
collect_pass (Votes *v, const TsLevelState *state, const TsAxisGrid *gx, const TsAxisGrid *gy,
              const TsMatch *matches, const TsHistogram *histogram, size_t px, size_t py,
              bool choosing)
{
  const TsImage *ex = state->exemplar;
  size_t ew = ex->width, count = v->count;
  float s0 = v->sum[0], s1 = v->sum[1], s2 = v->sum[2], s3 = v->sum[3], total = v->weight;
  bool overflow = v->overflow;

  for (size_t vy = gy->virtual_start[py]; vy < gy->virtual_start[py + 1]; vy++)
    {
      ptrdiff_t ty = gy->virtual_coord[vy];
      size_t jy_lo = gy->cover_lo[vy], jy_hi = gy->cover_hi[vy];
      for (size_t vx = gx->virtual_start[px]; vx < gx->virtual_start[px + 1]; vx++)
        {
          ptrdiff_t tx = gx->virtual_coord[vx];
          size_t jx_lo = gx->cover_lo[vx], jx_hi = gx->cover_hi[vx];
          for (size_t jy = jy_lo; jy <= jy_hi; jy++)
            {
              ptrdiff_t dy = ty - ts_axis_grid_centre (gy, jy);
              const TsMatch *row = matches + jy * gx->centres;
              for (size_t jx = jx_lo; jx <= jx_hi; jx++)
                {
                  if (row[jx].centre < 0)
                    continue;
                  ptrdiff_t dx = tx - ts_axis_grid_centre (gx, jx);
                  if (!ts_match_reaches (&row[jx], ew, ex->height, dx, dy))
                    continue;
                  int32_t source = row[jx].centre + (int32_t) (dy * (ptrdiff_t) ew + dx);
                  const float *value = ex->pixels + (size_t) source * TS_CHANNELS;
                  float weight = row[jx].weight;
                  if (histogram)
                    weight *= histogram->factor[source];
                  if (state->guide)
                    weight *= ts_guide_vote_factor (state->guide, py * state->width + px, source);
                  /* Matched neighbourhoods never vote for transparency. */
                  if (value[3] <= 0.0f || !(weight > 0.0f))
                    continue;
                  if (choosing)
                    {
                      choose (v, value, source);
                      continue;
                    }
                  s0 += weight * value[0];
                  s1 += weight * value[1];
                  s2 += weight * value[2];
                  s3 += weight * value[3];
                  total += weight;
                  list_vote (v, &count, &overflow, source, value, weight);
                }
            }
        }
    }
  if (!choosing)
    {
      v->sum[0] = s0;
      v->sum[1] = s1;
      v->sum[2] = s2;
      v->sum[3] = s3;
      v->weight = total;
      v->count = count;
      v->overflow = overflow;
    }
}

/* How many matched neighbourhoods cover (px, py), transparent votes
 * included: an upper bound on its votes. */
TS_CLONE_INLINE size_t
cover_count (const TsAxisGrid *gx, const TsAxisGrid *gy, size_t px, size_t py)
{
  size_t across = 0, down = 0;

  for (size_t vx = gx->virtual_start[px]; vx < gx->virtual_start[px + 1]; vx++)
    across += gx->cover_lo[vx] <= gx->cover_hi[vx] ? gx->cover_hi[vx] - gx->cover_lo[vx] + 1 : 0;
  for (size_t vy = gy->virtual_start[py]; vy < gy->virtual_start[py + 1]; vy++)
    down += gy->cover_lo[vy] <= gy->cover_hi[vy] ? gy->cover_hi[vy] - gy->cover_lo[vy] + 1 : 0;
  return across * down;
}

/* The first pass when every vote fits the list: the votes are listed
 * first and summed after, in the same order as collect_pass adds them,
 * so the sums stay in registers instead of passing through memory at
 * every vote. */
TS_CLONE_INLINE void
collect_listed (Votes *v, const TsLevelState *state, const TsAxisGrid *gx, const TsAxisGrid *gy,
                const TsMatch *matches, const TsHistogram *histogram, size_t px, size_t py)
{
  const float *pixels = state->exemplar->pixels;
  const float *factor = histogram ? histogram->factor : NULL;
  const TsGuideLevel *guide = state->guide;
  ptrdiff_t ew = (ptrdiff_t) state->exemplar->width;
  size_t count = 0, p = py * state->width + px;
  float s0 = 0.0f, s1 = 0.0f, s2 = 0.0f, s3 = 0.0f, total = 0.0f;

  for (size_t vy = gy->virtual_start[py]; vy < gy->virtual_start[py + 1]; vy++)
    {
      ptrdiff_t ty = gy->virtual_coord[vy];
      size_t jy_lo = gy->cover_lo[vy], jy_hi = gy->cover_hi[vy];
      for (size_t vx = gx->virtual_start[px]; vx < gx->virtual_start[px + 1]; vx++)
        {
          ptrdiff_t tx = gx->virtual_coord[vx];
          size_t jx_lo = gx->cover_lo[vx], jx_hi = gx->cover_hi[vx];
          for (size_t jy = jy_lo; jy <= jy_hi; jy++)
            {
              ptrdiff_t shift = (ty - ts_axis_grid_centre (gy, jy)) * ew + tx;
              const TsMatch *row = matches + jy * gx->centres;
              for (size_t jx = jx_lo; jx <= jx_hi; jx++)
                {
                  if (row[jx].centre < 0
                      || !ts_match_reaches (&row[jx], (size_t) ew, state->exemplar->height,
                                            tx - ts_axis_grid_centre (gx, jx),
                                            ty - ts_axis_grid_centre (gy, jy)))
                    continue;
                  int32_t source = row[jx].centre + (int32_t) (shift - ts_axis_grid_centre (gx, jx));
                  const float *value = pixels + (size_t) source * TS_CHANNELS;
                  float weight = row[jx].weight;
                  if (factor)
                    weight *= factor[source];
                  if (guide)
                    weight *= ts_guide_vote_factor (guide, p, source);
                  if (value[3] <= 0.0f || !(weight > 0.0f))
                    continue;
                  v->source[count] = source;
                  v->vote_weight[count] = weight;
                  for (int c = 0; c < TS_CHANNELS; c++)
                    v->value[c][count] = value[c];
                  count++;
                }
            }
        }
    }
  for (size_t i = 0; i < count; i++)
    {
      float weight = v->vote_weight[i];
      s0 += weight * v->value[0][i];
      s1 += weight * v->value[1][i];
      s2 += weight * v->value[2][i];
      s3 += weight * v->value[3][i];
      total += weight;
    }
  v->sum[0] = s0;
  v->sum[1] = s1;
  v->sum[2] = s2;
  v->sum[3] = s3;
  v->weight = total;
  v->count = count;
}

TS_CLONE_INLINE void
collect (Votes *v, const TsLevelState *state, const TsAxisGrid *gx, const TsAxisGrid *gy,
         const TsMatch *matches, const TsHistogram *histogram, size_t px, size_t py)
{
  if (v->choosing)
    collect_pass (v, state, gx, gy, matches, histogram, px, py, true);
  else if (cover_count (gx, gy, px, py) <= TS_LOCAL_VOTES)
    collect_listed (v, state, gx, gy, matches, histogram, px, py);
  else
    collect_pass (v, state, gx, gy, matches, histogram, px, py, false);
}

/* Votes for every pixel of row y; returns how many changed source. */
TS_VECTOR_CLONES static size_t
vote_row (TsLevelState *state, const TsAxisGrid *gx, const TsAxisGrid *gy,
          const TsMatch *matches, const TsHistogram *histogram, size_t y)
{
  size_t changed = 0;

  for (size_t x = 0; x < state->width; x++)
    {
      size_t p = y * state->width + x;
      Votes v;
      float keep = 0.0f;

      /* Weight 1 keeps the pixel at its initial source (see start_sources). */
      if ((state->preserve && state->preserve[p] >= 1.0f) || (state->active && !state->active[p]))
        continue;
      votes_reset (&v);
      collect (&v, state, gx, gy, matches, histogram, x, y);
      if (state->preserve && state->preserve[p] > 0.0f)
        {
          /* Data term: the initial source votes with a share of the
           * total weight that grows without bound as preserve -> 1. */
          float w = state->preserve[p];
          keep = (v.weight > 0.0f ? v.weight : 1.0f) * w / (1.0f - w + 1e-4f);
          add_vote (&v, state->exemplar, state->preserve_source[p], keep, true);
        }
      if (!(v.weight > 0.0f))
        continue;
      for (int c = 0; c < TS_CHANNELS; c++)
        v.mean[c] = v.sum[c] / v.weight;
      v.choosing = true;
      v.best_distance = INFINITY;
      v.best_source = -1;
      /* An overflowing list (degenerate sizes) cannot count sources. */
      if (!v.overflow && state->consensus)
        choose_consensus (&v);
      else if (!v.overflow)
        choose_listed (&v);
      else
        {
          collect (&v, state, gx, gy, matches, histogram, x, y);
          if (keep > 0.0f)
            add_vote (&v, state->exemplar, state->preserve_source[p], keep, true);
        }
      if (v.best_source < 0)
        continue;
      if (state->disagreement)
        state->disagreement[p] = v.best_distance;
      if (v.best_source != state->source[p])
        changed++;
      state->source[p] = v.best_source;
    }
  return changed;
}

size_t
ts_estep (TsLevelState *state, const TsAxisGrid *gx, const TsAxisGrid *gy,
          const TsMatch *matches, const TsHistogram *histogram)
{
  size_t changed = 0;

  /* Dynamic rows: a thread the machine preempts holds up no barrier.
   * Each pixel is computed by one thread alone, so any order gives the
   * same result. A cancel is polled at the start of each row. */
#pragma omp parallel for schedule(dynamic, 4) reduction(+:changed)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) state->height; y++)
    if (!ts_cancel_poll (state->cancel))
      changed += vote_row (state, gx, gy, matches, histogram, (size_t) y);
  return changed;
}
