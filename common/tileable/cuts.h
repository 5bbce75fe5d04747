/* Placing the joins of a tileable plan on minimum-cost cuts (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_TILEABLE_CUTS_H
#define TS_TILEABLE_CUTS_H

#include "plan.h"

/* Moves each join between kept picture and band, within `reach` of its
 * nominal place towards the edge and `transition` towards the middle,
 * onto the path where the two differ least (a minimum-cost cut), so the
 * optimization starts from a nearly invisible join. `input` is in the
 * engine's working format. */
TsStatus ts_tileable_place_cuts (const TsImage *input, TsTileablePlan *plan);

#endif
