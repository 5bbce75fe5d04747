/* k-coherence candidate sets by MRPM preprocessing (internal):
 * mixed-resolution patch matching, Sureka & Narayanan 2012.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_MRPM_H
#define TS_MRPM_H

#include "cancel.h"
#include "pyramid.h"

/* For every pixel of one exemplar pyramid level, the `k` most similar
 * other exemplar neighbourhoods of that level, best first. */
typedef struct
{
  size_t   width;
  size_t   height;
  size_t   k;
  int32_t *index;  /* width * height * k entries: y * width + x at this
                      level, or -1 where fewer than k were found */
} TsCandidateSet;

/* The feature of a centre p at level l is the (2r + 1)^2 patch at l (r =
 * patch_size / 2, shrunk on levels too small for it) plus, for each further
 * compared level j = 1, 2, the (2 rc + 1)^2 patch around p >> j at level
 * l + j (rc = (r + 1) / 2, coordinates clamped). Its squared Euclidean
 * distance ranks the candidates. Defaults chosen by measurement (recall vs.
 * brute force against time): 5, 5, 3, 2, 16, 4, 8, 0, 1. */
typedef struct
{
  size_t patch_size;      /* odd neighbourhood side compared at each level  */
  size_t window;          /* u: side of the search window around children   */
  size_t levels_compared; /* 1..3 consecutive pyramid levels in a feature   */
  size_t exclude_radius;  /* candidates with Chebyshev distance <= this from
                             the pixel itself are skipped (trivial shifts)  */
  size_t pca_dims;        /* search in a PCA projection of this many dims
                             (<= 32, rounded up to a multiple of 4);
                             0 = search with exact distances (slow)         */
  size_t rerank;          /* with PCA: the best k + rerank by projected
                             distance are re-ranked by exact distance       */
  size_t rerank_coarsest; /* the same at the coarsest level, whose brute
                             force ranks far centres by projection too     */
  size_t parent_matches;  /* use at most this many of the parent's matches
                             (best first) as sources; 0 = all               */
  size_t propagation;     /* passes re-ranking the neighbours' matches,
                             shifted: cheap, and raises recall             */
} TsMrpmOptions;

void     ts_mrpm_options_init (TsMrpmOptions *options);

/* Candidate set of `level` of `pyramid` (a working-image pyramid, alpha
 * scaled). `coarser` is the set of level + 1, or NULL: brute force (the
 * coarsest level). Fully transparent pixels (alpha 0) never appear as
 * candidates. Candidates are centres whose patch lies inside the level;
 * pixels near the border get the candidates of their clamped centre.
 * `cancel` (may be NULL) is polled between rows (thread 0 asks its
 * callback); once it is raised the function returns TS_ERROR_CANCELLED.
 * Threads: OpenMP over rows; the result does not depend on the thread
 * count. `options` may be NULL (defaults). */
TsStatus ts_mrpm_level (const TsPyramid       *pyramid,
                        size_t                 level,
                        const TsCandidateSet  *coarser,
                        size_t                 k,
                        const TsMrpmOptions   *options,
                        TsCancel              *cancel,
                        TsCandidateSet        *out);

void     ts_candidate_set_free (TsCandidateSet *set);

/* Patch radius used at `level`: patch_size / 2, shrunk so the patch fits
 * the level. Valid centres are at least this far from every border. */
size_t   ts_mrpm_radius (const TsPyramid *pyramid, size_t level,
                         const TsMrpmOptions *options);

/* Exact squared feature distance between valid centres a and b
 * (y * width + x) of `level`: the distance candidates are ranked by.
 * For tests and diagnostics. */
float    ts_mrpm_distance (const TsPyramid *pyramid, size_t level,
                           const TsMrpmOptions *options, size_t a, size_t b);

#endif
