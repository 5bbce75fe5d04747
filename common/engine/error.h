/* Error reporting shared by every part of the engine (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_ERROR_H
#define TS_ERROR_H

#include "texsynth.h"

/* Sets error (if not NULL) and returns status; printf-style message,
 * translated (po/ extracts ts_fail's third argument). */
TsStatus ts_fail (TsError *error, TsStatus status, const char *format, ...)
  __attribute__ ((format (printf, 3, 4)));

#endif
