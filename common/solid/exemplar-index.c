/* PCA-projected exemplar neighbourhoods in a kd-tree. Built on one thread
 * in a fixed order, queried read-only: the same answers on any number of
 * threads.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "exemplar-index.h"
#include "engine/mrpm-feature.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Points per leaf: small enough to prune well, large enough to keep the
 * tree shallow. */
#define LEAF_POINTS 8
/* Nodes at least this large ask the cancel callback (its clock costs). */
#define POLL_POINTS 4096

void
ts_solid_index_free (TsSolidIndex *index)
{
  free (index->basis);
  free (index->centre);
  free (index->point);
  free (index->node);
  memset (index, 0, sizeof *index);
}

#if defined(__GNUC__)
typedef float Lanes __attribute__ ((vector_size (4 * sizeof (float))));

/* Four components per vector, each summed over the dimensions in order as
 * the plain loop does, so the bits are the same. Left to itself, GCC
 * vectorised across the dimensions instead and spent most of its time
 * transposing: the projection was 14 % of a 128^3 run. */
void
ts_solid_index_project (const TsSolidIndex *index, const float *neighbourhood,
                        float projected[TS_SOLID_INDEX_DIMS])
{
  enum { VECTORS = TS_SOLID_INDEX_DIMS / 4 };
  Lanes acc[VECTORS];

  memset (acc, 0, sizeof acc);
  for (size_t d = 0; d < index->dims; d++)
    {
      Lanes row[VECTORS];
      memcpy (row, index->basis + d * TS_SOLID_INDEX_DIMS, sizeof row);
      for (size_t j = 0; j < VECTORS; j++)
        acc[j] += neighbourhood[d] * row[j];
    }
  memcpy (projected, acc, sizeof acc);
}
#else
void
ts_solid_index_project (const TsSolidIndex *index, const float *neighbourhood,
                        float projected[TS_SOLID_INDEX_DIMS])
{
  float acc[TS_SOLID_INDEX_DIMS] = { 0 };
  for (size_t d = 0; d < index->dims; d++)
    {
      const float *row = index->basis + d * TS_SOLID_INDEX_DIMS;
      for (size_t j = 0; j < TS_SOLID_INDEX_DIMS; j++)
        acc[j] += neighbourhood[d] * row[j];
    }
  memcpy (projected, acc, sizeof acc);
}
#endif

static float
coordinate (const TsSolidIndex *index, const uint32_t *order, size_t i, uint32_t dim)
{
  return index->point[(size_t) order[i] * TS_SOLID_INDEX_DIMS + dim];
}

static void
swap (uint32_t *order, size_t a, size_t b)
{
  uint32_t t = order[a];
  order[a] = order[b];
  order[b] = t;
}

/* Puts the median along `dim` at `mid`, smaller before, larger after
 * (quickselect, three-way partitions around middle pivots:
 * deterministic). */
static void
select_median (const TsSolidIndex *index, uint32_t *order, size_t lo, size_t hi, size_t mid,
               uint32_t dim)
{
  while (hi - lo > 1)
    {
      float pivot = coordinate (index, order, lo + (hi - lo) / 2, dim);
      size_t lt = lo, i = lo, gt = hi;
      while (i < gt)
        {
          float c = coordinate (index, order, i, dim);
          if (c < pivot)
            swap (order, lt++, i++);
          else if (c > pivot)
            swap (order, i, --gt);
          else
            i++;
        }
      if (mid < lt)
        hi = lt;
      else if (mid >= gt)
        lo = gt;
      else
        return;
    }
}

/* Splits [begin, end) along its widest projected dimension; returns the
 * node. A cancel turns the nodes not yet split into leaves. */
