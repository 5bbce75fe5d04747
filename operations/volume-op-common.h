/* Helpers shared by texsynth:volume-slice and texsynth:volume-save:
 * reading the exemplar pads and getting the volume from the cache.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Exemplar rule of both ops: "input" is the exemplar of every slice
 * orientation that has no exemplar of its own; "aux", when connected, is
 * that of the slices across x (which show y, z), and "aux2" that of the
 * slices across y (which show x, z). The slices across z always follow
 * "input". The free-axis property then leaves one orientation
 * unconstrained (Kopf et al.'s two-exemplar solids).
 */
#ifndef TEXSYNTH_VOLUME_OP_COMMON_H
#define TEXSYNTH_VOLUME_OP_COMMON_H

#include "op-common.h"
#include "volume-cache.h"

/* Largest volume the ops offer (the engine allows more; 512^3 already
 * holds 2 GiB of Lab floats). */
#define TS_VOLUME_OP_MAX_SIZE 512

/* Values of both ops' free-axis enums (each op registers its own type). */
enum
{
  TS_VOLUME_OP_FREE_NONE = 0,
  TS_VOLUME_OP_FREE_X,
  TS_VOLUME_OP_FREE_Y,
  TS_VOLUME_OP_FREE_Z
};

/* The engine's defaults, for the property defaults. */
TsSolidParams ts_volume_op_default_params (void);

/* Fill a TsSolidParams from the properties of volume-properties.h, which
 * both ops' GeglProperties have under the same names. */
#define TS_VOLUME_OP_FILL_PARAMS(o, params)                                  \
  do {                                                                       \
    int patch_, fine_;                                                       \
    ts_solid_params_init (params);                                           \
    (params)->size = (size_t) (o)->size;                                     \
    (params)->periodic = (o)->periodic;                                      \
    (params)->quality = (o)->quality;                                        \
    (params)->seed = (o)->seed;                                              \
    ts_op_patch_sizes ((o)->patch_size, 0, &patch_, &fine_);                 \
    (params)->patch_size = patch_;                                           \
    (params)->max_iterations = (o)->iterations;                              \
    (params)->histogram_matching = (o)->histogram_matching;                  \
    (params)->cell_structure = (TsCellStructure) (o)->cell_structure;        \
    (params)->memory_limit = ts_op_memory_limit ((o)->memory_limit);         \
  } while (0)

/* All of the named input pad for any output (nothing if unbounded). */
GeglRectangle ts_volume_op_required_input (GeglOperation *operation, const gchar *pad);

/* Every input pad in the engine's format. */
void ts_volume_op_prepare_inputs (GeglOperation *operation);

/* Read the exemplars from the three pads' buffers (any may be NULL or
 * unconnected), apply the exemplar rule and `free_axis`, and return the
 * volume held from the cache, synthesising it with progress reported on
 * `operation`. NULL with `error` filled on failure. */
TsVolumeEntry *ts_volume_op_acquire (GeglOperation       *operation,
                                     GeglBuffer          *input,
                                     GeglBuffer          *aux,
                                     GeglBuffer          *aux2,
                                     const TsSolidParams *params,
                                     int                  free_axis,
                                     TsError             *error);

#endif /* TEXSYNTH_VOLUME_OP_COMMON_H */
