/* Solid E-step: each voxel becomes the vote, over the matched slice
 * neighbourhoods of all three orientations covering it, of the
 * best-matched neighbourhood, and each orientation's source follows its
 * own best-matched vote, so the next search stays coherent.
 *
 * No blending and no mode: a mean of the votes, or the vote nearest
 * their mode, is an in-between pixel wherever the orientations disagree,
 * and the volume loses the exemplar's fine grain and edges. Taking the
 * single best vote keeps whole exemplar neighbourhoods together:
 * neighbouring voxels covered by the same well-matched neighbourhood
 * copy its pixels.
 *
 * Inertia: a vote for the voxel's current value weighs TS_SOLID_INERTIA
 * times more. Winner-takes-all votes erode the structure a level starts
 * from (well-matched flat neighbourhoods claim the voxels of edges, so
 * spots merge and mortar thickens, iteration after iteration); with
 * inertia, the sharp start from the coarser level's winners
 * (start.c) survives unless a clearly better match replaces it.
 *
 * Continuation (the level's `continuation`, at the finest level): a vote
 * weighs 1 + continuation times more for each in-slice neighbour whose
 * value is the exemplar pixel next to the vote's source in the same
 * direction, i.e. for each neighbour whose copy the vote would continue.
 * Winner-takes-all votes otherwise flip between orientations and
 * neighbourhoods from voxel to voxel, and the volume fills with isolated
 * voxels: ragged, speckled mortar in cells, and axis-aligned gradient
 * energy around every lone voxel. Only neighbours outside the current
 * batch count: they do not change while it runs, so the result stays the
 * same at any thread count.
 *
 * Lone voxels (the level's `no_lone_voxels`, at the finest level): a
 * winning vote whose lightness phase (dark or light of the exemplar's
 * phase split, phase-split.c) is that of none of the voxel's six face
 * neighbours yields to the heaviest vote of the other phase. Such a voxel
 * is a sliver where two copies meet, a speck that solid textures do not
 * have, and sharpness counts it as edge. A voxel of a one-voxel sheet
 * or thread keeps same-phase neighbours and stays. At least
 * TS_SOLID_LONE_KNOWN neighbours outside
 * the current batch must say so. With the cell structure the joint split
 * (phase-split.c) makes a third class, the joints below it: a vote is
 * then lone if its side of either split is none of its neighbours', and
 * yields to the heaviest vote of a class that is not. Why: the guide's
 * joints end at the joint split, and with the rule at that split alone,
 * lone voxels of the dark stones between the splits stay. A light voxel
 * in a dark stone is often held by its one light face neighbour, so a
 * light voxel with five face neighbours below the phase split also
 * counts as lone; five, not four: at four, slices showed fewer light
 * sections than the exemplar has.
 *
 * Pieces kept apart (the level's `kept_apart`, at the finest level for
 * stones in mortar): a vote that would join two stones through a joint
 * voxel yields to the heaviest vote for a joint (piece-topology.c).
 * Stones and joints part at the joint split (phase-plan.c), and so does
 * the fallback: a vote merely below the phase split may be a dark
 * stone's pixel, which would join the stones just the same.
 *
 * Cell tones (the level's `cell_tone`, at the finest level with the
 * cell guide): a vote for an exemplar stone whose tone differs from the
 * voxel's cell's weighs less (cell-tone.c), so a cell copies stones of
 * one tone.
 *
 * Shear (the level's `shear`, at the finest levels, without the cell
 * structure, solid.h): a vote weighs 1 + shear times less for each of
 * the two neighbours across its slice that holds an exemplar pixel one
 * step from the vote's source (and not the source's own colour, which
 * flat stone insides share with every neighbour). Such a vote runs its
 * copy on into the next slice shifted by a pixel: V(x, y, z) =
 * E(x, y + z) is a perfect copy in every y and every z slice, so the
 * two orientations' near-perfect matches outweigh the poor ones of the x
 * slices, where it is a band of 45-degree streaks. Counting the
 * source's own pixel too (straight extrusion) would lower every vote
 * inside flat stones, and raised the specks.
 *
 * Histogram matching: Kopf et al.'s weight 1 / (1 + excess) lowers the
 * votes of over-represented colours, so a near-tie goes to the colour the
 * volume lacks.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <math.h>
#include <string.h>

/* Enough for a sharp start to hold against a flat neighbourhood that
 * matches about as well, small enough that a clearly better match
 * still wins (see the top of this file). Chosen on the truth solids. */
