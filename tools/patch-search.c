/* Exact nearest-neighbour search among image windows: PCA-lifted kd-tree.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "patch-search.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#define TS_OMP(x) _Pragma (#x)
#else
#define TS_OMP(x)
#endif

#define BOX_DIMS 16           /* at most this many leading lifted axes
                                 are kept in node boxes                  */
#define LEAF_SIZE 8           /* leaves hold 4 .. 8 points              */
#define LEAF_DIM UINT32_MAX
#define SPREAD_SAMPLES 256    /* points used to pick a node's split axis */

/* Lifted coordinates are computed in double and stored as float (error
 * < 2e-4 for window norms < 3200, i.e. any Lab data), and bounds summed in
 * float: a bound only prunes when it exceeds the best SSD by this margin,
 * well above those errors, so pruning never loses the true nearest. */
#define SLACK_REL 1e-3
#define SLACK_ABS 0.05

/* A node keeps the bounding box of its points in the leading lifted axes
 * (residual norm, then the main principal axes): a much tighter bound than
 * the split planes alone, which constrain only the few axes split on the
 * way down. */
typedef struct
{
  float    box_lo[BOX_DIMS];
  float    box_hi[BOX_DIMS];
  uint32_t dim;            /* split axis; LEAF_DIM for a leaf       */
  uint32_t lo, hi;         /* range of points in tree order         */
  uint32_t left, right;
  uint32_t min_index;      /* smallest grid index in the subtree    */
} KdNode;

struct TsPatchIndex
{
  TsWindowGrid grid;
  size_t    dims;
  size_t    count;
  double   *mean;          /* dims                                   */
  size_t    lift_dims;     /* 8, 16 or 32                            */
  size_t    head;          /* principal axes: lift_dims - 1          */
  size_t    box_dims;      /* min (BOX_DIMS, lift_dims)              */
  double   *basis;         /* dims x lift_dims: orthonormal columns, the
                              last one zero (keeps loops a whole width) */
  size_t    points;        /* distinct windows (duplicates dropped)  */
  float    *lift;          /* points x lift_dims, tree order         */
  uint32_t *order;         /* tree order -> grid index               */
  KdNode   *nodes;
  size_t    node_count;
};

/* Lifted coordinates of a gathered window: the norm of its part
 * orthogonal to the basis, then its principal coordinates (tail first, so
 * node boxes, which keep the leading axes, bound it too: it often carries
 * much of the distance). Double precision keeps rounding far below the
 * search's slack. `n` is a constant at each call so loops vectorise. */
static inline void
lift_n (const TsPatchIndex *ix, const float *vec, float *out, const size_t n)
{
  double acc[TS_SEARCH_MAX_LIFT] = { 0 };
  double total = 0.0, head = 0.0;
  for (size_t i = 0; i < ix->dims; i++)
    {
      double c = vec[i] - ix->mean[i];
      const double *b = ix->basis + i * n;
      total += c * c;
      for (size_t k = 0; k < n; k++)
        acc[k] += c * b[k];
    }
  for (size_t k = 0; k + 1 < n; k++)
    {
      out[k + 1] = (float) acc[k];
      head += acc[k] * acc[k];
    }
  out[0] = (float) sqrt (total > head ? total - head : 0.0);
}

static void
lift (const TsPatchIndex *ix, const float *vec, float *out)
{
  switch (ix->lift_dims)
    {
    case 8:
      lift_n (ix, vec, out, 8);
      break;
    case 16:
      lift_n (ix, vec, out, 16);
      break;
    default:
      lift_n (ix, vec, out, 32);
      break;
    }
}

/* ---- kd-tree ------------------------------------------------------------ */

static float
key (const float *lifted, size_t stride, uint32_t point, uint32_t dim)
{
  return lifted[(size_t) point * stride + dim];
}

/* Reorders perm[0 .. n) so that perm[k] has the k-th smallest key and no
 * key before it is larger, none after it smaller (Hoare quickselect). */
static void
select_kth (uint32_t *perm, size_t n, size_t k, const float *lifted, size_t stride,
            uint32_t dim)
{
  ptrdiff_t lo = 0, hi = (ptrdiff_t) n - 1, target = (ptrdiff_t) k;
  while (hi > lo)
    {
      float pivot = key (lifted, stride, perm[lo + (hi - lo) / 2], dim);
      ptrdiff_t i = lo, j = hi;
      while (i <= j)
        {
          while (key (lifted, stride, perm[i], dim) < pivot)
            i++;
          while (key (lifted, stride, perm[j], dim) > pivot)
            j--;
          if (i <= j)
            {
              uint32_t t = perm[i];
              perm[i] = perm[j];
              perm[j] = t;
              i++;
              j--;
            }
        }
      if (target <= j)
        hi = j;
      else if (target >= i)
        lo = i;
      else
        return;
    }
}