static int32_t
build_node (TsSolidIndex *index, uint32_t *order, size_t begin, size_t end, TsCancel *cancel)
{
  int32_t id = (int32_t) index->nodes++;
  TsSolidIndexNode *node = &index->node[id];
  float lo[TS_SOLID_INDEX_DIMS], hi[TS_SOLID_INDEX_DIMS], widest = -1.0f;

  node->begin = (uint32_t) begin;
  node->end = (uint32_t) end;
  node->left = node->right = -1;
  node->dim = 0;
  node->split = 0.0f;
  if (end - begin <= LEAF_POINTS
      || (end - begin >= POLL_POINTS ? ts_cancel_poll (cancel) : ts_cancel_requested (cancel)))
    return id;
  for (size_t j = 0; j < TS_SOLID_INDEX_DIMS; j++)
    lo[j] = hi[j] = coordinate (index, order, begin, (uint32_t) j);
  for (size_t i = begin + 1; i < end; i++)
    for (size_t j = 0; j < TS_SOLID_INDEX_DIMS; j++)
      {
        float c = coordinate (index, order, i, (uint32_t) j);
        lo[j] = c < lo[j] ? c : lo[j];
        hi[j] = c > hi[j] ? c : hi[j];
      }
  for (size_t j = 0; j < TS_SOLID_INDEX_DIMS; j++)
    if (hi[j] - lo[j] > widest)
      {
        widest = hi[j] - lo[j];
        node->dim = (uint32_t) j;
      }
  size_t mid = begin + (end - begin) / 2;
  select_median (index, order, begin, end, mid, node->dim);
  float split = coordinate (index, order, mid, node->dim);
  int32_t left = build_node (index, order, begin, mid, cancel);
  int32_t right = build_node (index, order, mid, end, cancel);
  /* index->node may not move: it is allocated at its final size. */
  node = &index->node[id];
  node->split = split;
  node->left = left;
  node->right = right;
  return id;
}

TsStatus
ts_solid_index_build (const TsPyramid *pyramid, size_t level, size_t patch, TsCancel *cancel,
                      TsSolidIndex *index)
{
  const TsImage *im = &pyramid->level[level];
  TsMrpmFeature feature;
  size_t r = patch / 2, w = im->width, h = im->height, count = 0;
  int32_t *list = NULL;
  uint32_t *order = NULL;
  float *point = NULL;
  TsStatus status = TS_ERROR_OUT_OF_MEMORY;

  memset (index, 0, sizeof *index);
  if (w <= 2 * r || h <= 2 * r)
    return TS_OK;
  ts_mrpm_feature_setup (pyramid, level, patch, 1, &feature);
  if (feature.r != r)
    return TS_OK;
  list = malloc ((w - 2 * r) * (h - 2 * r) * sizeof (int32_t));
  if (!list)
    return status;
  for (size_t y = r; y + r < h; y++)
    for (size_t x = r; x + r < w; x++)
      if (ts_image_pixel (im, x, y)[3] > 0.0f)
        list[count++] = (int32_t) (y * w + x);
  if (count == 0)
    {
      free (list);
      return TS_OK;
    }
  index->patch = patch;
  index->dims = feature.dims;
  index->count = count;
  index->basis = malloc (feature.dims * TS_SOLID_INDEX_DIMS * sizeof (float));
  index->point = malloc (count * TS_SOLID_INDEX_DIMS * sizeof (float));
  index->centre = malloc (count * sizeof (int32_t));
  /* Split leaves keep at least LEAF_POINTS / 2 points: at most count / 4
   * leaves, fewer than count / 2 + 2 nodes. */
  index->node = malloc ((count / 2 + 2) * sizeof (TsSolidIndexNode));
  order = malloc (count * sizeof (uint32_t));
  point = malloc (count * TS_SOLID_INDEX_DIMS * sizeof (float));
  if (!index->basis || !index->point || !index->centre || !index->node || !order || !point)
    goto out;
  status = ts_mrpm_pca_basis (&feature, list, count, w, TS_SOLID_INDEX_DIMS, index->basis);
  if (status != TS_OK)
    goto out;
  status = TS_ERROR_OUT_OF_MEMORY;
  int failed = 0;
#pragma omp parallel
  {
    float *patch_values = malloc (feature.dims * sizeof (float));
    if (!patch_values)
      {
#pragma omp atomic write
        failed = 1;
      }
#pragma omp for schedule(static)
    for (ptrdiff_t i = 0; i < (ptrdiff_t) count; i++)
      if (patch_values && !((i & 255) == 0 ? ts_cancel_poll (cancel) : ts_cancel_requested (cancel)))
        {
          size_t p = (size_t) list[i];
          ts_mrpm_feature_extract (&feature, p % w, p / w, patch_values);
          ts_solid_index_project (index, patch_values, index->point + (size_t) i * TS_SOLID_INDEX_DIMS);
        }
    free (patch_values);
  }
  if (failed)
    goto out;
  for (size_t i = 0; i < count; i++)
    order[i] = (uint32_t) i;
  build_node (index, order, 0, count, cancel);
  if (ts_cancel_requested (cancel))
    {
      status = TS_ERROR_CANCELLED;
      goto out;
    }
  /* Points and centres in tree order, so leaves are contiguous. */
  for (size_t i = 0; i < count; i++)
    {
      memcpy (point + i * TS_SOLID_INDEX_DIMS, index->point + (size_t) order[i] * TS_SOLID_INDEX_DIMS,
              TS_SOLID_INDEX_DIMS * sizeof (float));
      index->centre[i] = list[order[i]];
    }
  free (index->point);
  index->point = point;
  point = NULL;
  status = TS_OK;
out:
  free (list);
  free (order);
  free (point);
  if (status != TS_OK)
    ts_solid_index_free (index);
  return status;
}

