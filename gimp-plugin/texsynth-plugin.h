/* The texsynth GIMP plug-in: what GIMP 2.10 and GIMP 3 share. The
 * procedures' names, arguments, ranges and defaults; argument checks; and
 * running the texsynth GEGL ops on private copies of GIMP's pixels.
 * SPDX-License-Identifier: GPL-3.0-or-later
 *
 * The version-specific glue (registration, dialogs, reading layers and
 * making images) is in compat-gimp2.c and compat-gimp3.c; everything here
 * uses GEGL and the libgimp calls both versions have alike.
 */
#ifndef TEXSYNTH_PLUGIN_H
#define TEXSYNTH_PLUGIN_H

#include <libgimp/gimp.h>

#define TS_PLUGIN_BINARY    "texsynth"
#define TS_PROC_RENDER      "plug-in-texsynth-render"
#define TS_PROC_TILEABLE    "plug-in-texsynth-tileable"
#define TS_PROC_SOLID       "plug-in-texsynth-solid"
#define TS_PROC_HEAL_SELECTION    "plug-in-texsynth-heal-selection"
#define TS_PROC_HEAL_TRANSPARENCY "plug-in-texsynth-heal-transparency"
#define TS_PROC_UNCROP            "plug-in-texsynth-uncrop"
#define TS_PROC_RENDER_LAYERS     "plug-in-texsynth-render-layers"
#define TS_PLUGIN_HELP_ID   "texsynth"

/* The ops the procedures run. */
#define TS_OP_SYNTHESIZE    "texsynth:synthesize"
#define TS_OP_TILEABLE      "texsynth:tileable"
#define TS_OP_VOLUME_SAVE   "texsynth:volume-save"
#define TS_OP_VOLUME_SLICE  "texsynth:volume-slice"
#define TS_OP_HEAL          "texsynth:heal"

/* Ranges and defaults as the ops declare them. */
#define TS_PLUGIN_MAX_SIDE        16384
#define TS_PLUGIN_MIN_QUALITY     1
#define TS_PLUGIN_MAX_QUALITY     10
#define TS_PLUGIN_DEFAULT_QUALITY 2
#define TS_PLUGIN_MIN_SOLID       8
#define TS_PLUGIN_MAX_SOLID       512
#define TS_PLUGIN_DEFAULT_SOLID   128
#define TS_PLUGIN_PATH_MAX        4096
#define TS_PLUGIN_MAX_CONTEXT     16384
#define TS_PLUGIN_MAX_SAMPLE_FROM 2      /* all around, sides, above and below */
#define TS_PLUGIN_MAX_UNCROP      100    /* percent of the side added        */
/* The cell structure's choices, the ops' TsCellStructure values. */
#define TS_PLUGIN_CELL_STRUCTURE_OFF  0
#define TS_PLUGIN_CELL_STRUCTURE_ON   1
#define TS_PLUGIN_CELL_STRUCTURE_AUTO 2
#define TS_PLUGIN_MAX_CELL_STRUCTURE  TS_PLUGIN_CELL_STRUCTURE_AUTO

/* Flat structs: GIMP 2.10 stores last values as raw bytes. */
typedef struct
{
  gint     width;     /* 0 in a fresh struct: twice the exemplar's */
  gint     height;
  gboolean tileable;
  gint     quality;
  gint     seed;
} TsRenderArgs;

typedef struct
{
  gint quality;
  gint seed;
} TsTileableArgs;

/* New fields go at the end: GIMP 2.10 keeps the last values of an older
 * plug-in as bytes of the older struct (see compat-gimp2.c). */
typedef struct
{
  gint     size;
  gchar    path[TS_PLUGIN_PATH_MAX];
  gint     quality;
  gint     seed;
  /* texsynth:volume-save's cell-structure: 0 off, 1 on, 2 automatic. A
   * gint where a gboolean (same size) once was, so stored last values
   * keep their layout and FALSE/TRUE keep their meaning. */
  gint     cell_structure;
} TsSolidArgs;

/* The three heal procedures: context and sample-from for healing a
 * selection or transparency, percent for uncrop. */
typedef struct
{
  gint context;      /* pixels around the hole to copy from; 0 = whole layer */
  gint sample_from;  /* 0 all around, 1 sides, 2 above and below          */
  gint percent;      /* uncrop: border added on each side, % of the side  */
  gint quality;
  gint seed;
} TsHealArgs;

void ts_render_args_init   (TsRenderArgs *args);
void ts_heal_args_init     (TsHealArgs *args);
gchar *ts_heal_args_check  (const TsHealArgs *args);
void ts_tileable_args_init (TsTileableArgs *args);
void ts_solid_args_init    (TsSolidArgs *args);

