/* Solid synthesis internals: the state of one level of the volume, its
 * M-step and E-step, and Kopf et al.'s histogram matching (internal).
 * "The truth solids" in this folder's comments are the ground-truth
 * cells, blobs and grains of benchmarks/truth-solids.h, whose slices are
 * known: the constants chosen on them are tuned to those kinds.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_SOLID_H
#define TS_SOLID_H

#include "engine/indexing.h"
#include "engine/level.h"
#include "exemplar-index.h"

#include <stdint.h>
#include <string.h>

/* Slice orientations, one per axis of the cube. */
#define TS_SOLID_AXES 3
/* Kopf et al. 2007 use 16 bins per channel. */
#define TS_SOLID_HISTOGRAM_BINS 16
/* The E-step visits voxels in this many random batches, refreshing the
 * histogram weights between them: often enough that the weights follow
 * the volume as it changes, each batch still large enough to keep the
 * threads busy. */
#define TS_SOLID_BATCHES 16
/* Below this edge a level's loops run on one thread: the work is too
 * small to repay waking the others, above all on a busy machine. */
#define TS_SOLID_PARALLEL_EDGE 32

/* Colour variance of every whole exemplar neighbourhood of one side
 * (0 where the neighbourhood does not fit), and the variance at which a
 * vote's error counts half (variance-map.c). */
typedef struct
{
  float *variance;
  float  flat;
} TsSolidVarianceMap;

/* Worked out once per pass: `coarse` for the levels above the finest,
 * whose flat variance follows the exemplar's median. */
TsStatus ts_solid_variance_map_build (const TsImage *ex, size_t radius, bool coarse,
                                      TsSolidVarianceMap *map);
void     ts_solid_variance_map_free (TsSolidVarianceMap *map);

/* From one pass over `ex`'s opaque pixels: `phase`, the lightness that
 * splits them into their two phases (dark mortar and light stones, spots
 * and ground), midway between the 5th and 95th lightness percentiles;
 * and `joint`, below which pixels are joints for the cell structure, a
 * quarter of the way from the 5th to the 95th percentile, below the
 * darkest stones' lightness (phase-split.c). */
void ts_solid_splits (const TsImage *ex, float *phase, float *joint);

/* Whether a working-format pixel lies on the light side of `split`
 * (transparent pixels lie on neither). */
static inline bool
ts_solid_is_light (const float *pixel, float split)
{
  return pixel[3] > 0.0f && pixel[0] >= split;
}

/* Calls `piece` once for each 4-connected piece of the nonzero pixels
 * of a w x h mask, with the piece's pixels in the order a depth-first
 * walk finds them (pieces.c). */
typedef void (*TsSolidPieceFunc) (const size_t *pixels, size_t area, void *data);
TsStatus ts_solid_mask_pieces (const uint8_t *mask, size_t w, size_t h, TsSolidPieceFunc piece,
                               void *data);

/* The phase guide (phase-guide.c) and the walls at necks (neck-walls.c),
 * at the finest level of the default path, when the exemplar's largest
 * 4-connected light piece holds at most TS_SOLID_PIECES_APART of its
 * light pixels, or else its largest dark piece of its dark pixels.
 * Half: when one piece holds most of the phase, the phase is a connected
 * ground, not pieces. The exact bound is fitted to the bundled
 * exemplars, two of which read just either side of it; see
 * docs/design.md, Known limits. */
#define TS_SOLID_PIECES_APART 0.5
/* A vote whose source's signed distance to the phase boundary differs
 * by z from the voxel's weighs 1 / (1 + (z / SIGMA)^2); distances are
 * clipped to +-CLIP first (voxels or pixels): only the two pixels either
 * side of a boundary say where it lies, and a vote from across it (z up
 * to 4) keeps about a third of its weight, so the guide steers without
 * vetoing. Chosen on the truth solids (docs/design.md, Known limits). */
