/* MRPM candidate sets (Sureka & Narayanan 2012).
 *
 * Coarsest level: brute force over all valid centres. Finer levels: the
 * candidates of p are the centres in the (u + 1)^2 boxes covering the u x u
 * windows around the four children of p's parent and of each of the
 * parent's matches. Candidates are ranked in a per-level PCA projection of
 * the features, the best k + rerank re-ranked exactly; then a propagation
 * pass tries the neighbours' matches, shifted.
 *
 * Determinism: every pixel is computed by one thread from read-only data
 * with a fixed order of operations, and lists are ordered by (distance,
 * index), so the result does not depend on the thread count.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "mrpm.h"
#include "clones.h"
#include "mrpm-feature.h"
#include "indexing.h"
#include "rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif


void
ts_mrpm_options_init (TsMrpmOptions *options)
{
  options->patch_size = 5;
  options->window = 5;
  options->levels_compared = 3;
  options->exclude_radius = 2;
  options->pca_dims = 16;
  /* Four re-ranks keep the synthesis's quality (bds, copy, sharpness
   * within seed noise of eight) at a sixth less MRPM work. */
  options->rerank = 4;
  options->rerank_coarsest = 8;
  options->parent_matches = 0;
  options->propagation = 1;
}

/* Sorted insertion into a list of at most cap entries, ordered by
 * (distance, index) so ties never depend on visiting order. */
static inline void
list_insert (float *dist, int32_t *idx, size_t *n, size_t cap, float d, int32_t i)
{
  size_t pos = *n;
  if (pos == cap)
    {
      if (d > dist[cap - 1] || (d == dist[cap - 1] && i > idx[cap - 1]))
        return;
      pos = cap - 1;
    }
  else
    (*n)++;
  while (pos > 0 && (dist[pos - 1] > d || (dist[pos - 1] == d && idx[pos - 1] > i)))
    {
      dist[pos] = dist[pos - 1];
      idx[pos] = idx[pos - 1];
      pos--;
    }
  dist[pos] = d;
  idx[pos] = i;
}

static inline float
list_bound (const float *dist, size_t n, size_t cap)
{
  return n == cap ? dist[cap - 1] : INFINITY;
}

typedef struct
{
  TsMrpmFeature f;
  size_t w, h, r, R, k, m;
  size_t M, Mp;        /* search list lengths: window search, propagation */
  size_t cap;          /* per-thread candidate capacity                   */
  ptrdiff_t lo, hix, hiy;  /* valid centres: [lo, hix] x [lo, hiy]        */
  const float *proj;   /* m floats per valid centre                       */
  const float *alpha;  /* channel 3 of the level, stride 4                */
} Ctx;

typedef struct
{
  uint32_t *stamp;     /* dedup marks, one per level pixel */
  uint32_t  cur;
  int32_t  *cand, *cx, *cy;
  float    *lead, *part; /* leading 4 projected axes, candidate-major */
  float    *sd, *rd, *feat;
  int32_t  *si, *ri;
  char      pad[64];     /* keeps threads' `cur` off a shared cache line */
} Scratch;

static void
next_stamp (Scratch *s, size_t pixels)
{
  if (++s->cur == 0)
    {
      memset (s->stamp, 0, pixels * sizeof (uint32_t));
      s->cur = 1;
    }
}

/* Adds (x, y) unless seen or transparent. */
static inline void
add_candidate (const Ctx *c, Scratch *s, size_t *n, ptrdiff_t x, ptrdiff_t y)
{
  size_t i = (size_t) y * c->w + (size_t) x;
  if (s->stamp[i] == s->cur)
    return;
  s->stamp[i] = s->cur;
  if (c->alpha[i * TS_CHANNELS] == 0.0f)
    return;
  s->cand[*n] = (int32_t) i;
  s->cx[*n] = (int32_t) x;
  s->cy[*n] = (int32_t) y;
  (*n)++;
}

static void
gather_lead (const Ctx *c, const int32_t *cand, size_t n, float *lead, size_t stride)
{
  if (c->m)
    for (size_t i = 0; i < n; i++)
      for (size_t j = 0; j < 4; j++)
        lead[j * stride + i] = c->proj[(size_t) cand[i] * c->m + j];
}

