/* texsynth: example-based texture synthesis engine (public API).
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Plain C11, no GEGL/GIMP types. Images are CIE Lab (D50) with alpha,
 * 4 floats per pixel in the order L, a, b, alpha (L 0..100, alpha 0..1),
 * row-major, no padding: exactly babl's "CIE Lab alpha float".
 *
 * Every function is reentrant: the engine keeps no global mutable state, so
 * several syntheses may run at once from different threads.
 */
#ifndef TEXSYNTH_H
#define TEXSYNTH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Floats per pixel: three colour channels and alpha. */
#define TS_CHANNELS 4
/* Ranges the parameters are checked against. An output of the largest
 * side already holds 4 GiB of floats. */
#define TS_MAX_OUTPUT_SIDE 16384
#define TS_MIN_QUALITY 1
#define TS_MAX_QUALITY 10
#define TS_MIN_PATCH_SIZE 3
#define TS_MAX_PATCH_SIZE 31
#define TS_MAX_ITERATIONS 100
#define TS_MESSAGE_SIZE 256

typedef enum
{
  TS_OK = 0,
  TS_ERROR_INVALID_ARGUMENT,     /* NULL pointer or inconsistent image    */
  TS_ERROR_BAD_PARAMETER,        /* a parameter is out of its range       */
  TS_ERROR_EMPTY_EXEMPLAR,       /* exemplar has no pixels                */
  TS_ERROR_TRANSPARENT_EXEMPLAR, /* every exemplar pixel has alpha 0      */
  TS_ERROR_EXEMPLAR_TOO_SMALL,   /* smaller than the smallest neighbourhood */
  TS_ERROR_TOO_LARGE,            /* would need more memory than allowed   */
  TS_ERROR_OUT_OF_MEMORY,        /* an allocation failed                  */
  TS_ERROR_CANCELLED,            /* the progress callback asked to stop   */
  TS_ERROR_IO,                   /* a file could not be read or written   */
  TS_ERROR_BAD_FILE,             /* a file is truncated or malformed      */
  TS_ERROR_NOTHING_TO_SAMPLE     /* no whole patch of known pixels to copy */
} TsStatus;

/* A short, static, human-readable description of a status. */
const char *ts_status_string (TsStatus status);

/* Details of a failure: the status and a message that says what was wrong
 * and what to do (e.g. how much memory an output would need). */
typedef struct
{
  TsStatus status;
  char     message[TS_MESSAGE_SIZE];
} TsError;

/* A Lab+alpha float image; `pixels` holds width * height * TS_CHANNELS
 * floats. The engine never frees caller images. */
typedef struct
{
  size_t width;
  size_t height;
  float *pixels;
} TsImage;

/* Progress in [0, 1] with a short stage name. Return false to cancel:
 * the engine then stops soon and returns TS_ERROR_CANCELLED. */
typedef bool (*TsProgressFunc) (double fraction, const char *stage, void *user_data);

/* --- Guides: a layout the synthesis follows (common/engine/guide*.c) ---
 * Texture by numbers and style transfer (Hertzmann et al. 2001): each
 * output neighbourhood is matched to exemplar neighbourhoods on its
 * colours and, times `weight`, on how the target guide around it agrees
 * with the exemplar guide around the candidate. */
#define TS_MAX_GUIDE_CHANNELS 3
/* Labels are kept in a byte; a label map rarely has more than a few. */
#define TS_MAX_GUIDE_LABELS 32
#define TS_MAX_GUIDE_WEIGHT 100.0

typedef enum
{
  TS_GUIDE_AUTO = 0, /* labels when the exemplar guide has at most
                        TS_MAX_GUIDE_LABELS distinct values and most
                        target pixels take one of them, else values   */
  TS_GUIDE_LABELS,   /* equal or not: flat colours, indexed maps      */
  TS_GUIDE_VALUES    /* squared differences: heights, sketches, photos */
} TsGuideCompare;

typedef struct
{
  size_t         channels;       /* floats per guide pixel, 1 .. 3        */
  /* Aligned with the exemplar (its size), or NULL for style transfer:
   * the guides are then the exemplar's L / 100 and the target's (one
   * channel, e.g. the photo to restyle's L / 100), the target's moved to
   * the exemplar's mean and spread of L. */
  const float   *exemplar_guide;
  const float   *target_guide;   /* output_width x output_height pixels  */
  TsGuideCompare compare;
  double         weight;         /* 0 .. TS_MAX_GUIDE_WEIGHT: at 1 a guide
                                    pixel that disagrees costs as much as
                                    two unrelated texture pixels; 0
                                    ignores the guides                    */
  /* Labels only. false (the default): each label's region is a plain
   * synthesis of that label's texture alone, cut at the target's label
   * edges, so regions of any width keep their texture (the weight only
   * says whether the guides count). true: one guided optimization over
   * the whole output, whose textures blend across label edges as they do
   * in the exemplar, but regions narrower than about 30 px come out less
   * coherent than their texture alone. */
  bool           blend_edges;
} TsGuides;