#define TS_SOLID_PHASE_SIGMA 3.0f
#define TS_SOLID_PHASE_CLIP 2.0f
/* Two basins of the phase in pieces stay apart where both peaks rise
 * this far (voxels of distance to the ground) above the voxel where they
 * meet (neck-walls.c): spots and grains TS_SOLID_NECK_HEIGHT, stones
 * TS_SOLID_STONE_NECK_HEIGHT. Stones touch along flat faces, so the
 * start merges them across low necks that only the lower height parts;
 * spots keep the higher one, where lower walls cost coherence. Both were
 * chosen on the truth solids (docs/design.md, Known limits). */
#define TS_SOLID_NECK_HEIGHT 1.5f
#define TS_SOLID_STONE_NECK_HEIGHT 1.0f
/* See ts_solid_exemplar_stones. */
#define TS_SOLID_STONE_DEPTH 2.0f
#define TS_SOLID_STONE_SHARE 0.4


/* The Sobel gradient of the lightness at interior pixel (x, y), in
 * *gx, *gy; false where the 3 x 3 block holds a transparent pixel. */
static inline bool
ts_solid_sobel (const TsImage *ex, size_t x, size_t y, double *gx, double *gy)
{
  float l[3][3];
  bool opaque = true;

  for (size_t j = 0; j < 3; j++)
    for (size_t i = 0; i < 3; i++)
      {
        const float *p = ex->pixels + ((y + j - 1) * ex->width + x + i - 1) * TS_CHANNELS;
        l[j][i] = p[0];
        opaque = opaque && p[3] > 0.0f;
      }
  *gx = (l[0][2] + 2.0 * l[1][2] + l[2][2]) - (l[0][0] + 2.0 * l[1][0] + l[2][0]);
  *gy = (l[2][0] + 2.0 * l[2][1] + l[2][2]) - (l[0][0] + 2.0 * l[0][1] + l[0][2]);
  return opaque;
}

/* Which way round one orientation reads its exemplar (handedness.c).
 * With one image on all three orientations and its edges' energy-
 * weighted sin 2t below -TS_SOLID_MIRROR_BIAS (lines falling more than
 * rising), the slices across TS_SOLID_MIRRORED_AXIS read it mirrored
 * left to right. Isotropic exemplars reach about -0.2 by chance at
 * 64^2 and less at larger sizes; the bound sits above that, so only a
 * clear slant flips; among the bundled images only granite1 (-0.32)
 * passes it (docs/design.md, Known limits). */
#define TS_SOLID_MIRRORED_AXIS 0
#define TS_SOLID_MIRROR_BIAS 0.25
double ts_solid_diagonal_bias (const TsImage *ex);
void   ts_solid_mirror_image (TsImage *image);
/* Sources of `axis` back to the unmirrored exemplar's pixels. */
void   ts_solid_unmirror_sources (TsSolidSource *sources, size_t voxels, int axis, size_t width);

/* Whether no pixel's alpha lies below 1, as the cell structure needs
 * (cell-choice.c; params.c refuses an explicit choice without it). */
bool ts_solid_fully_opaque (const TsImage *ex);
/* `params` with the cell structure's automatic choice made
 * (cell-choice.c): on or off. The engine's steps see only these. */
void ts_solid_resolve_params (const TsSolidParams *params, const TsImage *const exemplars[3],
                              TsSolidParams *resolved);
/* Whether one exemplar is cells for the automatic choice: opaque, its
 * light phase in stones, their joints thin (`*thin_share`: the share of
 * the joints' middle line within 1.5 pixels of a stone) and its edges
 * not along the axes (`*axis_share`: the share of its gradient energy
 * within 10 degrees of them); both 0 if not looked at. */
TsStatus ts_solid_cells_in_joints (const TsImage *ex, bool *cells, double *thin_share,
                                   double *axis_share);

/* Whether the finest level weighs votes by the position histogram
 * (position-histogram.c): with histogram matching, and not with the cell
 * structure (synthesize.c, TS_SOLID_POSITION_WEIGHT). Resolved params
 * only. */
bool ts_solid_uses_positions (const TsSolidParams *params);

