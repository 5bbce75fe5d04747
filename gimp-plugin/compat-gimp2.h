/* GIMP 2.10 glue shared by its files: a procedure's outcome and the heal
 * procedures (heal-gimp2.c).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_COMPAT_GIMP2_H
#define TEXSYNTH_COMPAT_GIMP2_H

#include "texsynth-plugin.h"

typedef struct
{
  GimpPDBStatusType status;
  gchar            *message;   /* for the caller when status is an error */
  gint32            new_image; /* -1 if none */
} Outcome;

/* Records a failure (status and message, which it takes) and returns FALSE. */
static inline gboolean
fail (Outcome *outcome, GimpPDBStatusType status, gchar *message)
{
  outcome->status = status;
  outcome->message = message;
  return FALSE;
}

/* plug-in-texsynth-heal-selection, -heal-transparency and -uncrop. */
gboolean ts_run_heal2 (const gchar *name, GimpRunMode mode, const GimpParam *params,
                       gint n_params, Outcome *outcome);

#endif /* TEXSYNTH_COMPAT_GIMP2_H */