/* Each returns NULL when the arguments are valid, else a message for the
 * user (g_free it). */
gchar *ts_render_args_check   (const TsRenderArgs *args);
gchar *ts_tileable_args_check (const TsTileableArgs *args, gint width, gint height);
gchar *ts_solid_args_check    (const TsSolidArgs *args, gint n_exemplars);
/* A material set is laid out pixel for pixel: every layer must have the
 * driving layer's size. NULL if `layer` has it, else a message. */
gchar *ts_layers_size_check   (const gchar *layer, gint width, gint height,
                               const gchar *driver, gint driver_width, gint driver_height);

/* The label and tooltip of an argument, translated, worded as the ops
 * word their properties; NULL for an unknown name. */
const gchar *ts_arg_label   (const gchar *name);
const gchar *ts_arg_tooltip (const gchar *name);
/* The translated name of a sample-from choice (0 .. TS_PLUGIN_MAX_SAMPLE_FROM),
 * for the dialogs' combo boxes; NULL out of range. */
const gchar *ts_sample_from_label (gint value);
/* The same for a cell-structure choice (0 .. TS_PLUGIN_MAX_CELL_STRUCTURE). */
const gchar *ts_cell_structure_label (gint value);

/* A seed for an interactive run: differs from run to run, and is then
 * stored with the last values so that Repeat gives the same result. */
gint ts_plugin_random_seed (void);

/* The folder of the translations: LOCALEDIR, or $TEXSYNTH_LOCALEDIR if set
 * (tests point it at the build tree's catalogues). */
const gchar *ts_plugin_locale_dir (void);

/* Binds the gettext domain (GETTEXT_PACKAGE) to ts_plugin_locale_dir (). */
void ts_plugin_init_i18n (void);

/* NULL if every op in the NULL-terminated list is available to GEGL in
 * this process, else a message saying which is missing and how to fix it. */
gchar *ts_plugin_check_ops (const gchar *first_op, ...) G_GNUC_NULL_TERMINATED;

/* What the version glue reads from GIMP: a private copy of the pixels,
 * so that the ops can run in a worker thread without talking to GIMP, and
 * what the new image must keep. */
typedef struct
{
  GeglBuffer       *buffer;       /* at (0, 0), in the drawable's format */
  GimpImageBaseType base_type;    /* GIMP_RGB or GIMP_GRAY (indexed: RGB) */
  gboolean          has_alpha;
  GimpPrecision     precision;
  GimpColorProfile *profile;      /* NULL: the built-in one */
} TsExemplar;

/* Copies `source_rect` of `source` to (target_x, target_y) of `target`
 * through `format`, in this thread only (GIMP's buffers need that).
 * FALSE if out of memory. */
gboolean    ts_plugin_transfer    (GeglBuffer          *source,
                                   const GeglRectangle *source_rect,
                                   GeglBuffer          *target,
                                   gint                 target_x,
                                   gint                 target_y,
                                   const Babl          *format);

/* A "Y' float" mask of `width` x `height` that is 1 everywhere but in
 * `inner` (0): uncrop's hole, the new border only, so that transparent
 * pixels the layer already had stay as they are. NULL if out of memory. */
GeglBuffer *ts_plugin_border_mask (gint                 width,
                                   gint                 height,
                                   const GeglRectangle *inner);

/* Copies `rect` of `source` (a GIMP drawable's buffer) into a new memory
 * buffer at (0, 0) in `format`; NULL if out of memory. */
GeglBuffer *ts_plugin_copy_buffer (GeglBuffer          *source,
                                   const GeglRectangle *rect,
                                   const Babl          *format);
void        ts_exemplar_clear     (TsExemplar *exemplar);

/* Links `source`'s output to `sink_pad` of `sink`, with whichever call
 * this GEGL has. */
void ts_plugin_connect_pads (GeglNode *source, GeglNode *sink, const gchar *sink_pad);
/* Sets an enum property of `node` by its value's nick; a property or
 * nick this op lacks leaves it as it is. */
void ts_plugin_set_enum_by_nick (GeglNode *node, const gchar *property, const gchar *nick);

/* Makes the exemplar's pixels outside the selection transparent, so that
 * a non-rectangular selection gives its shape, not its bounds: pixels at
 * least half selected keep their alpha, the others get 0 (the ops never
 * copy transparent pixels). Takes `mask`, the selection's buffer; `rect`
 * is the exemplar's area in its drawable, which lies at (offset_x,
 * offset_y) in the image. Out of memory, it clears exemplar->buffer. */