/* The cell structure guide (cell-guide.c). A signed distance d (pixels,
 * positive inside a cell) rides in the working alpha channel as
 * TS_ALPHA_SCALE + code (d): slope NEAR within KNEE pixels of a wall,
 * FAR beyond, because where the walls lie matters more than how deep in
 * its cell a pixel is. The coarser levels lay the cells out: steep
 * within a few pixels of a wall, gentle beyond, so a cell's depth still
 * counts a little. The finest level draws the joints: very steep within
 * one pixel, so a joint pixel only matches a joint pixel, and nearly
 * flat beyond, so the stones' insides match freely (fewer specks and
 * merged stones than with one slope). The values were chosen on the
 * truth solids (docs/design.md, Known limits). */
#define TS_SOLID_CELL_GUIDE_COARSE_NEAR 8.0f
#define TS_SOLID_CELL_GUIDE_COARSE_FAR  2.0f
#define TS_SOLID_CELL_GUIDE_COARSE_KNEE 3.0f
#define TS_SOLID_CELL_GUIDE_FINEST_NEAR 12.0f
#define TS_SOLID_CELL_GUIDE_FINEST_FAR  1.0f
#define TS_SOLID_CELL_GUIDE_FINEST_KNEE 1.0f

typedef struct
{
  size_t    sections, area, dark; /* over the exemplars: stone sections,
                                     pixels, and pixels of the dark phase */
  size_t    edge;                 /* of the finest level                */
  float    *seeds;                /* seed_count x 3, in finest voxels   */
  size_t    seed_count, buckets;  /* buckets^3 cells of the seed grid   */
  size_t   *bucket_start;         /* buckets^3 + 1 offsets into `order` */
  uint32_t *order;                /* seeds sorted by bucket             */
  float    *field;                /* field_edge^3 distances to a wall   */
  uint8_t  *slant;                /* finest level: field_edge^3 x 3, the
                                     share (of 255) of the wall's normal
                                     in the slices across each axis; NULL
                                     at the coarser levels             */
  size_t    field_edge;
  uint32_t *cell_of;              /* finest level: each voxel's cell (its
                                     nearest seed); NULL at the coarser */
  float    *cell_tone;            /* seed_count: each cell's tone, its
                                     light voxels' mean lightness matched
                                     to `shades` (cell-tone.c)          */
  double   *tone_sum;             /* seed_count each: cell-tone.c's sums */
  uint32_t *tone_count;           /* and ranking, allocated with the    */
  struct TsSolidRankedCell *ranked; /* seeds                            */
  float    *shades;               /* every exemplar stone pixel's section
                                     tone, sorted once seeded           */
  size_t    shade_count;
} TsSolidCellGuide;

/* Writes the exemplar's signed distances to its mortar into `working`'s
 * alpha (the coarser levels' code) and adds its sections and pixels to
 * `guide`. Each pixel of a stone section (a 4-connected piece of at
 * least 4 pixels above the joint split, less the joints' dark rims)
 * gets its section's mean lightness in *stone_tone (allocated), NAN
 * elsewhere: what cell tones compare (cell-tone.c). */
TsStatus ts_solid_cell_guide_exemplar (TsImage *working, TsSolidCellGuide *guide,
                                       float **stone_tone, TsCancel *cancel);
/* Turns the finest exemplar level's alpha to the finest level's code. */
void     ts_solid_cell_guide_finest (TsImage *finest);
/* Draws the Voronoi seeds for a volume of edge `edge`, once the
 * exemplars are in. */
TsStatus ts_solid_cell_guide_seed (TsSolidCellGuide *guide, size_t edge, uint32_t seed);
/* The distances of a level of edge n (polls `cancel`). */
TsStatus ts_solid_cell_guide_level (TsSolidCellGuide *guide, size_t n, TsCancel *cancel);
/* Writes the level's distances into the alpha of `value`; at the finest
 * level, as measured in the slices across `axis`. */
void     ts_solid_cell_guide_apply (const TsSolidCellGuide *guide, float *value, int axis);
void     ts_solid_cell_guide_free (TsSolidCellGuide *guide);

