/* Reading a feature map (texsynth:synthesize's aux) for the match.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TEXSYNTH_OP_FEATURES_H
#define TEXSYNTH_OP_FEATURES_H

#include <gegl.h>

#include "texsynth.h"

/* Reads the whole of `aux` as stored values in [0, 1] (R'G'B', no colour
 * conversion: a height or normal map is data, not colour), one channel if
 * it is grey, else three. `features->values` is g_malloc'd (g_free it).
 * FALSE with `message` if it cannot be read. */
gboolean ts_op_read_features (GeglOperation *operation,
                              GeglBuffer    *aux,
                              TsFeatureMap  *features,
                              gchar         *message,
                              gsize          message_size);

#endif /* TEXSYNTH_OP_FEATURES_H */