/* Builds the subtree of perm[lo .. hi) (grid indices) and returns its node. */
static uint32_t
build_node (TsPatchIndex *ix, const float *lifted, uint32_t *perm, size_t lo, size_t hi)
{
  uint32_t id = (uint32_t) ix->node_count++;
  KdNode *node = &ix->nodes[id];
  size_t n = hi - lo, stride = ix->lift_dims;
  float best_spread = -1.0f;
  uint32_t dim = 0;

  node->lo = (uint32_t) lo;
  node->hi = (uint32_t) hi;
  node->min_index = UINT32_MAX;
  for (size_t d = 0; d < ix->box_dims; d++)
    {
      node->box_lo[d] = FLT_MAX;
      node->box_hi[d] = -FLT_MAX;
    }
  if (n <= LEAF_SIZE)
    {
      node->dim = LEAF_DIM;
      for (size_t i = lo; i < hi; i++)
        {
          node->min_index = perm[i] < node->min_index ? perm[i] : node->min_index;
          for (uint32_t d = 0; d < ix->box_dims; d++)
            {
              float v = key (lifted, stride, perm[i], d);
              node->box_lo[d] = v < node->box_lo[d] ? v : node->box_lo[d];
              node->box_hi[d] = v > node->box_hi[d] ? v : node->box_hi[d];
            }
        }
      return id;
    }
  /* Split the axis of largest spread, estimated on a sample. */
  {
    size_t every = n > SPREAD_SAMPLES ? n / SPREAD_SAMPLES : 1;
    for (uint32_t d = 0; d < ix->box_dims; d++)
      {
        float mn = FLT_MAX, mx = -FLT_MAX;
        for (size_t i = lo; i < hi; i += every)
          {
            float v = key (lifted, stride, perm[i], d);
            mn = v < mn ? v : mn;
            mx = v > mx ? v : mx;
          }
        if (mx - mn > best_spread)
          {
            best_spread = mx - mn;
            dim = d;
          }
      }
  }
  select_kth (perm + lo, n, n / 2, lifted, stride, dim);
  {
    uint32_t left = build_node (ix, lifted, perm, lo, lo + n / 2);
    uint32_t right = build_node (ix, lifted, perm, lo + n / 2, hi);
    const KdNode *l = &ix->nodes[left], *r = &ix->nodes[right];
    node = &ix->nodes[id];
    node->dim = dim;
    node->left = left;
    node->right = right;
    node->min_index = l->min_index < r->min_index ? l->min_index : r->min_index;
    for (size_t d = 0; d < ix->box_dims; d++)
      {
        node->box_lo[d] = l->box_lo[d] < r->box_lo[d] ? l->box_lo[d] : r->box_lo[d];
        node->box_hi[d] = l->box_hi[d] > r->box_hi[d] ? l->box_hi[d] : r->box_hi[d];
      }
  }
  return id;
}

/* FNV-1a over 32-bit words: equal windows get equal hashes (the exact
 * comparison follows); -0.0 and 0.0 differ, which only misses a merge. */
static uint64_t
hash_window (const float *vec, size_t dims)
{
  uint64_t h = 1469598103934665603u;
  for (size_t i = 0; i < dims; i++)
    {
      uint32_t w;
      memcpy (&w, &vec[i], sizeof w);
      h = (h ^ w) * 1099511628211u;
    }
  return h ^ (h >> 29);
}

typedef struct
{
  uint64_t hash;
  uint32_t index;
} HashedWindow;

static int
compare_hashed (const void *a, const void *b)
{
  const HashedWindow *x = a, *y = b;
  if (x->hash != y->hash)
    return x->hash < y->hash ? -1 : 1;
  return x->index < y->index ? -1 : x->index > y->index;
}

/* Marks in `keep` the first (smallest-index) window of every group of
 * identical windows. Flat areas of 8-bit images give thousands of
 * identical windows, which would all tie with each other in searches. */
static bool
mark_distinct (const TsWindowGrid *grid, HashedWindow *hw, size_t count, uint8_t *keep)
{
  size_t dims = ts_grid_dims (grid);
  float *a = malloc (dims * sizeof (float)), *b = malloc (dims * sizeof (float));
  if (!a || !b)
    {
      free (a), free (b);
      return false;
    }
  qsort (hw, count, sizeof (HashedWindow), compare_hashed);
  for (size_t g = 0, end; g < count; g = end)
    {
      for (end = g + 1; end < count && hw[end].hash == hw[g].hash; end++)
        ;
      for (size_t i = g; i < end; i++)
        {
          bool duplicate = false;
          ts_grid_gather (grid, hw[i].index, a);
          for (size_t j = g; j < i && !duplicate; j++)
            if (keep[hw[j].index])
              {
                ts_grid_gather (grid, hw[j].index, b);
                duplicate = memcmp (a, b, dims * sizeof (float)) == 0;
              }
          keep[hw[i].index] = !duplicate;
        }
    }
  free (a), free (b);
  return true;
}