/* Cell tones (cell-tone.c), at the finest level with the cell guide: a
 * vote for a stone whose mean lightness lies z spreads (L* units) from
 * its cell's weighs 1 / (1 + weight z^2) (estep.c). A stone one spread
 * off (6 L*, a plainly visible step in tone) keeps half its vote, so
 * tone decides between stones that match about as well but does not
 * override shape; a narrower spread or a larger weight cost coherence.
 * Chosen on the cells truth (docs/design.md, Known limits). */
#define TS_SOLID_TONE_WEIGHT 1.0f
#define TS_SOLID_TONE_SPREAD 6.0f

/* Which phase of an exemplar, at its phase split, lies in separate
 * pieces (phase-guide.c): the light one is asked first. */
typedef enum
{
  TS_SOLID_NO_PIECES,
  TS_SOLID_LIGHT_PIECES,
  TS_SOLID_DARK_PIECES
} TsSolidPieces;

/* One slice orientation at one level. */
typedef struct
{
  const TsImage        *exemplar;    /* working exemplar level; NULL = free */
  const int32_t        *opaque;      /* indices of pixels with alpha > 0    */
  size_t                opaque_count;
  float                *excess;      /* histogram excess per exemplar pixel, or NULL */
  const TsSolidIndex   *index;       /* all neighbourhoods of the pass's size, or NULL */
  const TsSolidVarianceMap *variance; /* of the pass's neighbourhoods   */
  uint32_t             *position_count; /* copies per exemplar pixel in
                                           `chosen` (position-histogram.c), or NULL */
  float                 phase_split; /* lightness between its two phases (phase-split.c) */
  float                 joint_split; /* with the cell structure, the joints' (phase-split.c);
                                        else -INFINITY */
  const float          *stone_tone;  /* finest level with the cell guide:
                                        per pixel, see ts_solid_cell_guide_exemplar */
  const float          *phase_distance; /* with the phase guide: per pixel
                                           (phase-guide.c); else NULL */
} TsSolidView;

typedef struct
{
  size_t       n;          /* edge of the cube at this level            */
  bool         periodic;
  float       *value;      /* n^3 voxels, working format (alpha scaled) */
  int32_t     *source[TS_SOLID_AXES]; /* exemplar index per voxel and
                                          orientation; NULL where free */
  TsSolidSource *chosen;   /* finest level, if asked: the vote each value
                              copies (orientation and index); else NULL */
  TsSolidView  view[TS_SOLID_AXES];
  float        continuation; /* E-step weight per continued neighbour (estep.c) */
  float        position_weight; /* of the position histogram's excess, 0 = off;
                                   needs `chosen` (position-histogram.c) */
  bool         no_lone_voxels; /* the E-step's lone-voxel rule (estep.c) */
  float        shear;      /* the E-step's shear rule (estep.c): divisor per
                              sheared neighbour, 0 = off */
  const uint32_t *cell_of;  /* the cell guide's, at the finest level, or NULL */
  const float  *cell_tone;  /* per cell, with cell_of (cell-tone.c)    */
  const float  *phase_field; /* with the phase guide: per voxel
                                (phase-guide.c); else NULL */
  TsSolidPieces kept_apart; /* the phase whose pieces the E-step keeps
                               apart (piece-topology.c), or none */
  float        pieces_split; /* with kept_apart, the lightness between
                                the pieces and their ground */
} TsSolidLevel;

/* Adds an exemplar's stone pixels' section tones (`stone_tone`, NAN off
 * the stones) to guide->shades. */
TsStatus ts_solid_cell_tone_exemplar (TsSolidCellGuide *guide, const float *stone_tone,
                                      size_t pixels);
/* Once the seeds are drawn: sorts the shades and allocates the per-cell
 * tones, sums and ranking. */
TsStatus ts_solid_cell_tone_alloc (TsSolidCellGuide *guide);
/* Each cell's tone into guide->cell_tone (NAN for a cell without light
 * voxels), which level->cell_tone then points at: its light voxels' mean
 * lightness (above the joint split of the level's first exemplar),
 * matched by rank to the shades. */
