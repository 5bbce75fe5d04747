/* What the truth-solid files share: the seeded hash, periodic value
 * noise and the renderers of each family of kinds (truth-solids.c,
 * truth-solids-pieces.c, truth-solids-fields.c).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_TRUTH_SOLIDS_INTERNAL_H
#define TS_TRUTH_SOLIDS_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct
{
  size_t   n;    /* the cube's side, in voxels */
  uint32_t seed;
} TruthSolid;

/* Uniform in [0, 1) from the seed, a stream and a key. */
double truth_uniform (const TruthSolid *s, uint32_t stream, uint64_t key);

/* i modulo period, in [0, period). */
size_t truth_wrap (long i, size_t period);

/* Smooth value noise in [0, 1) with `period` lattice cells across the
 * cube, so that it repeats exactly with the volume. */
double truth_value_noise (const TruthSolid *s, uint32_t stream, size_t period, const double p[3]);

/* The whole number of lattice cells across the cube nearest to cells of
 * `spacing` voxels (at least 1). */
size_t truth_lattice_period (const TruthSolid *s, double spacing);

/* A colour value rounded and clamped to a byte. */
uint8_t truth_byte (double v);

/* Kinds drawn as separate or overlapping pieces in a matrix
 * (truth-solids-pieces.c). TRUTH_UNKNOWN if `kind` is not one of them. */
typedef enum
{
  TRUTH_DONE,
  TRUTH_UNKNOWN,
  TRUTH_OUT_OF_MEMORY
} TruthStatus;

TruthStatus truth_render_pieces (const char *kind, const TruthSolid *s, uint8_t *rgb);

/* Kinds drawn from periodic random fields: sponge, random media, marble
 * (truth-solids-fields.c). */
TruthStatus truth_render_fields (const char *kind, const TruthSolid *s, uint8_t *rgb);

/* Dark cells in light walls (truth-solids.c's Voronoi sites, other
 * polarity; truth-solids-pieces.c). */
TruthStatus truth_render_foam (const TruthSolid *s, uint8_t *rgb);

#endif