void
ts_patch_index_free (TsPatchIndex *ix)
{
  if (!ix)
    return;
  free (ix->mean);
  free (ix->basis);
  free (ix->lift);
  free (ix->order);
  free (ix->nodes);
  free (ix);
}

TsPatchIndex *
ts_patch_index_new (const TsWindowGrid *grid, int lift_dims)
{
  TsPatchIndex *ix = calloc (1, sizeof (TsPatchIndex));
  size_t count = ts_grid_count (grid), dims = ts_grid_dims (grid), points = 0;
  float *lifted = NULL;
  HashedWindow *hw = NULL;
  uint8_t *keep = NULL;
  bool ok = true;

  if (!ix || count == 0 || count >= UINT32_MAX
      || count > SIZE_MAX / (TS_SEARCH_MAX_LIFT * sizeof (float))
      || (lift_dims != 8 && lift_dims != 16 && lift_dims != 32))
    {
      free (ix);
      return NULL;
    }
  ix->grid = *grid;
  ix->dims = dims;
  ix->count = count;
  ix->lift_dims = (size_t) lift_dims;
  ix->head = ix->lift_dims - 1;
  ix->box_dims = ix->lift_dims < BOX_DIMS ? ix->lift_dims : BOX_DIMS;
  ix->mean = calloc (dims, sizeof (double));
  ix->basis = calloc (dims * ix->lift_dims, sizeof (double));
  ix->order = malloc (count * sizeof (uint32_t));
  lifted = malloc (count * ix->lift_dims * sizeof (float));
  hw = malloc (count * sizeof (HashedWindow));
  keep = malloc (count);
  if (!ix->mean || !ix->basis || !ix->order || !lifted || !hw || !keep
      || !ts_grid_pca (grid, ix->head, ix->lift_dims, ix->mean, ix->basis))
    goto fail;

  TS_OMP (omp parallel reduction (&& : ok))
  {
    float *vec = malloc (dims * sizeof (float));
    if (!vec)
      ok = false;
    TS_OMP (omp for schedule (static))
    for (size_t i = 0; i < count; i++)
      if (vec)
        {
          ts_grid_gather (grid, i, vec);
          lift (ix, vec, lifted + i * ix->lift_dims);
          hw[i].hash = hash_window (vec, dims);
          hw[i].index = (uint32_t) i;
        }
    free (vec);
  }
  if (!ok || !mark_distinct (grid, hw, count, keep))
    goto fail;
  free (hw);
  hw = NULL;

  for (size_t i = 0; i < count; i++)
    if (keep[i])
      ix->order[points++] = (uint32_t) i;
  ix->points = points;
  /* Leaves hold >= LEAF_SIZE / 2 points, so nodes < 4 points / LEAF_SIZE. */
  ix->nodes = malloc ((4 * points / LEAF_SIZE + 2) * sizeof (KdNode));
  ix->lift = malloc (points * ix->lift_dims * sizeof (float));
  if (!ix->nodes || !ix->lift)
    goto fail;
  build_node (ix, lifted, ix->order, 0, points);
  /* Store points in tree order so a leaf's points are contiguous. */
  for (size_t i = 0; i < points; i++)
    memcpy (ix->lift + i * ix->lift_dims, lifted + (size_t) ix->order[i] * ix->lift_dims,
            ix->lift_dims * sizeof (float));
  free (lifted);
  free (keep);
  return ix;

fail:
  free (lifted);
  free (hw);
  free (keep);
  ts_patch_index_free (ix);
  return NULL;
}

/* ---- search ------------------------------------------------------------- */

typedef enum
{
  FIND_NEAREST,     /* exact nearest window                          */
  FIND_FIRST,       /* smallest index with SSD below `best`          */
  FIND_ANY          /* any index with SSD below `best`               */
} SearchMode;

typedef struct
{
  const TsPatchIndex *ix;
  const float *vec;
  float      q[TS_SEARCH_MAX_LIFT];
  float      best;       /* SSD to beat (nearest) or threshold        */
  size_t     best_index;
  SearchMode mode;
} Search;

static bool
prunes (float bound, float best)
{
  return (double) bound > (double) best * (1.0 + SLACK_REL) + SLACK_ABS;
}