void     ts_solid_cell_tones (TsSolidCellGuide *guide, TsSolidLevel *level);

/* The first orientation whose view shows the same exemplar as `axis`'s:
 * per-exemplar data (histogram counts, excesses) is kept once, there. */
static inline int
ts_solid_view_owner (const TsSolidLevel *level, int axis)
{
  for (int b = 0; b < axis; b++)
    if (level->view[b].exemplar == level->view[axis].exemplar)
      return b;
  return axis;
}

/* The E-step's shear rule (estep.c): a vote weighs 1 + this times less
 * per neighbour across its slice that continues its copy shifted by a
 * pixel, the mark of a diagonal streak. Streaks fall most between 1 and
 * 4 and little beyond. Off with the cell structure: the guide shapes
 * the stones, whose plane faces cross the slices as sheared copies of
 * their joint lines, and the rule turned their edges towards the axes. */
#define TS_SOLID_SHEAR 4.0f
/* ...at the finest levels only, this many: at the coarser ones it cost
 * sharpness and removed no streaks, and at the finest alone streaks
 * came back. */
#define TS_SOLID_SHEAR_LEVELS 2

/* A matched slice neighbourhood: exemplar centre (-1 = none) and robust
 * vote weight. */
typedef struct
{
  int32_t centre;
  float   weight;
} TsSolidMatch;

/* Whether two pixels are bit for bit the same, as memcmp () == 0 but
 * inline: the E-step tests several pairs per vote, and the library calls
 * took about 5 % of a 128^3 run. */
static inline bool
ts_solid_same_pixel (const float *a, const float *b)
{
  uint64_t x[2], y[2];

  _Static_assert (sizeof x == TS_CHANNELS * sizeof (float), "a pixel is 16 bytes");
  memcpy (x, a, sizeof x);
  memcpy (y, b, sizeof y);
  return ((x[0] ^ y[0]) | (x[1] ^ y[1])) == 0;
}

/* qsort's order of floats, ascending (variance-map.c, cell-tone.c). */
static inline int
ts_solid_compare_floats (const void *a, const void *b)
{
  float x = *(const float *) a, y = *(const float *) b;
  return (x > y) - (x < y);
}

/* The in-slice axes (u, v) of the slices orthogonal to `axis`. */
static inline void
ts_solid_plane_axes (int axis, int *u, int *v)
{
  *u = axis == 0 ? 1 : 0;
  *v = axis == 2 ? 1 : 2;
}

static inline size_t
ts_solid_stride (size_t n, int axis)
{
  return axis == 0 ? 1 : (axis == 1 ? n : n * n);
}

/* The index of voxel xyz's face neighbour one step down (side 0) or up
 * (side 1) along `axis`, wrapped or mirrored at the border as the level
 * says: the E-step and the speck pass (specks.c) must see the same. */
static inline size_t
ts_solid_face_neighbour (const TsSolidLevel *level, const size_t xyz[3], int axis, int side)
{
  size_t n = level->n, q[3] = { xyz[0], xyz[1], xyz[2] };

  q[axis] = ts_border_index ((ptrdiff_t) q[axis] + (side ? 1 : -1), n, level->periodic);
  return (q[2] * n + q[1]) * n + q[0];
}

/* Slices along its own axis that an orientation searches in one
 * iteration: every TS_SOLID_SLICE_SPACING-th. With every slice searched,
 * neighbouring slices find the same exemplar pieces and the volume
 * extrudes them; on a sparse grid in all three directions the voxels
 * between are shaped by the other orientations (Kopf et al. 2007). */
#define TS_SOLID_SLICE_SPACING 2

/* Whether an orientation whose searched slices start at `t_offset`
 * searches slice t this iteration (only those have matches). */
static inline bool
ts_solid_slice_searched (size_t t, size_t t_offset)
{
  return t % TS_SOLID_SLICE_SPACING == t_offset % TS_SOLID_SLICE_SPACING;
}

