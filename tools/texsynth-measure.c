/* texsynth-measure: quality measures of a synthesised texture against its
 * exemplar (definitions in metrics.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "image-io.h"
#include "metrics.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXIT_USAGE 2

static const char usage_text[] =
  "Usage: texsynth-measure [OPTION]... EXEMPLAR RESULT\n"
  "Measures how well RESULT, synthesised from EXEMPLAR, reproduces it.\n"
  "Images are compared in CIE Lab over 7x7 windows (alpha is ignored).\n"
  "\n"
  "Options:\n"
  "  --tileable      RESULT tiles in both directions: its windows wrap\n"
  "                  around the edges, and the seam measure is printed\n"
  "  --tileable=x    ... horizontally only (left/right edges)\n"
  "  --tileable=y    ... vertically only (top/bottom edges)\n"
  "  --json          print one JSON object instead of name: value lines\n"
  "  -h, --help      print this help and exit\n"
  "\n"
  "Measures (distances are RMS Lab differences per value, sqrt(SSD / 147)):\n"
  "  coherence     mean distance from result windows (every 2nd pixel) to\n"
  "                the nearest exemplar window; 0 = all of it is in the exemplar\n"
  "  completeness  mean distance from exemplar windows (every 2nd pixel) to\n"
  "                the nearest result window; 0 = all of the exemplar is used\n"
  "  seam          with --tileable: (mean distance of windows crossing the\n"
  "                wrap-around edges + 0.5) / (that of the others + 0.5);\n"
  "                about 1 = seamless\n"
  "  copy          largest region of RESULT copied verbatim (5x5 windows within\n"
  "                1 Lab RMS at one constant offset) over the exemplar's area;\n"
  "                1 = the exemplar pasted whole, near 0 = synthesised\n"
  "  sharpness     mean |grad L| of RESULT over that of EXEMPLAR; < 1 = blurrier\n"
  "  axis-edges    share of RESULT's gradient energy (Sobel on L) pointing within\n"
  "                10 degrees of the image axes, over EXEMPLAR's; > 1 = more\n"
  "                axis-aligned edges (blocks, seams, dashes) than the exemplar.\n"
  "                --json also gives both shares (axis_edges_exemplar, _result)\n"
  "                and anisotropy_exemplar: how strongly EXEMPLAR's edges favour\n"
  "                some orientations (0 = isotropic, 1 = all one way or on a\n"
  "                grid); axis-edges is meant for exemplars near 0\n"
  "\n"
  "Both images must be at least 7x7 pixels. Exit status: 0 on success,\n"
  "2 on bad arguments or images that cannot be read or are too small.\n";

static int
fail (const char *fmt, const char *arg)
{
  fputs ("texsynth-measure: ", stderr);
  fprintf (stderr, fmt, arg);
  fputc ('\n', stderr);
  return EXIT_USAGE;
}

static int
usage_error (const char *fmt, const char *arg)
{
  fail (fmt, arg);
  fputs ("Try 'texsynth-measure --help' for more information.\n", stderr);
  return EXIT_USAGE;
}

static void
print_value (const char *name, double value, bool json, bool *first)
{
  if (json)
    {
      printf ("%s\"%s\": ", *first ? "" : ", ", name);
      if (isfinite (value))
        printf ("%.6g", value);
      else
        fputs ("null", stdout);
    }
  else if (isfinite (value))
    printf ("%s: %.4f\n", name, value);
  else
    printf ("%s: %s\n", name, isnan (value) ? "nan" : "inf");
  *first = false;
}

static bool
load (const char *path, TsImage *image)
{
  char why[512];
  if (!ts_io_load (path, image, why, sizeof why))
    {
      fail ("%s", why);
      return false;
    }
  if (image->width < TS_MEASURE_MIN_SIDE || image->height < TS_MEASURE_MIN_SIDE)
    {
      fprintf (stderr,
               "texsynth-measure: '%s' is %zux%zu pixels; both images must be "
               "at least %dx%d\n",
               path, image->width, image->height, TS_MEASURE_MIN_SIDE, TS_MEASURE_MIN_SIDE);
      return false;
    }
  return true;
}

int
main (int argc, char **argv)
{
  const char *paths[2] = { NULL, NULL };
  int n_paths = 0;
  bool json = false, wrap_x = false, wrap_y = false, options_done = false;
  TsImage exemplar = { 0 }, result = { 0 };
  TsMeasures m;
  TsMeasureStatus status;
  int code = EXIT_USAGE;

  for (int i = 1; i < argc; i++)
    {
      const char *a = argv[i];
      if (options_done || a[0] != '-' || a[1] == '\0')
        {
          if (n_paths == 2)
            return usage_error ("too many arguments ('%s'): expected EXEMPLAR RESULT", a);
          paths[n_paths++] = a;
        }
      else if (strcmp (a, "--") == 0)
        options_done = true;
      else if (strcmp (a, "-h") == 0 || strcmp (a, "--help") == 0)
        {
          fputs (usage_text, stdout);
          return EXIT_SUCCESS;
        }
      else if (strcmp (a, "--json") == 0)
        json = true;
      else if (strcmp (a, "--tileable") == 0 || strcmp (a, "--tileable=xy") == 0
               || strcmp (a, "--tileable=yx") == 0 || strcmp (a, "--tileable=both") == 0)
        wrap_x = wrap_y = true;
      else if (strcmp (a, "--tileable=x") == 0)
        wrap_x = true;
      else if (strcmp (a, "--tileable=y") == 0)
        wrap_y = true;
      else if (strncmp (a, "--tileable=", 11) == 0)
        return usage_error ("invalid value in '%s': use x, y or xy", a);
      else
        return usage_error ("unknown option '%s'", a);
    }
  if (n_paths < 2)
    return usage_error ("%s", n_paths == 0 ? "missing EXEMPLAR and RESULT"
                                           : "missing RESULT (expected EXEMPLAR RESULT)");

  ts_io_init ();
  if (!load (paths[0], &exemplar) || !load (paths[1], &result))
    goto out;

  status = ts_measure_all (&exemplar, &result, wrap_x, wrap_y, &m);
  if (status == TS_MEASURE_OUT_OF_MEMORY)
    {
      fail ("%s", "out of memory: the images are too large to measure");
      goto out;
    }
  if (status != TS_MEASURE_OK)
    {
      fail ("%s", "an image is smaller than 7x7 pixels");
      goto out;
    }

  {
    bool first = true, tileable = wrap_x || wrap_y;
    if (json)
      fputc ('{', stdout);
    print_value ("coherence", m.coherence, json, &first);
    print_value ("completeness", m.completeness, json, &first);
    if (tileable || json)
      print_value ("seam", m.seam, json, &first);
    print_value ("copy", m.copy, json, &first);
    print_value ("sharpness", m.sharpness, json, &first);
    print_value (json ? "axis_edges" : "axis-edges", m.axis_edges, json, &first);
    if (json)
      {
        print_value ("axis_edges_exemplar", m.axis_edges_exemplar, json, &first);
        print_value ("axis_edges_result", m.axis_edges_result, json, &first);
        print_value ("anisotropy_exemplar", m.anisotropy_exemplar, json, &first);
      }
    if (json)
      printf (", \"tileable\": \"%s\", \"exemplar_size\": [%zu, %zu], "
              "\"result_size\": [%zu, %zu]}\n",
              wrap_x && wrap_y ? "xy" : wrap_x ? "x" : wrap_y ? "y" : "none",
              exemplar.width, exemplar.height, result.width, result.height);
  }
  code = fflush (stdout) == 0 ? EXIT_SUCCESS : EXIT_USAGE;

out:
  free (exemplar.pixels);
  free (result.pixels);
  return code;
}
