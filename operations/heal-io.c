/* texsynth:heal's work between GEGL buffers and the engine (heal-io.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "heal-io.h"
#include "op-common.h"
#include "op-lab.h"

#include <glib/gi18n-lib.h>
#include <stdio.h>
#include <string.h>

/* A mask pixel asks for filling from this grey value times alpha. */
#define TS_HEAL_MASK_THRESHOLD 0.5f
/* Alpha at or above this counts as opaque (float images may hold 0.99999). */
#define TS_HEAL_OPAQUE 0.9999f

typedef struct
{
  gsize    width, height;  /* the image (box)                          */
  guint8  *hole;           /* 1 = fill                                  */
  gfloat  *cover;          /* heal transparency: each pixel's alpha     */
  gsize    x0, y0, x1, y1; /* the hole's bounds                         */
  gboolean any;
} Hole;

/* The hole from the mask, or from the input's alpha. */
static gboolean
read_hole (GeglBuffer *input, GeglBuffer *aux, const GeglRectangle *box, Hole *h)
{
  gsize n = (gsize) box->width * (gsize) box->height;
  gfloat *ya = g_try_malloc (n * 2 * sizeof (gfloat));

  h->width = (gsize) box->width;
  h->height = (gsize) box->height;
  h->hole = g_try_malloc (n);
  h->cover = aux ? NULL : g_try_malloc (n * sizeof (gfloat));
  if (!ya || !h->hole || (!aux && !h->cover))
    {
      g_free (ya);
      return FALSE;
    }
  /* Outside the mask's extent GEGL gives 0: those pixels are kept. */
  gegl_buffer_get (aux ? aux : input, box, 1.0, babl_format ("Y'A float"), ya,
                   GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
  h->x0 = h->width;
  h->y0 = h->height;
  h->x1 = h->y1 = 0;
  for (gsize p = 0; p < n; p++)
    {
      gfloat alpha = ya[2 * p + 1];
      gboolean fill;
      if (aux)
        fill = ya[2 * p] * alpha >= TS_HEAL_MASK_THRESHOLD;
      else
        {
          alpha = alpha > 0.0f ? (alpha < 1.0f ? alpha : 1.0f) : 0.0f;   /* NaN: 0 */
          h->cover[p] = alpha;
          fill = alpha < TS_HEAL_OPAQUE;
        }
      h->hole[p] = fill;
      if (fill)
        {
          gsize x = p % h->width, y = p / h->width;
          h->x0 = MIN (h->x0, x);
          h->x1 = MAX (h->x1, x + 1);
          h->y0 = MIN (h->y0, y);
          h->y1 = y + 1;
          h->any = TRUE;
        }
    }
  g_free (ya);
  return TRUE;
}

/* Heal transparency: a partly transparent pixel keeps what it shows, over
 * the fill (the "over" operator in Lab). */
static void
blend_partial (const TsImage *original, TsImage *result, const Hole *h, const GeglRectangle *crop)
{
  for (gsize y = 0; y < result->height; y++)
    for (gsize x = 0; x < result->width; x++)
      {
        gsize p = y * result->width + x;
        gsize q = ((gsize) crop->y + y) * h->width + (gsize) crop->x + x;
        gfloat a = h->cover[q], *r = result->pixels + p * TS_CHANNELS;
        const gfloat *o = original->pixels + p * TS_CHANNELS;
        if (!h->hole[q] || a <= 0.0f)
          continue;
        for (int c = 0; c < 3; c++)
          r[c] = a * o[c] + (1.0f - a) * r[c];
        r[3] = a + (1.0f - a) * r[3];
      }
}

/* Writes the hole's pixels of `result` (the crop) into `output`, in the
 * output's format, leaving every other byte as it is. */
static gboolean
write_hole (GeglBuffer *output, const GeglRectangle *box, const GeglRectangle *crop,
            const TsImage *result, const Hole *h)
{
  const Babl *format = gegl_buffer_get_format (output);
  gsize bpp = (gsize) babl_format_get_bytes_per_pixel (format);
  gsize n = result->width * result->height;
  GeglRectangle abs = { box->x + crop->x, box->y + crop->y, crop->width, crop->height };
  guint8 *bytes = g_try_malloc (n * bpp), *converted = g_try_malloc (n * bpp);

  if (!bytes || !converted)
    {
      g_free (bytes);
      g_free (converted);
      return FALSE;
    }
  gegl_buffer_get (output, &abs, 1.0, format, bytes, GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
  ts_op_lab_to_format (result->pixels, format, converted, n);
  for (gsize y = 0; y < result->height; y++)
    for (gsize x = 0; x < result->width; x++)
      {
        gsize p = y * result->width + x;
        if (h->hole[((gsize) crop->y + y) * h->width + (gsize) crop->x + x])
          memcpy (bytes + p * bpp, converted + p * bpp, bpp);
      }
  gegl_buffer_set (output, &abs, 0, format, bytes, GEGL_AUTO_ROWSTRIDE);
  g_free (bytes);
  g_free (converted);
  return TRUE;
}

static gboolean
read_source (GeglBuffer *aux2, TsImage *source, gchar *message, gsize message_size)
{
  const GeglRectangle *ext = gegl_buffer_get_extent (aux2);

  if (ext->width <= 0 || ext->height <= 0 || gegl_rectangle_is_infinite_plane (ext) ||
      ext->width > TS_MAX_OUTPUT_SIDE || ext->height > TS_MAX_OUTPUT_SIDE)
    {
      snprintf (message, message_size,
                _("the source image (aux2) must be 1 to %d pixels on each side, got %dx%d"),
                TS_MAX_OUTPUT_SIDE, ext->width, ext->height);
      return FALSE;
    }
  source->width = (size_t) ext->width;
  source->height = (size_t) ext->height;
  source->pixels = g_try_malloc (source->width * source->height * TS_CHANNELS * sizeof (float));
  if (!source->pixels)
    {
      snprintf (message, message_size, _("out of memory while healing"));
      return FALSE;
    }
  ts_op_read_lab (aux2, ext, source->pixels);
  return TRUE;
}

gboolean
ts_heal_op_run (GeglOperation *operation, const TsHealParams *params, GeglBuffer *input,
                GeglBuffer *aux, GeglBuffer *aux2, GeglBuffer *output, const GeglRectangle *box,
                gchar *message, gsize message_size)
{
  Hole h = { 0 };
  TsImage image = { 0, 0, NULL }, result = { 0, 0, NULL }, source = { 0, 0, NULL };
  guint8 *crop_hole = NULL;
  GeglRectangle crop;
  size_t rx0, ry0, rx1, ry1;
  TsError error = { TS_OK, "" };
  TsOpProgress progress;
  TsStatus status = TS_ERROR_OUT_OF_MEMORY;
  gboolean ok = FALSE;

  if (box->width > TS_MAX_OUTPUT_SIDE || box->height > TS_MAX_OUTPUT_SIDE)
    {
      snprintf (message, message_size, _("the image is %zux%zu; its sides must be at most %d pixels"),
                (size_t) box->width, (size_t) box->height, TS_MAX_OUTPUT_SIDE);
      return FALSE;
    }
  if (!read_hole (input, aux, box, &h))
    {
      snprintf (message, message_size, _("out of memory while healing"));
      goto out;
    }
  if (!h.any)
    {
      ok = TRUE;   /* nothing to fill: the copy is the result */
      goto out;
    }
  if (!aux && h.x0 == 0 && h.y0 == 0 && h.x1 == h.width && h.y1 == h.height)
    {
      gsize n = h.width * h.height, opaque = 0;
      for (gsize p = 0; p < n; p++)
        opaque += !h.hole[p];
      if (opaque == 0)
        {
          snprintf (message, message_size,
                    _("the image has no fully opaque pixel: there is nothing to heal the "
                      "transparency from"));
          goto out;
        }
    }
  if (aux2 && !read_source (aux2, &source, message, message_size))
    goto out;

  /* Only the part of the image within the context matters. */
  ts_heal_region (params, h.width, h.height, h.x0, h.y0, h.x1, h.y1, &rx0, &ry0, &rx1, &ry1);
  crop = (GeglRectangle) { (gint) rx0, (gint) ry0, (gint) (rx1 - rx0), (gint) (ry1 - ry0) };
  image.width = result.width = rx1 - rx0;
  image.height = result.height = ry1 - ry0;
  image.pixels = g_try_malloc (image.width * image.height * TS_CHANNELS * sizeof (float));
  result.pixels = g_try_malloc (image.width * image.height * TS_CHANNELS * sizeof (float));
  crop_hole = g_try_malloc (image.width * image.height);
  if (!image.pixels || !result.pixels || !crop_hole)
    {
      snprintf (message, message_size, _("out of memory while healing"));
      goto out;
    }
  {
    GeglRectangle abs = { box->x + crop.x, box->y + crop.y, crop.width, crop.height };
    ts_op_read_lab (input, &abs, image.pixels);
  }
  for (gsize y = 0; y < image.height; y++)
    memcpy (crop_hole + y * image.width, h.hole + (y + ry0) * h.width + rx0, image.width);

  ts_op_progress_init (&progress, operation);
  ts_op_progress_func (0.0, "starting", &progress);
  status = ts_heal (params, &image, crop_hole, aux2 ? &source : NULL, &result, NULL,
                    ts_op_progress_func, &progress, &error);
  ts_op_progress_func (1.0, "done", &progress);
  ts_op_progress_clear (&progress);
  if (status != TS_OK)
    {
      g_strlcpy (message, error.message[0] ? error.message : ts_status_string (status),
                 message_size);
      goto out;
    }
  if (!aux)
    blend_partial (&image, &result, &h, &crop);
  ok = write_hole (output, box, &crop, &result, &h);
  if (!ok)
    snprintf (message, message_size, _("out of memory while healing"));

out:
  g_free (h.hole);
  g_free (h.cover);
  g_free (crop_hole);
  g_free (image.pixels);
  g_free (result.pixels);
  g_free (source.pixels);
  return ok;
}