#define TS_SOLID_INERTIA 1.5f
/* Face neighbours outside the batch the lone-voxel rule needs: with all
 * six, 1 - (15/16)^6 = 32 % of the voxels would be exempt each batch. */
#define TS_SOLID_LONE_KNOWN 5

/* The lone-voxel rule's lightness classes (see the top of this file). */
enum
{
  LONE_JOINT, /* below the joint split: only with the cell structure */
  LONE_DARK,  /* below the phase split */
  LONE_LIGHT,
  LONE_CLASSES
};

static int
lightness_class (const TsSolidView *view, float lightness)
{
  return lightness < view->joint_split ? LONE_JOINT
         : lightness < view->phase_split ? LONE_DARK
                                         : LONE_LIGHT;
}

/* An in-slice neighbour of the voted voxel, outside the current batch,
 * that a vote may continue: its value and its step (dx, dy) in the
 * exemplar's axes. */
typedef struct
{
  const float *value;
  int          dx, dy;
} Neighbour;

typedef struct
{
  float        weight;
  int32_t      source;
  int          axis;
  float        axis_weight[TS_SOLID_AXES];
  int32_t      axis_source[TS_SOLID_AXES];
  const float *current;   /* the voxel's value before this E-step */
  size_t       xyz[3];    /* the voxel                            */
  const size_t *t_offset; /* of the orientations' searched slices */
  const uint8_t *batch_of;
  uint8_t      batch;
  const float *face[TS_SOLID_AXES][2]; /* see face_neighbours, if continuing,
                                          avoiding lone voxels or shears */
  bool         by_phase;  /* the level's no_lone_voxels: keep the
                             heaviest vote of each phase: */
  float        phase_weight[LONE_CLASSES];
  int32_t      phase_source[LONE_CLASSES];
  int          phase_axis[LONE_CLASSES];
  bool         by_ground; /* with the level's kept_apart, keep the
                             heaviest vote for the pieces' ground too
                             (at pieces_split, on the light side if
                             light_pieces is false): */
  float        ground_split;
  bool         light_pieces;
  float        ground_weight;
  int32_t      ground_source;
  int          ground_axis;
  float        tone;      /* the voxel's cell's tone, or NAN */
  float        phase;     /* the voxel's phase distance (phase-guide.c), or NAN */
  float        shear;     /* the level's shear */
} Votes;

/* Steps (dx, dy) to a pixel's four neighbours in the exemplar; a
 * voxel's in-slice face neighbours -u, +u, -v, +v map onto them in this
 * order (slice_neighbours). */
static const int slice_step[4][2] = { { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } };

/* Whether `value` is the exemplar pixel (dx, dy) from `source`; false
 * off the exemplar. */
static bool
next_to_source (const TsImage *ex, int32_t source, int dx, int dy, const float *value)
{
  ptrdiff_t w = (ptrdiff_t) ex->width, h = (ptrdiff_t) ex->height;
  ptrdiff_t x = source % w + dx, y = source / w + dy;

  return x >= 0 && y >= 0 && x < w && y < h
         && ts_solid_same_pixel (value, ex->pixels + (size_t) (y * w + x) * TS_CHANNELS);
}

/* How many of the voxel's two neighbours across the slice of `axis`
 * hold the exemplar pixel one step from `source`, and not its colour: the
 * shear rule's count (see the top of this file). */