/* Slices an orientation's matches have room for, whatever its offset. */
static inline size_t
ts_solid_match_slices (size_t n)
{
  return (n + TS_SOLID_SLICE_SPACING - 1) / TS_SOLID_SLICE_SPACING;
}

/* Where the match of searched slice t, grid centre (ju, jv) is stored:
 * slice by slice, u fastest. The E-step visits a random sixteenth of the
 * voxels per batch, so the matches covering one voxel should share cache
 * lines, not those of the voxels next to it. */
static inline size_t
ts_solid_match_index (size_t cu, size_t cv, size_t t, size_t ju, size_t jv)
{
  return (t / TS_SOLID_SLICE_SPACING * cv + jv) * cu + ju;
}

/* The passes of volume level `level` of `levels`, of edge n (plan.c):
 * the 2D schedule for the smallest exemplar's ex_w x ex_h at that
 * level, with the solid engine's neighbourhood sizes, iterations and
 * spacings; `joints`: the exemplar's light phase lies in separate pieces
 * (ts_solid_phase_plan), whose joints the finest level iterates
 * longer to close. */
void ts_solid_plan_level (const TsSolidParams *sp, size_t level, size_t levels, size_t n,
                          size_t ex_w, size_t ex_h, bool joints, TsLevelPlan *plan);
/* Leaves of the exemplar index a query visits at `quality` (1 .. 10). */
size_t ts_solid_index_leaves (int quality);

/* M-step of one orientation: the best exemplar neighbourhood for the
 * slice neighbourhood of every centre (the slices t = t_offset modulo
 * TS_SOLID_SLICE_SPACING, sparse grid gu x gv within them), among those
 * that continue the slice neighbours' sources and, with the view's index,
 * the nearest of all exemplar neighbourhoods (visiting `leaves` of its
 * leaves, ts_solid_index_leaves). `matches` has ts_solid_match_slices (n) *
 * gu->centres * gv->centres entries (ts_solid_match_index). */
TsStatus ts_solid_mstep (const TsSolidLevel *level, int axis, const TsAxisGrid *gu,
                         const TsAxisGrid *gv, const TsPass *pass, size_t leaves,
                         size_t t_offset, uint32_t seed_stream, TsSolidMatch *matches,
                         TsCancel *cancel);

/* --- starts of a level (start.c) ------------------------------------------ */

/* Coarsest level: random exemplar blocks of side at most `block` per
 * orientation, tiling the period at a random phase per axis; each
 * voxel's value is one orientation's colour drawn at random, or with
 * `majority` the one nearest their mean. */
void ts_solid_start_random_blocks (TsSolidLevel *l, size_t level, size_t block, uint32_t seed,
                                   bool majority);
/* Finer level: each voxel's sources are its parent's in `coarser`,
 * refined to the child pixel of the finer exemplar level; its value is
 * that of the orientation that won the parent. Every voxel is written
 * even after a stop (the finest level is the caller's volume, written
 * whole or not at all): `cancel` is only asked, for prompt reports. */
void ts_solid_start_from_coarser (TsSolidLevel *l, const TsSolidLevel *coarser, size_t level,
                                  uint32_t seed, TsCancel *cancel);

/* --- histogram matching --------------------------------------------------- */

typedef struct
{
  float   lo[3], scale[3];                             /* bin = (v - lo) * scale */
  float   target[3][TS_SOLID_HISTOGRAM_BINS];          /* exemplars' density      */
  int64_t count[3][TS_SOLID_HISTOGRAM_BINS];           /* voxels per bin          */
  int64_t total;                                       /* opaque voxels counted   */
} TsSolidHistogram;

typedef int64_t TsSolidHistogramDelta[3][TS_SOLID_HISTOGRAM_BINS];

/* Bins and target densities from the opaque pixels of the level's
 * exemplars, then the counts of the level's volume. */
void ts_solid_histogram_init (TsSolidHistogram *h, const TsSolidLevel *level);
/* Records a voxel's change from `before` to `after` (working values). */
void ts_solid_histogram_move (const TsSolidHistogram *h, TsSolidHistogramDelta delta,
                              const float *before, const float *after);