/* Sums of squares below accumulate in LANES independent partial sums so
 * that compilers can vectorise them without -ffast-math. */
#define LANES 8
_Static_assert (BOX_DIMS % LANES == 0, "box axes must fill whole lanes");

static float
sum_lanes (const float *acc)
{
  float d = 0.0f;
  for (int l = 0; l < LANES; l++)
    d += acc[l];
  return d;
}

static float
box_distance (const float *q, const KdNode *node, size_t box_dims)
{
  float acc[LANES] = { 0 };
  for (size_t k = 0; k < box_dims; k += LANES)
    for (size_t l = 0; l < LANES; l++)
      {
        float below = node->box_lo[k + l] - q[k + l], above = q[k + l] - node->box_hi[k + l];
        float t = (below > 0.0f ? below : 0.0f) + (above > 0.0f ? above : 0.0f);
        acc[l] += t * t;
      }
  return sum_lanes (acc);
}

static float
point_distance (const float *q, const float *p, size_t dims)
{
  float acc[LANES] = { 0 };
  for (size_t k = 0; k < dims; k += LANES)
    for (size_t l = 0; l < LANES; l++)
      {
        float t = q[k + l] - p[k + l];
        acc[l] += t * t;
      }
  return sum_lanes (acc);
}

static void
search_leaf (Search *s, const KdNode *node)
{
  const TsPatchIndex *ix = s->ix;
  for (uint32_t j = node->lo; j < node->hi; j++)
    {
      const float *p = ix->lift + (size_t) j * ix->lift_dims;
      uint32_t index = ix->order[j];
      float e;
      if (s->mode == FIND_FIRST && index >= s->best_index)
        continue;
      if (prunes (point_distance (s->q, p, ix->lift_dims), s->best))
        continue;
      e = ts_grid_ssd (s->vec, &ix->grid, index, s->best);
      if (e < s->best)
        {
          s->best_index = index;
          if (s->mode == FIND_NEAREST)
            s->best = e;
          else if (s->mode == FIND_ANY)
            return;
        }
    }
}

static void
search_node (Search *s, uint32_t id, float bound)
{
  const KdNode *node = &s->ix->nodes[id];
  float bl, br;

  if (prunes (bound, s->best)
      || (s->mode == FIND_NEAREST && s->best <= 0.0f)
      || (s->mode == FIND_ANY && s->best_index != TS_SEARCH_NONE)
      || (s->mode == FIND_FIRST && node->min_index >= s->best_index))
    return;
  if (node->dim == LEAF_DIM)
    {
      search_leaf (s, node);
      return;
    }
  bl = box_distance (s->q, &s->ix->nodes[node->left], s->ix->box_dims);
  br = box_distance (s->q, &s->ix->nodes[node->right], s->ix->box_dims);
  if (bl <= br)
    {
      search_node (s, node->left, bl);
      search_node (s, node->right, br);
    }
  else
    {
      search_node (s, node->right, br);
      search_node (s, node->left, bl);
    }
}

static void
run (Search *s)
{
  lift (s->ix, s->vec, s->q);
  search_node (s, 0, box_distance (s->q, &s->ix->nodes[0], s->ix->box_dims));
}

size_t
ts_patch_index_nearest (const TsPatchIndex *ix, const float *vec, size_t guess, float *ssd)
{
  Search s = { .ix = ix, .vec = vec, .best = FLT_MAX, .best_index = TS_SEARCH_NONE,
               .mode = FIND_NEAREST };
  if (guess < ix->count)
    {
      s.best = ts_grid_ssd (vec, &ix->grid, guess, FLT_MAX);
      s.best_index = guess;
    }
  if (s.best > 0.0f) /* an exact copy cannot be beaten: skip the search */
    run (&s);
  if (s.best_index == TS_SEARCH_NONE)
    {
      /* Only if every SSD overflowed to infinity: fall back to window 0. */
      s.best_index = 0;
      s.best = ts_grid_ssd (vec, &ix->grid, 0, FLT_MAX);
    }
  *ssd = s.best;
  return s.best_index;
}

size_t
ts_patch_index_first_within (const TsPatchIndex *ix, const float *vec, float max_ssd)
{
  Search s = { .ix = ix, .vec = vec, .best = max_ssd, .best_index = TS_SEARCH_NONE,
               .mode = FIND_FIRST };
  run (&s);
  return s.best_index;
}

size_t
ts_patch_index_any_within (const TsPatchIndex *ix, const float *vec, float max_ssd)
{
  Search s = { .ix = ix, .vec = vec, .best = max_ssd, .best_index = TS_SEARCH_NONE,
               .mode = FIND_ANY };
  run (&s);
  return s.best_index;
}
