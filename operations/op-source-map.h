/* The synthesis's layout as an image: for each output pixel, the
 * exemplar pixel it was copied from, in gegl:map-absolute's convention.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * gegl:map-absolute reads its aux as two floats per pixel, the absolute
 * coordinates to sample, with pixel (i, j)'s centre at (i + 0.5, j + 0.5)
 * (an identity map holds exactly those). A source map in that format,
 * applied with sampler-type=nearest to any image aligned with the
 * exemplar (normal, roughness or height map), lays it out as the colour
 * result. Pixels are copied whole, never rotated or mirrored, so a normal
 * map's directions stay right.
 */
#ifndef TEXSYNTH_OP_SOURCE_MAP_H
#define TEXSYNTH_OP_SOURCE_MAP_H

#include <gegl.h>
#include <stdint.h>

/* Two floats per pixel, no colour model: what map-absolute asks for, so
 * nothing converts the coordinates on the way. */
const Babl *ts_op_source_map_format (void);

/* Input in the engine's format; output in the source-map format when
 * `source_map`, else in ts_op_result_format. */
void ts_op_prepare_source_map (GeglOperation *operation, gboolean source_map);

/* Writes the part of a `width` x `height` source map (2 int32 per pixel,
 * exemplar coordinates as the engine gives them; NULL = the identity)
 * placed at (x, y) that lies in `roi`, as absolute pixel-centre
 * coordinates of an exemplar whose origin is (origin_x, origin_y).
 * FALSE if memory ran out (the output is then cleared). */
gboolean ts_op_write_source_map (GeglBuffer          *output,
                                 const GeglRectangle *roi,
                                 const int32_t       *map,
                                 size_t               width,
                                 size_t               height,
                                 gint                 x,
                                 gint                 y,
                                 gint                 origin_x,
                                 gint                 origin_y);

#endif /* TEXSYNTH_OP_SOURCE_MAP_H */