typedef struct
{
  float   distance[TS_SOLID_INDEX_RESULTS];
  int32_t centre[TS_SOLID_INDEX_RESULTS];
  size_t  leaves;
} Nearest;

static void
visit (const TsSolidIndex *index, int32_t id, const float *q, Nearest *n)
{
  const TsSolidIndexNode *node = &index->node[id];

  if (node->left < 0)
    {
      for (size_t i = node->begin; i < node->end; i++)
        {
          const float *p = index->point + i * TS_SOLID_INDEX_DIMS;
          float d = 0.0f;
          for (size_t j = 0; j < TS_SOLID_INDEX_DIMS; j++)
            d += (q[j] - p[j]) * (q[j] - p[j]);
          if (d >= n->distance[TS_SOLID_INDEX_RESULTS - 1])
            continue;
          size_t k = TS_SOLID_INDEX_RESULTS - 1;
          for (; k > 0 && n->distance[k - 1] > d; k--)
            {
              n->distance[k] = n->distance[k - 1];
              n->centre[k] = n->centre[k - 1];
            }
          n->distance[k] = d;
          n->centre[k] = index->centre[i];
        }
      if (n->leaves > 0)
        n->leaves--;
      return;
    }
  float diff = q[node->dim] - node->split;
  visit (index, diff < 0.0f ? node->left : node->right, q, n);
  if (n->leaves > 0 && diff * diff < n->distance[TS_SOLID_INDEX_RESULTS - 1])
    visit (index, diff < 0.0f ? node->right : node->left, q, n);
}

void
ts_solid_index_query (const TsSolidIndex *index, const float projected[TS_SOLID_INDEX_DIMS],
                      size_t leaves, int32_t found[TS_SOLID_INDEX_RESULTS])
{
  Nearest n;

  for (size_t k = 0; k < TS_SOLID_INDEX_RESULTS; k++)
    {
      n.distance[k] = (float) INFINITY;
      n.centre[k] = -1;
    }
  n.leaves = leaves;
  if (index->count > 0)
    visit (index, 0, projected, &n);
  memcpy (found, n.centre, sizeof n.centre);
}