/* Best k of the n candidates and of the nseed seeds (sorted, with exact
 * distances) for the valid centre (x, y), into out / outd. With PCA the
 * best M by projected distance are re-ranked exactly; seeds make that
 * bound tight from the start, so most exact distances stop early. */
TS_VECTOR_CLONES static void
search_pixel (const Ctx *c, Scratch *s, size_t x, size_t y, size_t n, const int32_t *cand,
              const int32_t *cx, const int32_t *cy, const float *lead, size_t stride, size_t M,
              const int32_t *seed, const float *seedd, size_t nseed, int32_t *out, float *outd)
{
  ptrdiff_t R = (ptrdiff_t) c->R;
  size_t ns = 0, nr = 0;
  const float *q = c->m ? c->proj + (y * c->w + x) * c->m : NULL;

  if (c->m)
    {
      /* The leading axes carry most of the variance: their distance,
       * vectorised across candidates, rejects most candidates cheaply. */
      const float *l0 = lead, *l1 = lead + stride, *l2 = lead + 2 * stride, *l3 = lead + 3 * stride;
      for (size_t i = 0; i < n; i++)
        {
          float a = l0[i] - q[0], b = l1[i] - q[1], e = l2[i] - q[2], f = l3[i] - q[3];
          s->part[i] = (a * a + b * b) + (e * e + f * f);
        }
    }
  else
    for (size_t i = 0; i < nseed; i++)
      list_insert (s->sd, s->si, &ns, M, seedd[i], seed[i]);
  float bound = list_bound (s->sd, ns, M);
  for (size_t i = 0; i < n; i++)
    {
      float d;
      if (c->m)
        {
          if (s->part[i] > bound)
            continue;
          float acc[4] = { 0, 0, 0, 0 };
          ts_lanes_add (acc, q, c->proj + (size_t) cand[i] * c->m, c->m);
          d = TS_LANES_TOTAL (acc);
          if (d > bound)
            continue;
        }
      ptrdiff_t ex = cx[i] - (ptrdiff_t) x, ey = cy[i] - (ptrdiff_t) y;
      if (ex >= -R && ex <= R && ey >= -R && ey <= R)
        continue;
      if (!c->m)
        d = ts_mrpm_feature_distance (&c->f, x, y, (size_t) cx[i], (size_t) cy[i], bound);
      if (d <= bound)
        {
          list_insert (s->sd, s->si, &ns, M, d, cand[i]);
          bound = list_bound (s->sd, ns, M);
        }
    }
  if (c->m)
    {
      /* The coarsest level has no seeds, and memcpy from NULL is
       * undefined even for 0 bytes. */
      if (nseed > 0)
        {
          memcpy (s->rd, seedd, nseed * sizeof (float));
          memcpy (s->ri, seed, nseed * sizeof (int32_t));
        }
      nr = nseed;
      for (size_t i = 0; i < ns; i++)
        {
          size_t p = (size_t) s->si[i];
          float b = list_bound (s->rd, nr, c->k);
          float d = ts_mrpm_feature_distance (&c->f, x, y, p % c->w, p / c->w, b);
          if (d <= b)
            list_insert (s->rd, s->ri, &nr, c->k, d, s->si[i]);
        }
    }
  else
    {
      memcpy (s->ri, s->si, ns * sizeof (int32_t));
      memcpy (s->rd, s->sd, ns * sizeof (float));
      nr = ns;
    }
  for (size_t j = 0; j < c->k; j++)
    {
      out[j] = j < nr ? s->ri[j] : -1;
      outd[j] = j < nr ? s->rd[j] : INFINITY;
    }
}

/* The PCA projections of the valid centres of row y. */
TS_VECTOR_CLONES static void
project_row (const Ctx *c, const float *basis, size_t y, float *feat, float *proj)
{
  for (size_t x = c->r; x + c->r < c->w; x++)
    {
      float acc[MAX_PCA] = { 0 };
      ts_mrpm_feature_extract (&c->f, x, y, feat);
      for (size_t d = 0; d < c->f.dims; d++)
        for (size_t j = 0; j < c->m; j++)
          acc[j] += basis[d * c->m + j] * feat[d];
      memcpy (proj + (y * c->w + x) * c->m, acc, c->m * sizeof (float));
    }
}