/* Defaults: one channel, AUTO, weight TS_DEFAULT_GUIDE_WEIGHT, no data. */
#define TS_DEFAULT_GUIDE_WEIGHT 1.0
void ts_guides_init (TsGuides *guides);

typedef struct
{
  size_t   output_width;       /* 1 .. TS_MAX_OUTPUT_SIDE                     */
  size_t   output_height;      /* 1 .. TS_MAX_OUTPUT_SIDE                     */
  bool     wrap_x;             /* output neighbourhoods wrap horizontally:    */
  bool     wrap_y;             /*   the result tiles seamlessly that way      */
  int      quality;            /* 1 .. 10; k = quality + 1 candidates/pixel  */
  uint32_t seed;               /* same seed, same result, any thread count   */
  int      patch_size;         /* 0 = automatic; else odd, 3 .. 31: size of the
                                  large neighbourhood of the first iterations */
  int      fine_patch_size;    /* 0 = automatic; else odd, 3 .. patch_size   */
  int      max_iterations;     /* 0 = automatic; else 1 .. 100 per size/level */
  bool     histogram_matching; /* Kopf et al. 2007 vote re-weighting         */
  size_t   memory_limit;       /* bytes; 0 = default (a quarter of RAM, at
                                  least 1 GiB)                                */

  /* Optional: start the finest level from these exemplar coordinates
   * (2 int32 per output pixel, x then y) instead of random ones, e.g. the
   * identity map to re-synthesise an image from itself. */
  const int32_t *initial_source;
  /* Optional, with `initial_source`: one weight per output pixel in [0, 1];
   * a data term that keeps pixels with weight near 1 at their initial
   * source (weight 1 never changes the pixel, 0 leaves it free). */
  const float   *preserve;

  /* Optional debug output: if not NULL, receives 2 int32 per output pixel,
   * the exemplar (x, y) each output pixel was copied from. */
  int32_t *source_map;

  /* Optional: guides the output's layout follows (see TsGuides). With
   * histogram matching, a guided output matches the exemplar's parts in
   * the shares the target asks for, not the whole exemplar's. Tileable
   * guided outputs keep the target's layout (no roll of tile edges). */
  const TsGuides *guides;
} TsParams;

/* Fill `params` with the defaults (512x512, quality default, seed 0, ...). */
void ts_params_init (TsParams *params);

/* Check `params` against `exemplar`. On failure fills `error` (may be NULL)
 * and returns its status. Every entry point calls this first. */
TsStatus ts_params_validate (const TsParams *params,
                             const TsImage  *exemplar,
                             TsError        *error);

/* Whether params->guides (checked as ts_params_validate does) compare as
 * labels: TS_GUIDE_AUTO answers for the guides given. */
bool ts_guides_use_labels (const TsParams *params, const TsImage *exemplar);

/* Peak memory a synthesis would need, in bytes. */
TsStatus ts_estimate_memory (const TsParams *params,
                             const TsImage  *exemplar,
                             size_t         *bytes,
                             TsError        *error);

/* Synthesise into `output`, which the caller allocated with
 * params->output_width x params->output_height pixels. On any failure
 * `output` is left untouched. `progress` may be NULL. */
TsStatus ts_synthesize (const TsParams *params,
                        const TsImage  *exemplar,
                        TsImage        *output,
                        TsProgressFunc  progress,
                        void           *user_data,
                        TsError        *error);

/* --- Matching on more than colour ------------------------------------- */

/* A map aligned with the exemplar (same size): `channels` floats per pixel
 * (1 to TS_MAX_FEATURE_CHANNELS), e.g. a height map, a normal map or a
 * mask, in [0, 1]. */
#define TS_MAX_FEATURE_CHANNELS 4
#define TS_MAX_FEATURE_WEIGHT 10.0
typedef struct
{
  size_t       width;
  size_t       height;
  size_t       channels;
  const float *values;
} TsFeatureMap;

