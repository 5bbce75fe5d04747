/* texsynth:heal's work between GEGL buffers and the engine: the hole from
 * the mask or the alpha, the part of the image to read, the blend of
 * partly transparent pixels and the write-back of the hole's pixels only.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TEXSYNTH_HEAL_IO_H
#define TEXSYNTH_HEAL_IO_H

#include <gegl-plugin.h>

#include "texsynth.h"

/* Heals `output` (already a copy of `input` over `box`) in place: only
 * hole pixels are written. `aux` is the mask or NULL (then the pixels that
 * are not fully opaque are the hole), `aux2` a source image or NULL.
 * Returns FALSE with `message` set if it could not heal; `output` is then
 * still the copy of the input. An empty hole is a success. */
gboolean ts_heal_op_run (GeglOperation       *operation,
                         const TsHealParams  *params,
                         GeglBuffer          *input,
                         GeglBuffer          *aux,
                         GeglBuffer          *aux2,
                         GeglBuffer          *output,
                         const GeglRectangle *box,
                         gchar               *message,
                         gsize                message_size);

#endif
