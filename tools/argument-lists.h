/* Several measurements in one run of a tool: its arguments split into
 * lists at each lone '+', so GEGL and babl start once for all of them.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_ARGUMENT_LISTS_H
#define TS_ARGUMENT_LISTS_H

#include <stdbool.h>

/* Measures one list: argv[1..argc-1] are its arguments, argv[0] the
 * program's name or a '+'; `several` says whether there are other lists.
 * Returns the tool's exit status. */
typedef int (*TsMeasureList) (int argc, char **argv, bool several);

/* Calls `measure` on each list in turn, up to the first that fails;
 * returns its exit status, or `success` after the last list. */
int ts_run_argument_lists (int argc, char **argv, TsMeasureList measure, int success);

#endif