/* The image to synthesise from when features count in the match
 * ("appearance space", Lefebvre and Hoppe 2006): each exemplar pixel's Lab
 * beside its features times `weight` (0 .. TS_MAX_FEATURE_WEIGHT; at 1 a
 * feature's range 0..1 weighs as L's 0..100), turned by PCA onto the three
 * directions of largest variance, alpha kept. Synthesise it with a
 * source_map and copy the exemplar's pixels by that map
 * (ts_copy_by_source_map) for colours. `matching` is allocated here (free
 * its pixels with free()); on failure it is left empty. */
TsStatus ts_feature_matching_image (const TsImage      *exemplar,
                                    const TsFeatureMap *features,
                                    double              weight,
                                    TsImage            *matching,
                                    TsError            *error);

/* output pixel i = exemplar pixel source_map[2i], source_map[2i + 1]
 * (coordinates as TsParams.source_map gives them, all inside the
 * exemplar), as the engine reads it: non-finite values 0, alpha clamped
 * to [0, 1]; `output` is allocated by the caller. */
void ts_copy_by_source_map (const TsImage *exemplar, const int32_t *source_map, TsImage *output);

/* --- Making an existing image tileable (common/tileable/) --------------- */

typedef enum
{
  TS_TILEABLE_BOTH = 0,    /* left/right and top/bottom edges meet        */
  TS_TILEABLE_HORIZONTAL,  /* left and right edges only (wraps along x)   */
  TS_TILEABLE_VERTICAL     /* top and bottom edges only (wraps along y)   */
} TsTileableDirection;

/* Smallest side of the input along a direction that is made to wrap. */
#define TS_TILEABLE_MIN_SIDE 8
/* Range of TsTileableParams.seam_width. */
#define TS_TILEABLE_MIN_SEAM_WIDTH 0.02
#define TS_TILEABLE_MAX_SEAM_WIDTH 0.25

typedef struct
{
  TsTileableDirection direction;
  double   seam_width;         /* band on each side of a wrap edge that is
                                  replaced, as a fraction of the image side,
                                  TS_TILEABLE_MIN_SEAM_WIDTH .. _MAX_; the
                                  rest of the image is kept as it is     */
  int      quality;            /* as TsParams                            */
  uint32_t seed;
  int      patch_size;
  int      fine_patch_size;
  int      max_iterations;
  bool     histogram_matching;
  size_t   memory_limit;
  /* Optional: receives 2 int32 per pixel, the input (x, y) each output
   * pixel was copied from (the identity where the picture is kept). */
  int32_t *source_map;
} TsTileableParams;

/* Fill `params` with the defaults (both directions, default seam width,
 * the synthesis defaults of ts_params_init). */
void ts_tileable_params_init (TsTileableParams *params);

/* Check `params` against `input`; on failure fills `error` (may be NULL)
 * and returns its status. ts_make_tileable calls this first. */
TsStatus ts_tileable_params_validate (const TsTileableParams *params,
                                      const TsImage          *input,
                                      TsError                *error);

/* Re-synthesise the parts of `input` near its edges so that the result
 * tiles seamlessly in the chosen direction(s) while everything farther
 * from the edges stays exactly as it was. `output` must be allocated
 * with the input's size; it is left untouched on failure. */
TsStatus ts_make_tileable (const TsTileableParams *params,
                           const TsImage          *input,
                           TsImage                *output,
                           TsProgressFunc          progress,
                           void                   *user_data,
                           TsError                *error);

/* --- Solid (volume) textures from 2D exemplars (common/solid-*.c) -------
 * Kopf et al. 2007: texture optimization over a cube so that the three
 * axis-aligned slices through every voxel look like the exemplar(s).
 * Volumes are size^3 voxels of TS_CHANNELS floats (as TsImage pixels),
 * x fastest, then y, then z. A slice orthogonal to x shows (u, v) = (y, z),
 * one orthogonal to y shows (x, z), one orthogonal to z shows (x, y). */

typedef enum
{
  TS_AXIS_X = 0,
  TS_AXIS_Y,
  TS_AXIS_Z
} TsAxis;

/* Range of a solid's edge: a smaller cube holds too little texture to
 * be of use; 1024^3 voxels already take 16 GiB of working values. */
#define TS_SOLID_MIN_SIZE 8
#define TS_SOLID_MAX_SIZE 1024

/* The cell structure, for cells with dark joints (stones in mortar,
 * cobbles, paving, cracked mud): a 3D cell tessellation fitted to the
 * exemplar guides where the walls go, so every slice shows whole
 * polygonal cells with closed joints. Wrong for other kinds: round
 * pebbles would turn into polygons. OFF and ON keep the values of the
 * boolean this once was. */
