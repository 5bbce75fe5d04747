/* Solid M-step: the best exemplar neighbourhood for the slice
 * neighbourhoods of one orientation, among the coherent ones and the
 * nearest of all (Kopf et al. 2007).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"
#include "engine/kcoherence.h"
#include "engine/rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Kwatra et al.'s robust energy exponent, as in 2D. */
#define TS_ENERGY_EXPONENT 0.8f

typedef struct
{
  const TsSolidLevel *level;
  int                 axis;
  size_t              stride_u, stride_v, stride_t;
} Plane;

static void
gather (const Plane *p, size_t t, ptrdiff_t cu, ptrdiff_t cv, size_t radius, float *out)
{
  const TsSolidLevel *level = p->level;
  size_t n = level->n;
  const float *slice = level->value + t * p->stride_t * TS_CHANNELS;

  for (ptrdiff_t dv = -(ptrdiff_t) radius; dv <= (ptrdiff_t) radius; dv++)
    {
      const float *row = slice + ts_border_index (cv + dv, n, level->periodic) * p->stride_v * TS_CHANNELS;
      for (ptrdiff_t du = -(ptrdiff_t) radius; du <= (ptrdiff_t) radius; du++)
        {
          const float *voxel = row + ts_border_index (cu + du, n, level->periodic) * p->stride_u * TS_CHANNELS;
          memcpy (out, voxel, TS_CHANNELS * sizeof (float));
          out += TS_CHANNELS;
        }
    }
}

/* The exemplar neighbourhood that continues `source` from (du, dv) away. */
static void
propose_coherent (TsSearch *s, int32_t source, ptrdiff_t du, ptrdiff_t dv)
{
  size_t w = s->exemplar->width;
  ts_search_consider (s, (ptrdiff_t) ((size_t) source % w) - du,
                      (ptrdiff_t) ((size_t) source / w) - dv);
}

static void
search_centre (TsSearch *s, const Plane *p, const TsPass *pass, size_t leaves,
               uint32_t seed_stream, size_t t, ptrdiff_t cu, ptrdiff_t cv, size_t centre_index)
{
  const TsSolidLevel *level = p->level;
  const TsSolidView *view = &level->view[p->axis];
  const int32_t *source = level->source[p->axis];
  size_t n = level->n;
  ptrdiff_t r = (ptrdiff_t) s->radius, step = (ptrdiff_t) pass->propose_step;
  ptrdiff_t first = -(r / step) * step;
  size_t base = t * p->stride_t;

  /* The centre's own source first: a tight bound for the early abort. */
  propose_coherent (s, source[base + (size_t) cu * p->stride_u + (size_t) cv * p->stride_v], 0, 0);
  for (ptrdiff_t dv = first; dv <= r; dv += step)
    {
      size_t v = ts_border_index (cv + dv, n, level->periodic);
      for (ptrdiff_t du = first; du <= r; du += step)
        {
          size_t u = ts_border_index (cu + du, n, level->periodic);
          propose_coherent (s, source[base + u * p->stride_u + v * p->stride_v], du, dv);
        }
    }
  if (view->index && view->index->patch == pass->patch)
    {
      /* Any exemplar neighbourhood, not only those coherent with this
       * slice's sources: the slices across other axes then reshape what
       * this one would otherwise extrude. */
      float projected[TS_SOLID_INDEX_DIMS];
      int32_t found[TS_SOLID_INDEX_RESULTS];
      size_t w = view->exemplar->width;
      ts_solid_index_project (view->index, s->neighbourhood, projected);
      ts_solid_index_query (view->index, projected, leaves, found);
      for (size_t k = 0; k < TS_SOLID_INDEX_RESULTS && found[k] >= 0; k++)
        ts_search_consider (s, (ptrdiff_t) ((size_t) found[k] % w), (ptrdiff_t) ((size_t) found[k] / w));
    }
  if (s->best_centre < 0)
    {
      /* Only transparent sources around: a random opaque pixel. */
      uint64_t r64 = ts_random (seed_stream, (uint32_t) p->axis, 0, centre_index, 7);
      int32_t q = view->opaque[ts_random_below (r64, view->opaque_count)];
      propose_coherent (s, q, 0, 0);
    }
}