void        ts_exemplar_keep_selected (TsExemplar          *exemplar,
                                       GeglBuffer          *mask,
                                       const GeglRectangle *rect,
                                       gint                 offset_x,
                                       gint                 offset_y);

/* The babl format of a layer of the new image for `exemplar`, in `space`. */
const Babl *ts_exemplar_layer_format (const TsExemplar *exemplar, const Babl *space);

/* Run the ops. Each shows and moves GIMP's progress bar while the op works
 * in a worker thread; GIMP's Cancel ends the plug-in process, and since
 * nothing is written to GIMP until the op is done, the image is left as it
 * was. On success returns TRUE and the result; else FALSE and `error`. */
gboolean ts_plugin_render   (const TsExemplar   *exemplar,
                             const TsRenderArgs *args,
                             GeglBuffer        **result,
                             GError            **error);
gboolean ts_plugin_tileable (const TsExemplar     *exemplar,
                             const TsTileableArgs *args,
                             GeglBuffer          **result,
                             GError              **error);
/* A material set: an image's top-level layers of one size, read before
 * anything runs so that a bad set changes nothing. */
typedef struct
{
  gint         n;
  gint         driver;     /* index of the layer the layout comes from */
  gchar      **names;
  gboolean    *alphas;
  TsExemplar  *exemplars;
  GeglBuffer **results;    /* filled by ts_plugin_render_layers */
} TsMaterialSet;

/* n zeroed entries in each array. */
void ts_material_set_init  (TsMaterialSet *set, gint n);
void ts_material_set_clear (TsMaterialSet *set);

/* Synthesises one layout from the driving layer (texsynth:synthesize with
 * source-map) and lays every layer out with it (gegl:map-absolute,
 * nearest), so that the results stay aligned as the layers were;
 * results[i] is in exemplars[i].buffer's format. */
gboolean ts_plugin_render_layers (TsMaterialSet      *set,
                                  const TsRenderArgs *args,
                                  GError            **error);
/* Writes the volume to args->path and returns its three middle slices
 * (orthogonal to x, y and z). `exemplars` has 1 to 3 entries. */
gboolean ts_plugin_solid    (const TsExemplar  *exemplars,
                             gint               n_exemplars,
                             const TsSolidArgs *args,
                             GeglBuffer        *slices[3],
                             GError           **error);

/* texsynth:heal on `pixels` (a private copy of a layer at (0, 0)) with
 * `mask` (the same size, "Y" at least 50 % = fill) or NULL (fill the
 * pixels that are not fully opaque). The result has `pixels`'s format, so
 * the pixels outside the hole are bit-identical. FALSE with `error` if the
 * op changed nothing (it explains why on the error console). */
gboolean ts_plugin_heal     (GeglBuffer        *pixels,
                             GeglBuffer        *mask,
                             const TsHealArgs  *args,
                             GeglBuffer       **result,
                             GError           **error);

/* What a heal procedure reads of GIMP: the layer, and the selection over
 * it (heal selection) or the width of the new border (uncrop). */
typedef struct
{
  GeglBuffer *buffer;               /* the drawable's pixels              */
  const Babl *format;               /* the drawable's format              */
  gint        width, height;
  gboolean    is_gray;
  GeglBuffer *selection;            /* the selection channel, or NULL     */
  gint        offset_x, offset_y;   /* the layer's place in the image     */
  gint        border_x, border_y;   /* uncrop: the new border; else 0     */
} TsHealLayer;

/* Heals a private copy of the layer (enlarged by the border for uncrop,
 * with an alpha channel then) through ts_plugin_heal; GIMP is not
 * touched. The result has the copy's size and format. */
gboolean ts_plugin_heal_layer (const TsHealLayer *layer,
                               const TsHealArgs  *args,
                               GeglBuffer       **result,
                               GError           **error);

/* The heal dialog's preview: copies of the layer and the selection over
 * it, cropped to `hole` (the selection's bounds in the layer) widened by
 * as much as the hole's larger side, at least TS_HEAL_PREVIEW_MIN_MARGIN
 * pixels; both at (0, 0). FALSE (and NULLs) without a selection or out of
 * memory. */
#define TS_HEAL_PREVIEW_MIN_MARGIN 32
gboolean ts_heal_preview_crop (const TsHealLayer   *layer,
                               const GeglRectangle *hole,
                               GeglBuffer         **pixels,
                               GeglBuffer         **mask);

#define TS_PLUGIN_ERROR ts_plugin_error_quark ()
GQuark ts_plugin_error_quark (void);

#endif /* TEXSYNTH_PLUGIN_H */