typedef enum
{
  TS_CELL_STRUCTURE_OFF  = 0,
  TS_CELL_STRUCTURE_ON   = 1, /* needs opaque exemplars                    */
  TS_CELL_STRUCTURE_AUTO = 2  /* on for opaque exemplars of separate light
                                 stones in thin dark joints (cell-choice.c) */
} TsCellStructure;

typedef struct
{
  size_t   size;               /* edge of the cube, TS_SOLID_MIN_SIZE ..   */
  bool     periodic;           /* the volume tiles in x, y and z           */
  int      quality;            /* 1 .. 10: breadth of the search over all
                                  exemplar neighbourhoods (3 x quality
                                  kd-tree leaves per query)               */
  uint32_t seed;
  int      patch_size;         /* 0 = automatic; else odd, 3 .. 31         */
  int      max_iterations;     /* 0 = automatic; else 1 .. 100 per level   */
  bool     histogram_matching; /* Kopf et al.'s re-weighting of votes      */
  size_t   memory_limit;       /* bytes; 0 = default, as TsParams          */
  bool     record_sources;     /* counts the source volume (4 bytes per
                                  voxel) in the estimate; required by
                                  ts_synthesize_solid_with_sources       */
  TsCellStructure cell_structure; /* see TsCellStructure              */
} TsSolidParams;

/* Defaults: 128^3, periodic, default quality, histogram matching, the
 * cell structure chosen automatically. */
void     ts_solid_params_init (TsSolidParams *params);

/* Whether a run with `params` on `exemplars` (as ts_synthesize_solid
 * takes them) uses the cell structure: TS_CELL_STRUCTURE_AUTO answers
 * for the exemplars. Cheap (one pass over each exemplar); false if the
 * exemplars cannot be read or memory runs out. */
bool     ts_solid_uses_cell_structure (const TsSolidParams *params,
                                       const TsImage *const exemplars[3]);

/* `exemplars[a]` is the exemplar of the slices orthogonal to axis a, or
 * NULL to leave that orientation free; at least two must be given (the
 * same image may be passed for all three). One image passed for all
 * three whose lines mostly fall diagonally (left-top to right-bottom) is
 * read mirrored left to right by the slices orthogonal to x: only then
 * can its lines be sheets that every slice shows. Sources still name its
 * own pixels. */
TsStatus ts_solid_params_validate (const TsSolidParams *params,
                                   const TsImage *const exemplars[3],
                                   TsError *error);
TsStatus ts_solid_estimate_memory (const TsSolidParams *params,
                                   const TsImage *const exemplars[3],
                                   size_t *bytes, TsError *error);

/* Synthesises a volume into `volume` (size^3 * TS_CHANNELS floats,
 * allocated by the caller). The finest level is synthesised in place to
 * save memory, so on failure or cancel its contents are unspecified. */
TsStatus ts_synthesize_solid (const TsSolidParams *params,
                              const TsImage *const exemplars[3],
                              float *volume,
                              TsProgressFunc progress,
                              void *user_data,
                              TsError *error);

/* Every voxel of a synthesised volume is a copy of one pixel of one
 * orientation's exemplar. Its source packs the orientation a (the axis
 * the exemplar's slices are cut across, TsAxis) in the top two bits and
 * the pixel's index y * width + x in exemplars[a] below: exemplars have
 * at most TS_MAX_OUTPUT_SIDE^2 = 2^28 pixels. */
typedef uint32_t TsSolidSource;
#define TS_SOLID_SOURCE_AXIS_SHIFT 30
#define TS_SOLID_SOURCE_INDEX_MASK ((1u << TS_SOLID_SOURCE_AXIS_SHIFT) - 1u)

static inline TsSolidSource
ts_solid_source_pack (int axis, uint32_t index)
{
  return (TsSolidSource) axis << TS_SOLID_SOURCE_AXIS_SHIFT | index;
}

static inline int
ts_solid_source_axis (TsSolidSource source)
{
  return (int) (source >> TS_SOLID_SOURCE_AXIS_SHIFT);
}

static inline uint32_t
ts_solid_source_index (TsSolidSource source)
{
  return source & TS_SOLID_SOURCE_INDEX_MASK;
}

/* ts_synthesize_solid that also fills `sources` (size^3, caller's, x
 * fastest) with every voxel's source; params->record_sources must be set.
 * Applying the sources to the exemplars (ts_solid_apply_sources on their
 * pixels) gives the volume bit for bit, but where an exemplar pixel is
 * translucent: the volume's alpha went through the working scale (x 100,
 * / 100) and may differ by 1 ulp (never in 8 bits). */
