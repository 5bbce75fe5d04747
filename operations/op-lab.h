/* Reading an exemplar into the engine's CIE Lab, and writing results back
 * into the exemplar's colour space, with the same numbers in every
 * process.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * babl chooses among its conversion paths by timing them (and caches the
 * choice per user), so two processes may convert the same pixels to Lab
 * differently, by up to about 1e-4; synthesis turns such a difference into
 * a completely different texture. The common exemplar formats are
 * therefore converted here, with fixed arithmetic. So are results on the
 * way back, so that a pixel copied from an 8-bit exemplar gets its very
 * bytes again.
 */
#ifndef TEXSYNTH_OP_LAB_H
#define TEXSYNTH_OP_LAB_H

#include <gegl.h>

/* The engine's pixel layout, exactly (see texsynth.h). */
#define TS_OP_FORMAT "CIE Lab alpha float"

/* Reads `rect` of `buffer` as "CIE Lab alpha float" into `lab` (4 floats
 * per pixel, rows of rect->width). Formats of the RGB and grey models in
 * u8, u16 or float, in a space with the sRGB, a linear or a gamma curve,
 * are converted here; any other format (or if memory is short) by babl. */
void ts_op_read_lab (GeglBuffer *buffer, const GeglRectangle *rect, float *lab);

/* Converts `n` pixels of `lab` (4 floats each) into `format`, written to
 * `out`: the formats ts_op_read_lab reads itself here (integers clamped
 * and rounded as babl does), any other by babl. */
void ts_op_lab_to_format (const float *lab, const Babl *format, void *out, size_t n);

/* Writes `rect` of `buffer`, in the buffer's own format, from `lab` (4
 * floats per pixel, rows `stride` bytes apart) with ts_op_lab_to_format. */
void ts_op_write_lab (GeglBuffer *buffer, const GeglRectangle *rect, const float *lab,
                      size_t stride);

#endif /* TEXSYNTH_OP_LAB_H */