/* The children of each source come first (pass 0), then the rest of the
 * windows: likely matches early tighten the scan's bound. Source 0 is the
 * parent itself, for non-trivial nearby shifts (periodic textures). */
static size_t
collect_windows (const Ctx *c, Scratch *s, const TsCandidateSet *coarser, size_t sources,
                 ptrdiff_t half, size_t px, size_t py)
{
  const int32_t *match = coarser->index + (py * coarser->width + px) * coarser->k;
  size_t n = 0;

  next_stamp (s, c->w * c->h);
  for (ptrdiff_t pass = 0, e = 0; pass < 2; pass++, e = half)
    for (size_t j = 0; j <= sources; j++)
      {
        int32_t q = j == 0 ? (int32_t) (py * coarser->width + px) : match[j - 1];
        if (q < 0)
          continue;
        ptrdiff_t qx = 2 * (ptrdiff_t) ((size_t) q % coarser->width);
        ptrdiff_t qy = 2 * (ptrdiff_t) ((size_t) q / coarser->width);
        ptrdiff_t x0 = qx - e < c->lo ? c->lo : qx - e, x1 = qx + 1 + e > c->hix ? c->hix : qx + 1 + e;
        ptrdiff_t y0 = qy - e < c->lo ? c->lo : qy - e, y1 = qy + 1 + e > c->hiy ? c->hiy : qy + 1 + e;
        for (ptrdiff_t yy = y0; yy <= y1; yy++)
          for (ptrdiff_t xx = x0; xx <= x1; xx++)
            add_candidate (c, s, &n, xx, yy);
      }
  return n;
}

/* Propagation (as in PatchMatch / k-coherence): the matches of the eight
 * neighbours, shifted back, are tried against p's own list. Recovers true
 * matches the windows missed where fine detail dominates. */
static void
propagate_pixel (const Ctx *c, Scratch *s, const int32_t *prev, const float *prevd,
                 size_t x, size_t y, int32_t *out, float *outd)
{
  const int32_t *own = prev + (y * c->w + x) * c->k;
  size_t n = 0, nseed = 0;

  next_stamp (s, c->w * c->h);
  while (nseed < c->k && own[nseed] >= 0)
    s->stamp[own[nseed++]] = s->cur;
  for (ptrdiff_t dy = -1; dy <= 1; dy++)
    for (ptrdiff_t dx = -1; dx <= 1; dx++)
      {
        ptrdiff_t nx = (ptrdiff_t) x + dx, ny = (ptrdiff_t) y + dy;
        if ((dx == 0 && dy == 0) || nx < c->lo || nx > c->hix || ny < c->lo || ny > c->hiy)
          continue;
        const int32_t *list = prev + ((size_t) ny * c->w + (size_t) nx) * c->k;
        for (size_t j = 0; j < c->k && list[j] >= 0; j++)
          {
            ptrdiff_t qx = (ptrdiff_t) ((size_t) list[j] % c->w) - dx;
            ptrdiff_t qy = (ptrdiff_t) ((size_t) list[j] / c->w) - dy;
            if (qx >= c->lo && qx <= c->hix && qy >= c->lo && qy <= c->hiy)
              add_candidate (c, s, &n, qx, qy);
          }
      }
  gather_lead (c, s->cand, n, s->lead, c->cap);
  search_pixel (c, s, x, y, n, s->cand, s->cx, s->cy, s->lead, c->cap, c->m ? c->Mp : c->k,
                own, prevd + (y * c->w + x) * c->k, nseed, out, outd);
}

static int
poll_cancel (int *stop, TsCancel *cancel)
{
  int v;
#pragma omp atomic read
  v = *stop;
  if (!v && ts_cancel_poll (cancel))
    {
      v = 1;
#pragma omp atomic write
      *stop = 1;
    }
  return v;
}