TsStatus ts_synthesize_solid_with_sources (const TsSolidParams *params,
                                           const TsImage *const exemplars[3],
                                           float *volume,
                                           TsSolidSource *sources,
                                           TsProgressFunc progress,
                                           void *user_data,
                                           TsError *error);

/* Lays out maps with a volume's sources: voxel p becomes pixel
 * index(sources[p]) of maps[axis(sources[p])], `pixel_bytes` bytes each,
 * into `out` (voxels * pixel_bytes). maps[a] holds map_pixels[a] pixels
 * (the exemplar a's count); the same map may serve several orientations.
 * Fails, writing nothing, if a source names a missing map or a pixel
 * beyond its map. */
TsStatus ts_solid_apply_sources (const TsSolidSource *sources, size_t voxels,
                                 const void *const maps[3], const size_t map_pixels[3],
                                 size_t pixel_bytes, void *out, TsError *error);

/* --- Image completion: filling a hole from the rest (common/completion/) -
 * Coarse to fine: the hole starts filled from its border inwards, then
 * texture optimization with the known pixels as hard constraints; every
 * patch that touches the hole is matched to a patch of known pixels by
 * PatchMatch (random search over the whole allowed source plus coherent
 * propagation from the neighbours' matches). */

typedef enum
{
  TS_HEAL_ALL_AROUND = 0,  /* sources anywhere within the context           */
  TS_HEAL_SIDES,           /* only left and right of the hole's bounds      */
  TS_HEAL_ABOVE_BELOW      /* only above and below the hole's bounds        */
} TsHealSampleFrom;

/* Largest context: as wide as the largest output side (16384). */
#define TS_HEAL_MAX_CONTEXT 16384

typedef struct
{
  size_t   context;         /* source patches lie within this many pixels of
                               the hole's bounding box; 0 = the whole image.
                               Memory and time then grow with the context,
                               not with the image.                         */
  TsHealSampleFrom sample_from;
  int      quality;         /* 1 .. 10: search effort per patch and level  */
  uint32_t seed;            /* same seed, same result, any thread count   */
  int      patch_size;      /* 0 = automatic; else odd 3 .. 31: the
                               patches of the coarser levels              */
  int      fine_patch_size; /* 0 = automatic; else odd 3 .. 31: the
                               patches of the finest level                */
  size_t   memory_limit;    /* bytes; 0 = default, as TsParams            */
} TsHealParams;

/* Defaults: whole image, all around, default quality, seed 0. */
void     ts_heal_params_init (TsHealParams *params);

/* Checks `params`, the image and the hole (one byte per pixel, non-zero =
 * fill). `source` is NULL to copy from the image's own known pixels, or
 * another image to copy from (its pixels with alpha 0 are never copied).
 * Fails with TS_ERROR_NOTHING_TO_SAMPLE when no whole patch of known
 * pixels lies where sources are allowed (hole covering everything, a
 * context too small to hold a patch). An empty hole is valid. */
TsStatus ts_heal_params_validate (const TsHealParams *params, const TsImage *image,
                                  const uint8_t *hole, const TsImage *source,
                                  TsError *error);

/* Peak memory of ts_heal, in bytes. */
TsStatus ts_heal_estimate_memory (const TsHealParams *params, const TsImage *image,
                                  const uint8_t *hole, const TsImage *source,
                                  size_t *bytes, TsError *error);

/* The part of the image ts_heal reads and writes, given the hole's bounds
 * (x0, y0 inclusive, x1, y1 exclusive): the bounds grown by the context
 * and a patch margin, clipped to the image (the whole image for context
 * 0). Callers that hold large images need read only this part. */
void     ts_heal_region (const TsHealParams *params, size_t width, size_t height,
                         size_t x0, size_t y0, size_t x1, size_t y1,
                         size_t *rx0, size_t *ry0, size_t *rx1, size_t *ry1);

/* Fills the hole of `image` into `output` (allocated by the caller with
 * the image's size); pixels outside the hole are copied unchanged. Every
 * hole pixel becomes a copy of one source pixel with its L, a, b shifted
 * by a smooth correction (a Poisson blend) that hides the outline and the
 * seams between copies; `source_map` (may be NULL) receives for every
 * pixel the index y * width + x of that source pixel (in `source` if
 * given, else in `image`), or -1 outside the hole. On failure `output` is
 * left untouched. */
TsStatus ts_heal (const TsHealParams *params, const TsImage *image, const uint8_t *hole,
                  const TsImage *source, TsImage *output, int32_t *source_map,
                  TsProgressFunc progress, void *user_data, TsError *error);

#ifdef __cplusplus
}
#endif

#endif /* TEXSYNTH_H */