static int
sheared (const Votes *v, const TsImage *ex, int axis, int32_t source)
{
  const float *own = ex->pixels + (size_t) source * TS_CHANNELS;
  int count = 0;

  for (int side = 0; side < 2; side++)
    {
      const float *across = v->face[axis][side];
      if (!across || ts_solid_same_pixel (across, own))
        continue;
      for (int k = 0; k < 4; k++)
        if (next_to_source (ex, source, slice_step[k][0], slice_step[k][1], across))
          {
            count++;
            break;
          }
    }
  return count;
}

/* Strictly heavier wins, so among equal weights the first vote in the
 * fixed collection order does: the same at any thread count. */
static void
add_vote (Votes *v, const TsSolidView *view, int axis, int32_t source, float weight)
{
  const float *value = view->exemplar->pixels + (size_t) source * TS_CHANNELS;

  if (view->excess)
    weight /= 1.0f + view->excess[source];
  if (value[3] <= 0.0f || !(weight > 0.0f))
    return;
  if (ts_solid_same_pixel (value, v->current))
    weight *= TS_SOLID_INERTIA;
  int phase = v->by_phase ? lightness_class (view, value[0]) : 0;
  bool ground = v->by_ground && ts_solid_is_light (value, v->ground_split) != v->light_pieces;
  /* The tone and the shear rule only lower a weight: skip their look-ups
   * for a vote that could not win anyway, as most cannot (the tone's cost
   * 2 s of 128^3). */
  if (weight <= v->weight && weight <= v->axis_weight[axis]
      && (!v->by_phase || weight <= v->phase_weight[phase])
      && (!ground || weight <= v->ground_weight))
    return;
  if (view->stone_tone && !isnan (v->tone))
    {
      float t = view->stone_tone[source];
      if (!isnan (t))
        {
          float z = (t - v->tone) / TS_SOLID_TONE_SPREAD;
          weight /= 1.0f + TS_SOLID_TONE_WEIGHT * z * z;
        }
    }
  if (v->shear > 0.0f)
    weight /= 1.0f + v->shear * (float) sheared (v, view->exemplar, axis, source);
  if (view->phase_distance && !isnan (v->phase))
    {
      float z = (view->phase_distance[source] - v->phase) / TS_SOLID_PHASE_SIGMA;
      weight /= 1.0f + z * z;
    }
  if (v->by_phase)
    {
      if (weight > v->phase_weight[phase])
        {
          v->phase_weight[phase] = weight;
          v->phase_source[phase] = source;
          v->phase_axis[phase] = axis;
        }
    }
  if (ground && weight > v->ground_weight)
    {
      v->ground_weight = weight;
      v->ground_source = source;
      v->ground_axis = axis;
    }
  if (weight > v->axis_weight[axis])
    {
      v->axis_weight[axis] = weight;
      v->axis_source[axis] = source;
    }
  if (weight > v->weight)
    {
      v->weight = weight;
      v->source = source;
      v->axis = axis;
    }
}

/* The voxel's six face neighbours, once per voxel (each orientation
 * uses four of them): their values, NULL for those in the current batch. */
static void
face_neighbours (const TsSolidLevel *level, Votes *v)
{
  for (int d = 0; d < TS_SOLID_AXES; d++)
    for (int side = 0; side < 2; side++)
      {
        size_t qi = ts_solid_face_neighbour (level, v->xyz, d, side);
        v->face[d][side] = v->batch_of[qi] == v->batch ? NULL : level->value + qi * TS_CHANNELS;
      }
}

/* The face neighbours in the slice across `axis`, with their steps in
 * the exemplar's axes; returns how many. */
static size_t
slice_neighbours (const Votes *v, int axis, Neighbour next[4])
{
  size_t count = 0;
  int u, w;

  ts_solid_plane_axes (axis, &u, &w);
  for (int k = 0; k < 4; k++)
    {
      const float *value = v->face[k < 2 ? u : w][k & 1];
      if (!value)
        continue;
      next[count].value = value;
      next[count].dx = slice_step[k][0];
      next[count].dy = slice_step[k][1];
      count++;
    }
  return count;
}

