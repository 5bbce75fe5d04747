/* Reading texsynth:guided's pads: the exemplar and the two guides.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TEXSYNTH_OP_GUIDES_H
#define TEXSYNTH_OP_GUIDES_H

#include <gegl.h>

#include "texsynth.h"

/* The bounding box of `pad`, or FALSE with `message` naming `what` if
 * nothing usable is connected (empty, unbounded or too large). */
gboolean ts_op_pad_box (GeglOperation *operation, const gchar *pad, const gchar *what,
                        GeglRectangle *box, gchar *message, gsize message_size);

/* Reads `box` of `buffer` as stored values in [0, 1] (R'G'B', no colour
 * conversion: a label map or a sketch is data): three floats per pixel,
 * g_malloc'd into *rgb (g_free it). *grey is TRUE if every pixel has
 * equal channels. FALSE with `message` if memory ran out. */
gboolean ts_op_read_guide (GeglBuffer *buffer, const GeglRectangle *box, float **rgb,
                           gboolean *grey, gchar *message, gsize message_size);

/* Keeps the first channel of each of `pixels` RGB pixels, in place. */
void     ts_op_guide_to_grey (float *rgb, gsize pixels);

#endif /* TEXSYNTH_OP_GUIDES_H */