void ts_solid_histogram_apply (TsSolidHistogram *h, TsSolidHistogramDelta delta);
/* Every exemplar pixel's excess in every view: the sum over channels of
 * how far the volume's density in the pixel's bin exceeds the target
 * (0 = not over-represented). */
void ts_solid_histogram_excess (const TsSolidHistogram *h, TsSolidLevel *level);

/* Counts into the views' position_count how often `chosen` copies each
 * exemplar pixel; the E-step then keeps the counts up to date. */
void ts_solid_position_count (TsSolidLevel *level);
/* One voxel's copy moves from `before` to `after`; safe from several
 * threads at once. */
void ts_solid_position_move (TsSolidLevel *level, TsSolidSource before, TsSolidSource after);
/* Adds to every exemplar pixel's excess (views with one) position_weight
 * times how much more often than uniformly the counts say it is copied. */
void ts_solid_position_excess (TsSolidLevel *level);

/* The first orientation, x then y then z, whose exemplar is given
 * (exemplar_of[a] >= 0; there is always one): the volume-wide rules use
 * its exemplar's splits. */
static inline int
ts_solid_first_axis (const int exemplar_of[TS_SOLID_AXES])
{
  return exemplar_of[0] >= 0 ? 0 : exemplar_of[1] >= 0 ? 1 : 2;
}
/* The first axis's view. */
const TsSolidView *ts_solid_first_view (const TsSolidLevel *level);

/* Voxel `to` takes voxel `from`'s value, recorded vote and sources, so
 * aligned maps stay aligned (specks.c, neck-walls.c). */
static inline void
ts_solid_copy_voxel (TsSolidLevel *level, size_t to, size_t from)
{
  memcpy (level->value + to * TS_CHANNELS, level->value + from * TS_CHANNELS,
          TS_CHANNELS * sizeof (float));
  if (level->chosen)
    level->chosen[to] = level->chosen[from];
  for (int a = 0; a < TS_SOLID_AXES; a++)
    if (level->source[a])
      level->source[a][to] = level->source[a][from];
}

/* After the finest level: each small
 * face-connected piece on one side of the phase split copies a face
 * neighbour on the other side (specks.c). */
TsStatus ts_solid_remove_specks (TsSolidLevel *level);

/* At the finest level's start, with the phase guide: the voxels where
 * two basins of the phase in pieces meet, both peaks rising at least
 * `neck_height` voxels above them, and their face neighbours of that
 * phase, copy the nearest voxel of the other phase (neck-walls.c). */
TsStatus ts_solid_wall_necks (TsSolidLevel *level, float split, TsSolidPieces pieces,
                              float neck_height, TsCancel *cancel);
TsSolidPieces ts_solid_phase_in_pieces (const TsImage *ex, float split);
/* Whether the exemplar's light phase, at its phase split `split`
 * (ts_solid_splits), is stones: at least TS_SOLID_STONE_SHARE of its
 * opaque light pixels lie TS_SOLID_STONE_DEPTH pixels or more from the
 * dark phase. The E-step keeps only stones apart (piece-topology.c):
 * thin veins and small grains, whose pieces in a slice may join in the
 * volume, came out blunter with the rule. Stones are wider than twice
 * the depth, so much of them lies deep; veins and grains are thin, so
 * little does. The share's bound is fitted to the bundled exemplars and
 * has a small margin; see docs/design.md, Known limits. */
TsStatus ts_solid_exemplar_stones (const TsImage *ex, float split, bool *stones);
/* Every pixel's clipped signed distance (light positive) to the phase
 * boundary at `split`, in a new array. */
TsStatus ts_solid_phase_distances (const TsImage *ex, float split, float **out);
/* The same for every voxel of the level's values (polls `cancel`). */
TsStatus ts_solid_phase_field (const TsSolidLevel *level, float split, float **out,
                               TsCancel *cancel);
/* Up to this many grids go to one ts_solid_distance_transforms. */
#define TS_SOLID_MAX_POLLED_GRIDS 2
/* ts_distance_transform of each of `count` grids, while the caller's
 * thread asks `cancel` (may be NULL) midway (distance-polled.c). */