static void
scratch_free (Scratch *s, size_t n)
{
  for (size_t t = 0; s && t < n; t++)
    {
      free (s[t].stamp), free (s[t].cand), free (s[t].cx), free (s[t].cy), free (s[t].lead);
      free (s[t].part), free (s[t].sd), free (s[t].rd), free (s[t].feat), free (s[t].si), free (s[t].ri);
    }
  free (s);
}

static Scratch *
scratch_alloc (size_t n, size_t pixels, size_t cap, size_t M, size_t k, size_t dims)
{
  Scratch *s = calloc (n, sizeof (Scratch));
  for (size_t t = 0; s && t < n; t++)
    {
      s[t].stamp = calloc (pixels, sizeof (uint32_t));
      s[t].cand = malloc (cap * sizeof (int32_t));
      s[t].cx = malloc (cap * sizeof (int32_t));
      s[t].cy = malloc (cap * sizeof (int32_t));
      s[t].lead = malloc (4 * cap * sizeof (float));
      s[t].part = malloc (cap * sizeof (float));
      s[t].sd = malloc (M * sizeof (float));
      s[t].si = malloc (M * sizeof (int32_t));
      s[t].rd = malloc (k * sizeof (float));
      s[t].ri = malloc ((M > k ? M : k) * sizeof (int32_t));
      s[t].feat = malloc (dims * sizeof (float));
      if (!s[t].stamp || !s[t].cand || !s[t].cx || !s[t].cy || !s[t].lead || !s[t].part
          || !s[t].sd || !s[t].si || !s[t].rd || !s[t].ri || !s[t].feat)
        {
          scratch_free (s, n);
          return NULL;
        }
    }
  return s;
}

static size_t
thread_id (void)
{
#ifdef _OPENMP
  return (size_t) omp_get_thread_num ();
#else
  return 0;
#endif
}

size_t
ts_mrpm_radius (const TsPyramid *pyramid, size_t level, const TsMrpmOptions *options)
{
  TsMrpmFeature f;
  ts_mrpm_feature_setup (pyramid, level, options->patch_size, options->levels_compared, &f);
  return f.r;
}

float
ts_mrpm_distance (const TsPyramid *pyramid, size_t level, const TsMrpmOptions *options, size_t a, size_t b)
{
  TsMrpmFeature f;
  size_t w = pyramid->level[level].width;
  ts_mrpm_feature_setup (pyramid, level, options->patch_size, options->levels_compared, &f);
  return ts_mrpm_feature_distance (&f, a % w, a / w, b % w, b / w, INFINITY);
}

void
ts_candidate_set_free (TsCandidateSet *set)
{
  if (!set)
    return;
  free (set->index);
  set->index = NULL;
  set->width = set->height = set->k = 0;
}