/* How many of the neighbours hold the exemplar pixel next to `source` in
 * their direction. */
static int
continued (const TsImage *ex, int32_t source, const Neighbour *next, size_t neighbours)
{
  int count = 0;

  for (size_t k = 0; k < neighbours; k++)
    count += next_to_source (ex, source, next[k].dx, next[k].dy, next[k].value);
  return count;
}

/* Votes of orientation `axis` for the voxel at in-slice (pu, pv) of slice t. */
static void
collect_axis (Votes *v, const TsSolidLevel *level, int axis, const TsAxisGrid *gu,
              const TsAxisGrid *gv, const TsSolidMatch *matches, size_t t, size_t pu, size_t pv)
{
  const TsSolidView *view = &level->view[axis];
  size_t ew = view->exemplar->width, cu = gu->centres, cv = gv->centres;
  Neighbour next[4];
  size_t neighbours = level->continuation > 0.0f ? slice_neighbours (v, axis, next) : 0;

  for (size_t iv = gv->virtual_start[pv]; iv < gv->virtual_start[pv + 1]; iv++)
    {
      ptrdiff_t tv = gv->virtual_coord[iv];
      size_t jv_lo, jv_hi;
      if (!ts_axis_grid_covering (gv, tv, &jv_lo, &jv_hi))
        continue;
      for (size_t iu = gu->virtual_start[pu]; iu < gu->virtual_start[pu + 1]; iu++)
        {
          ptrdiff_t tu = gu->virtual_coord[iu];
          size_t ju_lo, ju_hi;
          if (!ts_axis_grid_covering (gu, tu, &ju_lo, &ju_hi))
            continue;
          for (size_t jv = jv_lo; jv <= jv_hi; jv++)
            {
              ptrdiff_t dv = tv - ts_axis_grid_centre (gv, jv);
              for (size_t ju = ju_lo; ju <= ju_hi; ju++)
                {
                  const TsSolidMatch *m = &matches[ts_solid_match_index (cu, cv, t, ju, jv)];
                  if (m->centre < 0)
                    continue;
                  ptrdiff_t du = tu - ts_axis_grid_centre (gu, ju);
                  int32_t source = m->centre + (int32_t) (dv * (ptrdiff_t) ew + du);
                  float weight = m->weight;
                  if (neighbours)
                    weight *= 1.0f + level->continuation
                                     * (float) continued (view->exemplar, source, next, neighbours);
                  add_vote (v, view, axis, source, weight);
                }
            }
        }
    }
}

/* Votes of every orientation that searched the voxel's slice: the
 * others' matches there are all empty, so their loops are skipped. */
static void
collect (Votes *v, const TsSolidLevel *level, const TsAxisGrid *gu, const TsAxisGrid *gv,
         TsSolidMatch *const matches[TS_SOLID_AXES])
{
  const size_t *xyz = v->xyz;

  for (int axis = 0; axis < TS_SOLID_AXES; axis++)
    {
      int u, w;
      if (!level->view[axis].exemplar || !ts_solid_slice_searched (xyz[axis], v->t_offset[axis]))
        continue;
      ts_solid_plane_axes (axis, &u, &w);
      collect_axis (v, level, axis, gu, gv, matches[axis], xyz[axis], xyz[u], xyz[w]);
    }
}

/* Whether a voxel of lightness class c would be lone: on its side of
 * the joint or the phase split, none of its known face neighbours, and
 * at least TS_SOLID_LONE_KNOWN of them known. With the cell structure, a
 * light voxel with TS_SOLID_LONE_KNOWN neighbours below the phase split
 * (in dark stones or joints) is lone too: it pokes into them by a single
 * face, or is half of a two-voxel speck there (see the top of this
 * file). */
