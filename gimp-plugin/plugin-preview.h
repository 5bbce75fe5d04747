/* The dialogs' previews: a small run of the procedure's op with the
 * dialog's settings, in a worker thread so that the dialog stays
 * responsive. Shared by GIMP 2.10 and GIMP 3; no GTK here.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_PLUGIN_PREVIEW_H
#define TEXSYNTH_PLUGIN_PREVIEW_H

#include "texsynth-plugin.h"
#include "guided-plugin.h"

/* The preview's largest side in pixels: small enough that a run takes a
 * fraction of a second, large enough to show a texture's structure. */
#define TS_PREVIEW_SIDE 160

/* The solid preview's largest cube: the middle slice across x of a
 * volume of this edge, which keeps the exemplar's scale. */
#define TS_PREVIEW_SOLID_SIZE 48

/* Make Seamless's preview: the layer scaled down to fit this side, made
 * seamless and repeated 2x2, so that the joins show within
 * TS_PREVIEW_SIDE. */
#define TS_PREVIEW_TILE_SIDE (TS_PREVIEW_SIDE / 2)

typedef struct _TsPreview TsPreview;

/* What a dialog's preview shows; each has its own caption. */
typedef enum
{
  TS_PREVIEW_RENDER,
  TS_PREVIEW_LAYERS,             /* the driving layer's texture          */
  TS_PREVIEW_SOLID,
  TS_PREVIEW_HEAL_SELECTION,
  TS_PREVIEW_HEAL_TRANSPARENCY,
  TS_PREVIEW_UNCROP,
  TS_PREVIEW_TILEABLE,
  TS_PREVIEW_GUIDED
} TsPreviewKind;

/* What a dialog's preview runs on, read from GIMP before the dialog
 * opens; the caller keeps it until the dialog is closed. */
typedef struct
{
  TsPreviewKind     kind;
  const TsExemplar *exemplars;     /* render, layers, solid: 1 to 3          */
  gint              n_exemplars;
  GeglBuffer       *pixels;        /* heal selection: the crop around it;
                                    * the others: ts_preview_copy's         */
  GeglBuffer       *mask;          /* heal selection: the selection on it    */
  gdouble           ratio;         /* pixels' scale against the layer's     */
  gint              image_width;   /* uncrop: the image's size              */
  gint              image_height;
} TsPreviewInput;

/* The dialog's settings as it shows them, those of input->kind read. */
typedef struct
{
  TsRenderArgs   render;     /* render, layers */
  TsSolidArgs    solid;
  TsHealArgs     heal;       /* heal selection, heal transparency, uncrop */
  TsTileableArgs tileable;
  TsGuidedArgs   guided;
  GeglBuffer    *exemplar;        /* guided: the layers the dialog picks */
  GeglBuffer    *exemplar_guide;  /* NULL for style transfer             */
} TsPreviewSettings;

/* Starts the preview of input->kind with `settings`; NULL if it cannot
 * (out of memory, or no exemplar or a guide of another size picked). */
TsPreview *ts_preview_start (const TsPreviewInput *input, const TsPreviewSettings *settings);

/* A line under the preview saying what it shows and how it differs from
 * the result, translated. */
const gchar *ts_preview_caption (TsPreviewKind kind);

/* A small private copy of `source` (a GIMP drawable's buffer, at (0, 0)),
 * read in this thread, as "R'G'B'A float" in its space at (0, 0): the
 * whole of it scaled down by *ratio to fit `side` (scale_down), or its
 * middle side x side pixels at full scale (*ratio 1). NULL if out of
 * memory. */
GeglBuffer *ts_preview_copy (GeglBuffer *source, gint side, gboolean scale_down, gdouble *ratio);

/* What a heal procedure's dialog previews (`procedure` names it): the
 * crop around `hole` (the selection's bounds in the layer; NULL when the
 * selection misses the layer) for heal selection, else the layer scaled
 * down, in an image of image_width x image_height for uncrop. FALSE (no
 * preview) without a hole for heal selection, or out of memory. */
gboolean ts_heal_preview_read (const TsHealLayer   *layer,
                               const gchar         *procedure,
                               const GeglRectangle *hole,
                               gint                 image_width,
                               gint                 image_height,
                               TsPreviewInput      *input);

/* Whether the run has finished; never blocks. */
gboolean ts_preview_done (TsPreview *preview);

/* After ts_preview_done: the result as sRGB "R'G'B'A u8" rows of
 * width * 4 bytes, owned by `preview`. */
const guchar *ts_preview_pixels (TsPreview *preview, gint *width, gint *height);

/* Waits for the run to finish (a fraction of a second at these sizes;
 * GEGL cannot stop an op midway) and frees everything. NULL is fine. */
void ts_preview_free (TsPreview *preview);

#endif /* TEXSYNTH_PLUGIN_PREVIEW_H */
