/* Style transfer's tone step (internal): the result's lightness, at the
 * scale of the picture's layout, moved towards the picture's.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_STYLE_TONE_H
#define TS_STYLE_TONE_H

#include "texsynth.h"

#include <stdbool.h>

/* How far the tone moves for a guide weight: weight / (1 + weight), the
 * guide's share against the texture's coherence (0 leaves the result as
 * synthesised). */
double   ts_style_tone_strength (double guide_weight);

/* Moves `output`'s tone (CIE L blurred by TS_STYLE_GUIDE_BLUR) that
 * share of the way to the picture's (`guides`' target guide, moved to
 * the exemplar's mean and spread of tone), by adding the difference to
 * the L of its visible pixels. Finer detail is left as synthesised; the
 * blur wraps across a tileable side (`wrap_x`, `wrap_y`), so the result
 * still tiles. */
TsStatus ts_style_tone (const TsGuides *guides, const TsImage *exemplar, bool wrap_x,
                        bool wrap_y, TsImage *output);

#endif
