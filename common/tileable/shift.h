/* Choosing the shift of a tileable plan's band content (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_TILEABLE_SHIFT_H
#define TS_TILEABLE_SHIFT_H

#include "plan.h"

/* Chooses plan->shift_x/_y: the offset whose content best continues the
 * kept picture across the cuts (least squared Lab+alpha difference there),
 * coarse to fine. `input` is in the engine's working format. */
TsStatus ts_tileable_choose_shift (const TsImage *input, TsTileablePlan *plan);

#endif