static bool
lone (const TsSolidView *view, const Votes *v, int c)
{
  int known = 0, by_joint = 0, by_phase = 0;

  for (int d = 0; d < TS_SOLID_AXES; d++)
    for (int side = 0; side < 2; side++)
      if (v->face[d][side])
        {
          float l = v->face[d][side][0];
          known++;
          by_joint += (l < view->joint_split) == (c == LONE_JOINT);
          by_phase += (l < view->phase_split) == (c != LONE_LIGHT);
        }
  /* For a light voxel, by_phase counts its light neighbours. */
  if (c == LONE_LIGHT && view->joint_split > -INFINITY
      && known - by_phase >= TS_SOLID_LONE_KNOWN)
    return true;
  return known >= TS_SOLID_LONE_KNOWN && (!by_joint || !by_phase);
}

/* The lone-voxel rule (see the top of this file). */
static void
avoid_lone_voxel (const TsSolidLevel *level, Votes *v)
{
  const TsSolidView *view = &level->view[v->axis];
  int c = lightness_class (view, view->exemplar->pixels[(size_t) v->source * TS_CHANNELS]);
  int best = -1;

  if (!lone (view, v, c))
    return;
  for (int k = 0; k < LONE_CLASSES; k++)
    if (k != c && v->phase_source[k] >= 0 && !lone (view, v, k)
        && (best < 0 || v->phase_weight[k] > v->phase_weight[best]))
      best = k;
  if (best < 0)
    return;
  v->source = v->phase_source[best];
  v->axis = v->phase_axis[best];
  v->weight = v->phase_weight[best];
}

/* The pieces kept apart (piece-topology.c): a winning vote that would
 * turn a voxel into a piece (at the level's pieces_split) and join two
 * of them yields to the heaviest vote for their ground (at the same
 * split: at the phase split it could still be a dark stone's pixel);
 * with none, the voxel stays. */
static void
keep_pieces_apart (const TsSolidLevel *level, Votes *v)
{
  float split = v->ground_split;
  const float *winner = level->view[v->axis].exemplar->pixels + (size_t) v->source * TS_CHANNELS;

  if (ts_solid_is_light (v->current, split) == v->light_pieces
      || ts_solid_is_light (winner, split) != v->light_pieces
      || !ts_solid_joins_pieces (level, v->xyz, v->batch_of, v->batch, split, v->light_pieces))
    return;
  v->source = v->ground_source;
  v->axis = v->ground_axis;
  v->weight = v->ground_weight;
}

/* New value and sources of voxel `p`; false if nothing voted for it. */
static bool
vote_voxel (const TsSolidLevel *level, const TsAxisGrid *gu, const TsAxisGrid *gv,
            TsSolidMatch *const matches[TS_SOLID_AXES], const size_t xyz[3], const float *current,
            Votes *v)
{
  v->current = current;
  memcpy (v->xyz, xyz, sizeof v->xyz);
  v->tone = level->cell_tone
              ? level->cell_tone[level->cell_of[(xyz[2] * level->n + xyz[1]) * level->n + xyz[0]]]
              : NAN;
  v->phase = level->phase_field ? level->phase_field[(xyz[2] * level->n + xyz[1]) * level->n + xyz[0]]
                                : NAN;
  if (ts_solid_reads_face_neighbours (level))
    face_neighbours (level, v);
  v->weight = 0.0f;
  v->source = -1;
  v->axis = 0;
  for (int a = 0; a < TS_SOLID_AXES; a++)
    {
      v->axis_weight[a] = 0.0f;
      v->axis_source[a] = -1;
    }
  for (int c = 0; c < LONE_CLASSES && v->by_phase; c++)
    {
      v->phase_weight[c] = 0.0f;
      v->phase_source[c] = -1;
      v->phase_axis[c] = 0;
    }
  v->ground_weight = 0.0f;
  v->ground_source = -1;
  v->ground_axis = 0;
  collect (v, level, gu, gv, matches);
  if (v->source >= 0 && v->by_phase)
    avoid_lone_voxel (level, v);
  if (v->source >= 0 && v->by_ground)
    keep_pieces_apart (level, v);
  return v->source >= 0;
}