TsStatus ts_solid_distance_transforms (float *const grids[], size_t count, const size_t dims[3],
                                       const bool wrap[3], TsCancel *cancel);

/* The phase guide's plan for one run on the default path (phase-plan.c). */
typedef struct
{
  TsSolidPieces pieces;  /* the first view's finest exemplar's phase in
                            pieces; none: no phase guide */
  bool          stones;  /* its light pieces are stones, kept apart */
  float         neck_height; /* the walls' (ts_solid_wall_necks) */
  float         split[TS_SOLID_AXES]; /* per distinct exemplar: the split
                                         between its pieces and their
                                         ground, the joint split for stones */
  size_t        exemplars, first;     /* how many; the first view's */
  float        *distance[TS_SOLID_AXES]; /* per exemplar, once started */
  float        *field;                /* per voxel, once started */
} TsSolidPhasePlan;

/* The plan from the finest levels of the distinct exemplars, which
 * orientation a reads as exemplar_of[a] (-1: none). */
TsStatus ts_solid_phase_plan (TsSolidPhasePlan *plan, const TsImage *const finest[],
                              size_t exemplars, const int exemplar_of[TS_SOLID_AXES]);
/* At the finest level's start, if the plan has pieces: walls at the
 * start's necks, the phase guide's distances and field, and for stones
 * the E-step's rule, in `level`, whose orientation a reads exemplar
 * exemplar_of[a] (-1: none). */
TsStatus ts_solid_phase_plan_start (TsSolidPhasePlan *plan, TsSolidLevel *level,
                                    const TsImage *const finest[],
                                    const int exemplar_of[TS_SOLID_AXES], TsCancel *cancel);
void     ts_solid_phase_plan_free (TsSolidPhasePlan *plan);

/* Whether voxel xyz, turned into the phase in pieces (the light one at
 * `split` if `light_pieces`), would join two pieces its 18-neighbourhood
 * holds apart; only voxels outside the E-step's current batch count
 * (piece-topology.c). */
bool ts_solid_joins_pieces (const TsSolidLevel *level, const size_t xyz[3], const uint8_t *batch_of,
                            uint8_t batch, float split, bool light_pieces);

/* --- E-step ---------------------------------------------------------------- */

/* Whether the E-step reads each voxel's face neighbours: for
 * continuation, the lone-voxel rule or the shear rule. */
static inline bool
ts_solid_reads_face_neighbours (const TsSolidLevel *level)
{
  return level->continuation > 0.0f || level->no_lone_voxels || level->shear > 0.0f;
}

/* Voxels whose `batch_of` entry equals `batch` become the vote of the
 * best-matched slice neighbourhood covering them (`matches` of the
 * orientations' M-steps, with their `t_offset`s; robust weight, lowered
 * by the histogram excess); each orientation's source follows its own
 * best vote, and `chosen` (if any) records the vote; with a position
 * weight the position counts follow it. With `histogram`, changes are
 * added to `delta`. Returns the number of voxels whose value changed.
 * Polls `cancel` per row of voxels; after a stop the rest of the rows
 * keep their values. */
size_t ts_solid_estep (TsSolidLevel *level, const TsAxisGrid *gu, const TsAxisGrid *gv,
                       TsSolidMatch *const matches[TS_SOLID_AXES],
                       const size_t t_offset[TS_SOLID_AXES], const uint8_t *batch_of,
                       uint8_t batch, const TsSolidHistogram *histogram,
                       TsSolidHistogramDelta delta, TsCancel *cancel);
/* Asks for the cache lines the E-step's vote for voxel p will read and
 * write (estep-prefetch.c). */
void ts_solid_prefetch_voxel (const TsSolidLevel *level, const TsAxisGrid *gu, const TsAxisGrid *gv,
                              TsSolidMatch *const matches[TS_SOLID_AXES],
                              const size_t t_offset[TS_SOLID_AXES], size_t p);

#endif
