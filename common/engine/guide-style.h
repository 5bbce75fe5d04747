/* Style transfer's guides (internal): lightness at the scale of a
 * picture's layout, and how much grain the exemplar has around it.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_GUIDE_STYLE_H
#define TS_GUIDE_STYLE_H

#include "texsynth.h"

#include <stdbool.h>

/* Style transfer's guides are lightness blurred by a Gaussian of this
 * many pixels: details below it (a texture's grain) are left to the
 * exemplar. Chosen on bark, granite1, rock and wood1 restyling land1
 * (192², seed 1, benchmarks/style-transfer.sh; then with the guide alike
 * at every level and a denser grid):
 * blurred-lightness correlation 0.94-0.96 and sharpness 0.61-0.93 at 4,
 * against 0.98-0.99 and 0.49-0.87 at 2, 0.85-0.91 and 0.61-0.96 at 6. */
#define TS_STYLE_GUIDE_BLUR 4.0
/* A style guide's contrast channel is scaled so that a contrast off by
 * its spread over the exemplar costs this many times what a tone off by
 * the tone's spread does. Without it a picture's even areas took the
 * exemplar's even parts, and the grain that darkens or lightens its
 * surroundings (a rock's joints, a granite's veins) was left out. On
 * the tuning half of benchmarks/style-transfer.sh (192², seed 1), the
 * guide's cost read at the neighbourhood's centre: sharpness against
 * the exemplar 0.92-0.96 and blurred-lightness correlation 0.926-0.949
 * at 4, against 0.91-0.94 and 0.925-0.955 at 3, 0.87-0.92 and
 * 0.933-0.958 at 2 (0.63-0.96 and 0.943-0.964 without the channel). */
#define TS_STYLE_CONTRAST_WEIGHT 4.0
/* The target's contrast is the exemplar's mean at the target's tone, in
 * this many steps of the exemplar's tones: fine enough to follow how
 * grain changes with the tone, coarse enough that each step holds many
 * pixels of a small exemplar. */
#define TS_STYLE_TONE_STEPS 16
/* Channels of a style transfer's guides: the tone (blurred lightness)
 * and the grain's local contrast. */
#define TS_STYLE_GUIDE_CHANNELS 2

/* Mean and standard deviation of every `stride`-th float of `values`
 * (n of them; only those whose `alpha` is positive, if given). */
void     ts_guide_spread (const float *values, size_t stride, size_t n, const float *alpha,
                          double *mean, double *sd);

/* Moves the n values of `tone` (`stride` floats apart) to the mean and
 * spread of the exemplar's ex_n values `ex_tone` (`ex_stride` apart;
 * only those whose `alpha` is positive); returns that spread. */
double   ts_tone_to_exemplar (const float *ex_tone, size_t ex_stride, size_t ex_n,
                              const float *alpha, float *tone, size_t stride, size_t n);

/* The w x h values of `values` (one per pixel, `stride` floats apart)
 * blurred in place by a Gaussian of `sigma` pixels: borders mirrored, or
 * wrapped where `wrap_x` / `wrap_y`. Takes w x h floats meanwhile. */
TsStatus ts_blur_values (float *values, size_t stride, size_t w, size_t h, double sigma,
                         bool wrap_x, bool wrap_y);

/* Makes style transfer's guides in place. On entry channel 0 of
 * `ex_guide` is the exemplar's lightness (`exemplar` its pixels, for
 * their alpha) and channel 0 of `target_guide` the picture's. On return
 * channel 0 of both is the tone, the target's moved to the exemplar's
 * mean and spread, and channel 1 the grain's contrast: the exemplar's
 * own, and for the target the exemplar's mean, so every part of the
 * picture asks for grain as strong as the exemplar's usual grain. */
TsStatus ts_style_guides (const TsImage *exemplar, TsImage *ex_guide, TsImage *target_guide);

#endif