/* In-batch voxels whose data are fetched ahead of their vote: enough
 * votes' work to cover a trip to memory, few enough that the fetched
 * lines are still cached when used. */
#define TS_SOLID_PREFETCH_AHEAD 4

size_t
ts_solid_estep (TsSolidLevel *level, const TsAxisGrid *gu, const TsAxisGrid *gv,
                TsSolidMatch *const matches[TS_SOLID_AXES], const size_t t_offset[TS_SOLID_AXES],
                const uint8_t *batch_of, uint8_t batch, const TsSolidHistogram *histogram,
                TsSolidHistogramDelta delta, TsCancel *cancel)
{
  size_t n = level->n, voxels = n * n * n, changed = 0;

#pragma omp parallel reduction(+:changed) if (n >= TS_SOLID_PARALLEL_EDGE)
  {
    TsSolidHistogramDelta local;
    Votes v;

    memset (local, 0, sizeof local);
    v.t_offset = t_offset;
    v.batch_of = batch_of;
    v.batch = batch;
    v.by_phase = level->no_lone_voxels;
    v.by_ground = level->no_lone_voxels && level->kept_apart != TS_SOLID_NO_PIECES;
    v.ground_split = level->pieces_split;
    v.light_pieces = level->kept_apart == TS_SOLID_LIGHT_PIECES;
    v.shear = level->shear;
    size_t ahead = 0, pending = 0; /* next voxel to prefetch; prefetched, not voted */
    /* A row's first voxel asks; after a stop the row is left. */
#pragma omp for schedule(static)
    for (ptrdiff_t zy = 0; zy < (ptrdiff_t) (n * n); zy++)
      for (size_t x = 0; x < n && !(x == 0 && ts_cancel_poll (cancel)); x++)
        {
          size_t p = (size_t) zy * n + x;
          size_t xyz[3] = { x, (size_t) zy % n, (size_t) zy / n };
          float *value = level->value + p * TS_CHANNELS;
          const float *chosen;

          if (batch_of[p] != batch)
            continue;
          if (p < ahead)
            pending--;
          else
            ahead = p + 1, pending = 0;
          for (; pending < TS_SOLID_PREFETCH_AHEAD && ahead < voxels; ahead++)
            if (batch_of[ahead] == batch)
              {
                ts_solid_prefetch_voxel (level, gu, gv, matches, t_offset, ahead);
                pending++;
              }
          if (!vote_voxel (level, gu, gv, matches, xyz, value, &v))
            continue;
          for (int a = 0; a < TS_SOLID_AXES; a++)
            if (level->source[a] && v.axis_source[a] >= 0)
              level->source[a][p] = v.axis_source[a];
          /* Also when the colour is unchanged: an equal colour may come
           * from another pixel, and aligned maps need the true one. */
          if (level->chosen)
            {
              TsSolidSource after = ts_solid_source_pack (v.axis, (uint32_t) v.source);
              if (level->position_weight > 0.0f && level->chosen[p] != after)
                ts_solid_position_move (level, level->chosen[p], after);
              level->chosen[p] = after;
            }
          chosen = level->view[v.axis].exemplar->pixels + (size_t) v.source * TS_CHANNELS;
          if (ts_solid_same_pixel (value, chosen))
            continue;
          changed++;
          if (histogram)
            ts_solid_histogram_move (histogram, local, value, chosen);
          memcpy (value, chosen, TS_CHANNELS * sizeof (float));
        }
#pragma omp critical (ts_solid_histogram_delta)
    for (int c = 0; c < 3; c++)
      for (size_t b = 0; b < TS_SOLID_HISTOGRAM_BINS; b++)
        delta[c][b] += local[c][b];
  }
  return changed;
}