TsStatus
ts_mrpm_level (const TsPyramid *pyramid, size_t level, const TsCandidateSet *coarser,
               size_t k, const TsMrpmOptions *options, TsCancel *cancel,
               TsCandidateSet *out)
{
  TsMrpmOptions defaults;
  TsStatus status = TS_OK;
  Ctx c;
  int32_t *list = NULL, *prev = NULL, *gx = NULL, *gy = NULL;
  float *basis = NULL, *proj = NULL, *odist = NULL, *prevd = NULL, *lead = NULL;
  Scratch *scratch = NULL;
  size_t nthreads = 1, pixels, total, n = 0;
  int stop = 0;

  if (!out)
    return TS_ERROR_INVALID_ARGUMENT;
  out->width = out->height = out->k = 0;
  out->index = NULL;
  if (!options)
    {
      ts_mrpm_options_init (&defaults);
      options = &defaults;
    }
  if (!pyramid || level >= pyramid->levels || k == 0 || k > INT32_MAX
      || options->pca_dims > MAX_PCA)
    return TS_ERROR_INVALID_ARGUMENT;
  const TsImage *im = &pyramid->level[level];
  if (im->width == 0 || im->height == 0 || !im->pixels)
    return TS_ERROR_INVALID_ARGUMENT;
  if (coarser
      && (level + 1 >= pyramid->levels || !coarser->index || coarser->k == 0
          || coarser->width != pyramid->level[level + 1].width
          || coarser->height != pyramid->level[level + 1].height))
    return TS_ERROR_INVALID_ARGUMENT;
  /* Generous bound covering every per-pixel array below. */
  if (!ts_size_mul (im->width, im->height, &pixels) || pixels > INT32_MAX
      || !ts_size_mul (pixels, k + MAX_PCA + 8, &total) || total > (size_t) -1 / 16)
    return TS_ERROR_TOO_LARGE;
  total = pixels * k;

  memset (&c, 0, sizeof c);
  ts_mrpm_feature_setup (pyramid, level, options->patch_size, options->levels_compared, &c.f);
  c.w = im->width;
  c.h = im->height;
  c.r = c.f.r;
  c.lo = (ptrdiff_t) c.r;
  c.hix = (ptrdiff_t) (c.w - 1 - c.r);
  c.hiy = (ptrdiff_t) (c.h - 1 - c.r);
  c.R = options->exclude_radius;
  c.k = k;
  c.alpha = im->pixels + 3;

  out->index = malloc (total * sizeof (int32_t));
  list = malloc (pixels * sizeof (int32_t));
  odist = malloc (total * sizeof (float));
  prev = malloc (total * sizeof (int32_t));
  prevd = malloc (total * sizeof (float));
  if (!out->index || !list || !odist || !prev || !prevd)
    goto oom;
  out->width = c.w;
  out->height = c.h;
  out->k = k;

  /* Valid centres (patch inside the level) that may be candidates. */
  for (size_t y = c.r; y + c.r < c.h; y++)
    for (size_t x = c.r; x + c.r < c.w; x++)
      if (ts_image_pixel (im, x, y)[3] != 0.0f)
        list[n++] = (int32_t) (y * c.w + x);

  /* PCA dims rounded up to lanes of 4 (dims is a multiple of 4 too). */
  c.m = n ? (options->pca_dims + 3) / 4 * 4 : 0;
  if (c.m > c.f.dims)
    c.m = c.f.dims;
  size_t rerank = coarser ? options->rerank : options->rerank_coarsest;
  c.M = c.m ? k + rerank : k;
  c.Mp = rerank ? rerank : 1;

  /* Candidate capacity: the whole list (brute force), the union of the
   * windows, the propagation candidates. */
  size_t box = 2 * (options->window / 2) + 2, windows;
  c.cap = n > 9 * k ? n : 9 * k;
  if (coarser)
    {
      if (!ts_size_mul (box, box, &windows) || !ts_size_mul (windows, coarser->k + 1, &windows))
        windows = pixels;
      c.cap = windows > c.cap ? windows : c.cap;
    }
  if (c.cap > pixels)
    c.cap = pixels;
#ifdef _OPENMP
  nthreads = (size_t) omp_get_max_threads ();
#endif
  scratch = scratch_alloc (nthreads, pixels, c.cap, c.M, k, c.f.dims);
  if (!scratch)
    goto oom;

  if (c.m)
    {
      basis = malloc (c.m * c.f.dims * sizeof (float));
      proj = malloc (pixels * c.m * sizeof (float));
      if (!basis || !proj)
        goto oom;
      status = ts_mrpm_pca_basis (&c.f, list, n, c.w, c.m, basis);
      if (status != TS_OK)
        goto fail;
#pragma omp parallel for schedule(static)
      for (ptrdiff_t y = c.lo; y <= c.hiy; y++)
        {
          float *feat = scratch[thread_id ()].feat;
          if (poll_cancel (&stop, cancel))
            continue;
          project_row (&c, basis, (size_t) y, feat, proj);
        }
      c.proj = proj;
    }

  if (!coarser)
    {
      /* Brute force against every candidate, gathered once. */
      gx = malloc (c.cap * sizeof (int32_t));
      gy = malloc (c.cap * sizeof (int32_t));
      lead = malloc (4 * c.cap * sizeof (float));
      if (!gx || !gy || !lead)
        goto oom;
      for (size_t i = 0; i < n; i++)
        {
          gx[i] = (int32_t) ((size_t) list[i] % c.w);
          gy[i] = (int32_t) ((size_t) list[i] / c.w);
        }
      gather_lead (&c, list, n, lead, c.cap);
#pragma omp parallel for schedule(dynamic, 1)
      for (ptrdiff_t y = c.lo; y <= c.hiy; y++)
        {
          Scratch *s = &scratch[thread_id ()];
          if (poll_cancel (&stop, cancel))
            continue;
          for (size_t x = c.r; x + c.r < c.w; x++)
            search_pixel (&c, s, x, (size_t) y, n, list, gx, gy, lead, c.cap, c.M, NULL, NULL, 0,
                          out->index + ((size_t) y * c.w + x) * k, odist + ((size_t) y * c.w + x) * k);
        }
    }
  else
    {
      /* One parent at a time: its children share the union of windows. */
      ptrdiff_t half = (ptrdiff_t) (options->window / 2);
      size_t sources = options->parent_matches && options->parent_matches < coarser->k
                       ? options->parent_matches : coarser->k;
#pragma omp parallel for schedule(dynamic, 1)
      for (ptrdiff_t py = c.lo / 2; py <= c.hiy / 2; py++)
        {
          Scratch *s = &scratch[thread_id ()];
          if (poll_cancel (&stop, cancel))
            continue;
          for (ptrdiff_t px = c.lo / 2; px <= c.hix / 2; px++)
            {
              size_t nc = collect_windows (&c, s, coarser, sources, half, (size_t) px, (size_t) py);
              gather_lead (&c, s->cand, nc, s->lead, c.cap);
              for (ptrdiff_t y = 2 * py; y <= 2 * py + 1; y++)
                for (ptrdiff_t x = 2 * px; x <= 2 * px + 1; x++)
                  if (x >= c.lo && x <= c.hix && y >= c.lo && y <= c.hiy)
                    search_pixel (&c, s, (size_t) x, (size_t) y, nc, s->cand, s->cx, s->cy, s->lead,
                                  c.cap, c.M, NULL, NULL, 0, out->index + ((size_t) y * c.w + (size_t) x) * k,
                                  odist + ((size_t) y * c.w + (size_t) x) * k);
            }
        }
    }

  for (size_t pass = 0; pass < options->propagation && !stop; pass++)
    {
      /* Jacobi-style: read the previous lists, so order doesn't matter. */
      memcpy (prev, out->index, total * sizeof (int32_t));
      memcpy (prevd, odist, total * sizeof (float));
#pragma omp parallel for schedule(dynamic, 1)
      for (ptrdiff_t y = c.lo; y <= c.hiy; y++)
        {
          Scratch *s = &scratch[thread_id ()];
          if (poll_cancel (&stop, cancel))
            continue;
          for (size_t x = c.r; x + c.r < c.w; x++)
            propagate_pixel (&c, s, prev, prevd, x, (size_t) y, out->index + ((size_t) y * c.w + x) * k,
                             odist + ((size_t) y * c.w + x) * k);
        }
    }
  if (stop || ts_cancel_requested (cancel))
    {
      status = TS_ERROR_CANCELLED;
      goto fail;
    }

  /* Pixels whose patch would cross the border: their clamped centre's. */
  for (size_t y = 0; y < c.h; y++)
    for (size_t x = 0; x < c.w; x++)
      {
        size_t cx = ts_clamp_centre ((ptrdiff_t) x, c.w, c.r), cy = ts_clamp_centre ((ptrdiff_t) y, c.h, c.r);
        if (cx != x || cy != y)
          memcpy (out->index + (y * c.w + x) * k, out->index + (cy * c.w + cx) * k, k * sizeof (int32_t));
      }
  goto done;

oom:
  status = TS_ERROR_OUT_OF_MEMORY;
fail:
  ts_candidate_set_free (out);
done:
  scratch_free (scratch, nthreads);
  free (list), free (prev), free (prevd), free (odist), free (basis), free (proj);
  free (gx), free (gy), free (lead);
  return status;
}
