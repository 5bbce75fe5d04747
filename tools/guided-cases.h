/* Built cases of texture by numbers, shared by test-guided-metrics and
 * benchmarks/guided-regions: three textures' left 48x96 side by side with
 * their label map, and 160x160 targets of discs, 24 px stripes and 10 px
 * slanted lines. Pure C11, no GEGL.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_GUIDED_CASES_H
#define TS_GUIDED_CASES_H

#include "texsynth.h"

#include <stdbool.h>
#include <stdint.h>

#define TS_CASE_STRIP 48
#define TS_CASE_EX_W (3 * TS_CASE_STRIP)
#define TS_CASE_EX_H 96
#define TS_CASE_OUT 160
/* Figures are medians over a number of seeds from TS_CASE_FIRST_SEED
 * (TS_CASE_SEEDS by default, at most TS_CASE_MAX_SEEDS): one seed's
 * coherence of a mostly flat texture (the cracked strip) swings by a
 * factor of 3, and a thin region's figure is a mean over a few hundred
 * pixels of one result. */
#define TS_CASE_SEEDS 3
#define TS_CASE_MAX_SEEDS 16
#define TS_CASE_FIRST_SEED 4

typedef enum { TS_CASE_DISCS, TS_CASE_STRIPES, TS_CASE_LINES, TS_CASE_LAYOUTS } TsCaseLayout;

extern const char *const ts_case_layout_name[TS_CASE_LAYOUTS];

/* Label (0, 1 or 2) of target pixel (x, y). */
uint8_t ts_case_target_label (TsCaseLayout layout, size_t x, size_t y);
/* The exemplar (allocated here; free its pixels) and its labels
 * (TS_CASE_EX_W x TS_CASE_EX_H bytes, the caller's) from three textures;
 * false, with nothing allocated, if one is smaller than 48x96 or memory
 * runs out. */
bool    ts_case_exemplar (const TsImage texture[3], TsImage *exemplar, uint8_t *labels);
/* Strip l of the exemplar as an image of its own (allocated here). */
bool    ts_case_strip (const TsImage *exemplar, size_t l, TsImage *strip);
/* The median of v[0..n-1], n >= 1 (the mean of the middle two if n is
 * even). */
double  ts_case_median (const double *v, size_t n);

/* Median over `seeds` seeds of the coherence of plain syntheses of
 * strip l alone, TS_CASE_OUT square; fills `error` on failure. */
TsStatus ts_case_plain_coherence (const TsImage *exemplar, size_t l, size_t seeds, double *median,
                                  TsError *error);

/* Each seed's label fidelity, edge offset and region coherences
 * (guided-metrics.h) of guided syntheses of `layout`. */
typedef struct
{
  double fidelity[TS_CASE_MAX_SEEDS], offset[TS_CASE_MAX_SEEDS], region[3][TS_CASE_MAX_SEEDS];
} TsCaseFigures;

/* Texture by numbers of `layout` from the exemplar and its labels, in
 * layers or with blended edges, over `seeds` seeds; the first seed's result
 * is left in `first` (TS_CASE_OUT square, the caller's) if not NULL. */
TsStatus ts_case_guided (const TsImage *exemplar, const uint8_t *labels, TsCaseLayout layout,
                         bool blend_edges, size_t seeds, TsCaseFigures *figures, TsImage *first,
                         TsError *error);

#endif
