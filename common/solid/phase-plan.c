/* The phase guide's plan for one run on the default path: which phase of
 * the first view's finest exemplar lies in pieces, whether they are
 * stones, the split each exemplar's pieces are parted at, the necks'
 * height at which they are walled (lower for stones: solid.h), and, at
 * the finest level's start, the walls at necks (neck-walls.c), the phase
 * guide's distances (phase-guide.c) and the E-step's rule that keeps
 * stones apart (piece-topology.c).
 *
 * Stones are parted at their exemplar's joint split (phase-split.c), not
 * its phase split, so that dark stones are stones too and only the joints
 * below it part them; at the phase split dark stones counted as ground
 * and the volume's coherence suffered.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "solid.h"

#include <stdlib.h>
#include <string.h>

TsStatus
ts_solid_phase_plan (TsSolidPhasePlan *plan, const TsImage *const finest[], size_t exemplars,
                     const int exemplar_of[TS_SOLID_AXES])
{
  float phase[TS_SOLID_AXES], joint[TS_SOLID_AXES];
  int first = exemplar_of[ts_solid_first_axis (exemplar_of)];
  TsStatus status = TS_OK;

  memset (plan, 0, sizeof *plan);
  if (exemplars == 0 || exemplars > TS_SOLID_AXES || first < 0 || (size_t) first >= exemplars)
    return TS_ERROR_INVALID_ARGUMENT;
  for (size_t e = 0; e < exemplars; e++)
    ts_solid_splits (finest[e], &phase[e], &joint[e]);
  plan->pieces = ts_solid_phase_in_pieces (finest[first], phase[first]);
  if (plan->pieces == TS_SOLID_LIGHT_PIECES)
    status = ts_solid_exemplar_stones (finest[first], phase[first], &plan->stones);
  for (size_t e = 0; e < exemplars; e++)
    plan->split[e] = plan->stones ? joint[e] : phase[e];
  plan->neck_height = plan->stones ? TS_SOLID_STONE_NECK_HEIGHT : TS_SOLID_NECK_HEIGHT;
  plan->exemplars = exemplars;
  plan->first = (size_t) first;
  return status;
}

TsStatus
ts_solid_phase_plan_start (TsSolidPhasePlan *plan, TsSolidLevel *level,
                           const TsImage *const finest[], const int exemplar_of[TS_SOLID_AXES],
                           TsCancel *cancel)
{
  float split = plan->split[plan->first];
  TsStatus status;

  if (plan->pieces == TS_SOLID_NO_PIECES)
    return TS_OK;
  status = ts_solid_wall_necks (level, split, plan->pieces, plan->neck_height, cancel);
  for (size_t e = 0; e < plan->exemplars && status == TS_OK; e++)
    {
      status = ts_solid_phase_distances (finest[e], plan->split[e], &plan->distance[e]);
      if (status == TS_OK && ts_cancel_poll (cancel))
        status = TS_ERROR_CANCELLED;
    }
  if (status == TS_OK)
    status = ts_solid_phase_field (level, split, &plan->field, cancel);
  if (status != TS_OK)
    return status;
  for (int a = 0; a < TS_SOLID_AXES; a++)
    if (exemplar_of[a] >= 0)
      level->view[a].phase_distance = plan->distance[exemplar_of[a]];
  level->phase_field = plan->field;
  level->kept_apart = plan->stones ? TS_SOLID_LIGHT_PIECES : TS_SOLID_NO_PIECES;
  level->pieces_split = split;
  return TS_OK;
}

void
ts_solid_phase_plan_free (TsSolidPhasePlan *plan)
{
  for (size_t e = 0; e < TS_SOLID_AXES; e++)
    free (plan->distance[e]);
  free (plan->field);
  memset (plan, 0, sizeof *plan);
}