/* A match's error per pixel, for its vote's weight, scaled down where
 * the exemplar neighbourhood varies. Why: the E-step gives each voxel its
 * best-matched vote, and flat neighbourhoods (stone insides) always match
 * better than those across an edge; unscaled, they claimed the voxels of
 * every edge, each iteration at the finest level blunted the volume
 * further and the mortar thickened. */
static float
match_error (const TsSolidVarianceMap *map, int32_t centre, float ssd, float pixels)
{
  float error = ssd / pixels;
  if (centre >= 0 && map->variance)
    error *= map->flat / (map->variance[centre] + map->flat);
  return error;
}

TsStatus
ts_solid_mstep (const TsSolidLevel *level, int axis, const TsAxisGrid *gu, const TsAxisGrid *gv,
                const TsPass *pass, size_t leaves, size_t t_offset, uint32_t seed_stream,
                TsSolidMatch *matches, TsCancel *cancel)
{
  const TsImage *ex = level->view[axis].exemplar;
  size_t n = level->n, cu = gu->centres, cv = gv->centres;
  size_t radius = pass->patch / 2, count = ts_solid_match_slices (n) * cu * cv;
  size_t ex_pixels = ts_image_pixel_count (ex);
  float pixels_per_patch = (float) (pass->patch * pass->patch);
  Plane plane = { level, axis, 0, 0, 0 };
  int failed = 0, u_axis, v_axis;

  ts_solid_plane_axes (axis, &u_axis, &v_axis);
  plane.stride_u = ts_solid_stride (n, u_axis);
  plane.stride_v = ts_solid_stride (n, v_axis);
  plane.stride_t = ts_solid_stride (n, axis);

#pragma omp parallel if (n >= TS_SOLID_PARALLEL_EDGE)
  {
    TsSearch s = { .exemplar = ex, .patch = pass->patch, .radius = radius, .best_centre = -1,
                   .margin = radius };
    float *neighbourhood = malloc (pass->patch * pass->patch * TS_CHANNELS * sizeof (float));
    s.stamp = calloc (ex_pixels, sizeof (uint32_t));
    s.neighbourhood = neighbourhood;
    if (!neighbourhood || !s.stamp)
      {
#pragma omp atomic write
        failed = 1;
      }

#pragma omp for schedule(dynamic, 64)
    for (ptrdiff_t i = 0; i < (ptrdiff_t) count; i++)
      {
        int stop;
        size_t t, ju, jv;
#pragma omp atomic read
        stop = failed;
        if (stop || ts_cancel_poll (cancel))
          continue;
        /* Inverse of ts_solid_match_index. */
        ju = (size_t) i % cu;
        jv = ((size_t) i / cu) % cv;
        t = (size_t) i / cu / cv * TS_SOLID_SLICE_SPACING + t_offset % TS_SOLID_SLICE_SPACING;
        if (t >= n)
          {
            matches[i].centre = -1;
            matches[i].weight = 0.0f;
            continue;
          }
        ptrdiff_t pu = ts_axis_grid_centre (gu, ju), pv = ts_axis_grid_centre (gv, jv);

        gather (&plane, t, pu, pv, radius, neighbourhood);
        ts_search_begin (&s, ex_pixels);
        search_centre (&s, &plane, pass, leaves, seed_stream, t, pu, pv, (size_t) i);
        matches[i].centre = s.best_centre;
        matches[i].weight = powf (match_error (level->view[axis].variance, s.best_centre, s.best, pixels_per_patch)
                                  + 1e-2f, (TS_ENERGY_EXPONENT - 2.0f) * 0.5f);
      }
    free (neighbourhood);
    free (s.stamp);
  }
  if (failed)
    return TS_ERROR_OUT_OF_MEMORY;
  return ts_cancel_requested (cancel) ? TS_ERROR_CANCELLED : TS_OK;
}
