/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "argument-lists.h"

#include <string.h>

int
ts_run_argument_lists (int argc, char **argv, TsMeasureList measure, int success)
{
  int start = 1, code = success;
  bool several = false;

  for (int i = 1; i < argc; i++)
    several = several || strcmp (argv[i], "+") == 0;
  /* Each list's arguments are argv[start..i-1]; argv[start - 1], the
   * program's name or a '+', stands in as its argv[0]. */
  for (int i = 1; i <= argc && code == success; i++)
    if (i == argc || strcmp (argv[i], "+") == 0)
      {
        code = measure (i - start + 1, argv + start - 1, several);
        start = i + 1;
      }
  return code;
}
