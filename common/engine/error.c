/* Error reporting shared by every part: status names and ts_fail's
 * translated, formatted messages.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "error.h"
#include "i18n.h"

#include <stdarg.h>
#include <stdio.h>

const char *
ts_status_string (TsStatus status)
{
  switch (status)
    {
    case TS_OK: return TS_ ("success");
    case TS_ERROR_INVALID_ARGUMENT: return TS_ ("invalid argument");
    case TS_ERROR_BAD_PARAMETER: return TS_ ("parameter out of range");
    case TS_ERROR_EMPTY_EXEMPLAR: return TS_ ("the exemplar is empty");
    case TS_ERROR_TRANSPARENT_EXEMPLAR: return TS_ ("the exemplar is fully transparent");
    case TS_ERROR_EXEMPLAR_TOO_SMALL: return TS_ ("the exemplar is too small");
    case TS_ERROR_TOO_LARGE: return TS_ ("the output would need too much memory");
    case TS_ERROR_OUT_OF_MEMORY: return TS_ ("out of memory");
    case TS_ERROR_CANCELLED: return TS_ ("cancelled");
    case TS_ERROR_IO: return TS_ ("a file could not be read or written");
    case TS_ERROR_BAD_FILE: return TS_ ("the file is truncated or malformed");
    case TS_ERROR_NOTHING_TO_SAMPLE: return TS_ ("there are no known pixels to fill the hole from");
    }
  return TS_ ("unknown error");
}

TsStatus
ts_fail (TsError *error, TsStatus status, const char *format, ...)
{
  if (error)
    {
      va_list args;
      error->status = status;
      va_start (args, format);
      /* Every caller's format is translated here; po/meson.build extracts
       * ts_fail's third argument. */
      vsnprintf (error->message, sizeof error->message, TS_ (format), args);
      va_end (args);
    }
  return status;
}
