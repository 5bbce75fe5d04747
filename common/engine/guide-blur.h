/* Blurring a guide (internal): style transfer compares lightness at the
 * scale of a picture's layout, not of the texture's grain.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_GUIDE_BLUR_H
#define TS_GUIDE_BLUR_H

#include "texsynth.h"

/* Channel 0 of `image` blurred in place by a Gaussian of `sigma` pixels
 * (mirrored borders). */
TsStatus ts_guide_blur (TsImage *image, double sigma);

#endif
