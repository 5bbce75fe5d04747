/* Loading and saving images as engine Lab+alpha float images through GEGL,
 * for the command-line tools and tests.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_IMAGE_IO_H
#define TS_IMAGE_IO_H

#include "texsynth.h"

/* Call once before the others (gegl_init); safe to call repeatedly. */
void ts_io_init (void);

/* Loads any image GEGL can read into a newly allocated image (free
 * `image->pixels` with free()). Returns false and prints nothing on
 * failure; `why` (may be NULL) receives a message. */
bool ts_io_load (const char *path, TsImage *image, char *why, size_t why_size);

/* Saves an image to a file whose type GEGL picks from the extension. */
bool ts_io_save (const char *path, const TsImage *image, char *why, size_t why_size);

#endif
