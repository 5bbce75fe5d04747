/* texsynth-measure: quality measures of a synthesised texture against its
 * exemplar (definitions in metrics.h), with --lattice how well it keeps
 * the exemplar's repeat (lattice-metrics.h), and with --shapes the shapes
 * of their phases (shape-metrics.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "argument-lists.h"
#include "image-io.h"
#include "lattice-metrics.h"
#include "measure-guided.h"
#include "metrics.h"
#include "shape-metrics.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXIT_USAGE 2

static const char usage_text[] =
  "Usage: texsynth-measure [OPTION]... EXEMPLAR RESULT...\n"
  "  or:  texsynth-measure --shapes [--phases=N] [--json] EXEMPLAR RESULT...\n"
  "Measures how well RESULT, synthesised from EXEMPLAR, reproduces it.\n"
  "Images are compared in CIE Lab over 7x7 windows (alpha is ignored).\n"
  "  or:  texsynth-measure ARGUMENTS + ARGUMENTS...\n"
  "Several RESULTs are each measured against EXEMPLAR, with the same options;\n"
  "their figures follow in order, each after a 'result: PATH' line (with\n"
  "--json, one object per line). Argument lists joined by '+' (a file named\n"
  "'+' is './+') run in turn, each with its own options, in one process; the\n"
  "first that fails ends the run.\n"
  "\n"
  "Options:\n"
  "  --tileable      RESULT tiles in both directions: its windows wrap\n"
  "                  around the edges, and the seam measure is printed\n"
  "  --tileable=x    ... horizontally only (left/right edges)\n"
  "  --tileable=y    ... vertically only (top/bottom edges)\n"
  "  --json          print a JSON object (with \"result\", its path) instead of\n"
  "                  name: value lines\n"
  "  --lattice       also measure whether RESULT keeps EXEMPLAR's lattice (see\n"
  "                  lattice below); EXEMPLAR must be at least 12x12\n"
  "  --shapes        measure the shapes of the phases of EXEMPLAR and of each\n"
  "                  RESULT instead (see Shapes below)\n"
  "  --phases=N      with --shapes: split the colours into N = 2 (default) or 3\n"
  "                  phases\n"
  "  --exemplar-guide=PATH --target-guide=PATH\n"
  "                  guided synthesis by labels: PATH are EXEMPLAR's label map\n"
  "                  (each colour a label) and the map RESULT was grown to;\n"
  "                  prints the label measures below instead\n"
  "  --style-target=PATH  style transfer: PATH is the image RESULT restyles;\n"
  "                  prints style-correlation and sharpness instead\n"
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
  "  lattice       with --lattice: R(d), the autocorrelation of lightness at\n"
  "                offset d (mean removed, summed over the overlap, divided\n"
  "                by its size and the variance: 1 at d = 0), has peaks (local\n"
  "                maxima) 6-60 px long and at most half EXEMPLAR across and\n"
  "                down; RESULT's R over EXEMPLAR's at the 4 highest,\n"
  "                averaged: about 1 = lattice kept, about 0 = lost.\n"
  "                Only for near-regular exemplars, whose highest peak\n"
  "                (lattice-strength) is >= 0.3; else 'n/a' (JSON null).\n"
  "                Each peak follows on a lattice-peak line (JSON:\n"
  "                lattice_strength, lattice_peaks with dx, dy, exemplar,\n"
  "                result)\n"
  "\n"
  "Guided (docs/measure.md): a result pixel's label is that of the centre of its\n"
  "nearest exemplar 7x7 window. label-fidelity: the share, over pixels more than\n"
  "3 px from the target's label edges, whose label is the target's there;\n"
  "label-edge-offset: mean distance (px) between the target's and the result's\n"
  "label edges, both ways; region-coherence: per label, coherence of those\n"
  "pixels; style-correlation: correlation of lightness blurred by a Gaussian of\n"
  "4 px between RESULT and the style target (1 = the layout followed).\n"
  "\n"
  "Shapes (--shapes): k-means on EXEMPLAR's Lab colours (started from the\n"
  "mean colours of N equal-count bands of its lightness) gives N phase\n"
  "centres; every image's pixels go to the nearest centre, phase 0 the\n"
  "darkest. Per image and phase:\n"
  "  fraction        share of the pixels in the phase\n"
  "  chord-rows      mean length of the phase's runs along rows, and along\n"
  "  chord-columns   columns (runs cut by the image's edge count as seen)\n"
  "  solidity        over the phase's 4-connected components of at least 12\n"
  "                  pixels, the area-weighted mean of area / convex-hull area\n"
  "                  (hull around the pixel squares' corners: 1 for a\n"
  "                  rectangle, near 1 for a disc); nan if there are none\n"
  "  components      how many components of at least 12 pixels\n"
  "  s2              two-point correlation for r = 1..32 pixels: probability\n"
  "                  that two pixels r apart both lie in the phase, mean of\n"
  "                  rows and columns, pairs inside the image only (no wrap)\n"
  "Text output gives the centres, then per image a line per phase and a\n"
  "line of its 32 s2 values; --json one object with \"centres\" and\n"
  "\"images\" (each with \"path\", \"role\" and per phase the values above).\n"
  "\n"
  "Every image must be at least 7x7 pixels. Exit status: 0 on success,\n"
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
               "texsynth-measure: '%s' is %zux%zu pixels; every image must be "
               "at least %dx%d\n",
               path, image->width, image->height, TS_MEASURE_MIN_SIDE, TS_MEASURE_MIN_SIDE);
      return false;
    }
  return true;
}

/* A JSON string: `text` quoted, with quotes, backslashes and control
 * characters escaped. */
static void
print_json_string (const char *text)
{
  putchar ('"');
  for (const unsigned char *c = (const unsigned char *) text; *c; c++)
    if (*c == '"' || *c == '\\')
      printf ("\\%c", *c);
    else if (*c < 0x20)
      printf ("\\u%04x", *c);
    else
      putchar (*c);
  putchar ('"');
}

static void
print_number (double value, bool json)
{
  if (isfinite (value))
    printf (json ? "%.6g" : "%.4f", value);
  else
    fputs (json ? "null" : "nan", stdout);
}

static void
print_shapes (const char *path, bool is_exemplar, const TsImage *image, const TsPhaseShape *shape,
              int phases, bool json)
{
  if (json)
    {
      fputs ("{\"path\": ", stdout);
      print_json_string (path);
      printf (", \"role\": \"%s\", \"size\": [%zu, %zu], \"phases\": [",
              is_exemplar ? "exemplar" : "result", image->width, image->height);
    }
  else
    printf ("%s: %s\n", is_exemplar ? "exemplar" : "result", path);
  for (int k = 0; k < phases; k++)
    {
      const TsPhaseShape *p = &shape[k];
      if (json)
        {
          printf ("%s{\"fraction\": ", k ? ", " : "");
          print_number (p->fraction, true);
          fputs (", \"chord_rows\": ", stdout);
          print_number (p->chord_rows, true);
          fputs (", \"chord_columns\": ", stdout);
          print_number (p->chord_columns, true);
          fputs (", \"solidity\": ", stdout);
          print_number (p->solidity, true);
          printf (", \"components\": %zu, \"s2\": [", p->components);
        }
      else
        {
          printf ("  phase %d: fraction ", k);
          print_number (p->fraction, false);
          fputs (" chord-rows ", stdout);
          print_number (p->chord_rows, false);
          fputs (" chord-columns ", stdout);
          print_number (p->chord_columns, false);
          fputs (" solidity ", stdout);
          print_number (p->solidity, false);
          printf (" components %zu\n  phase %d s2:", p->components, k);
        }
      for (int r = 1; r <= TS_SHAPE_MAX_LAG; r++)
        {
          fputs (json ? (r > 1 ? ", " : "") : " ", stdout);
          print_number (p->s2[r], json);
        }
      fputs (json ? "]}" : "\n", stdout);
    }
  if (json)
    fputs ("]}", stdout);
}

/* --shapes: the phases' centres from paths[0], then every image's shapes,
 * all measured before any is printed, so a failure prints no figures. */
static int
measure_shapes (const char *const *paths, int n_paths, int phases, bool json)
{
  TsPhaseCentres centres;
  TsPhaseShape *shapes = malloc ((size_t) n_paths * TS_SHAPE_MAX_PHASES * sizeof *shapes);
  TsImage *sizes = calloc ((size_t) n_paths, sizeof *sizes);
  TsImage image = { 0 };
  TsMeasureStatus status = TS_MEASURE_OK;
  int code = EXIT_USAGE, measured = 0;

  if (!shapes || !sizes)
    {
      free (shapes);
      free (sizes);
      return fail ("%s", "out of memory");
    }
  ts_io_init ();
  for (; measured < n_paths && status == TS_MEASURE_OK; measured++)
    {
      if (!load (paths[measured], &image))
        break;
      if (measured == 0)
        status = ts_shape_centres (&image, phases, &centres);
      if (status == TS_MEASURE_OK)
        status = ts_shape_measure (&image, &centres, shapes + (size_t) measured * TS_SHAPE_MAX_PHASES);
      sizes[measured] = (TsImage) { image.width, image.height, NULL };
      free (image.pixels);
      image.pixels = NULL;
    }
  if (status != TS_MEASURE_OK)
    fail ("%s", status == TS_MEASURE_OUT_OF_MEMORY ? "out of memory: the images are too large to measure"
                                                    : "an image has too few pixels");
  else if (measured == n_paths)
    {
      if (json)
        printf ("{\"phases\": %d, \"max_lag\": %d, \"centres\": [", phases, TS_SHAPE_MAX_LAG);
      else
        printf ("phases: %d (k-means on the exemplar's Lab colours, darkest first)\n", phases);
      for (int k = 0; k < phases; k++)
        if (json)
          printf ("%s[%.6g, %.6g, %.6g]", k ? ", " : "", centres.centre[k][0], centres.centre[k][1],
                  centres.centre[k][2]);
        else
          printf ("centre %d: L %.2f a %.2f b %.2f\n", k, centres.centre[k][0], centres.centre[k][1],
                  centres.centre[k][2]);
      if (json)
        fputs ("], \"images\": [", stdout);
      for (int i = 0; i < n_paths; i++)
        {
          if (json && i > 0)
            fputs (", ", stdout);
          print_shapes (paths[i], i == 0, &sizes[i], shapes + (size_t) i * TS_SHAPE_MAX_PHASES, phases, json);
        }
      if (json)
        fputs ("]}\n", stdout);
      code = fflush (stdout) == 0 ? EXIT_SUCCESS : EXIT_USAGE;
    }
  free (shapes);
  free (sizes);
  return code;
}

/* --lattice: the figure (or why there is none), the exemplar's strength
 * and its peaks with both images' autocorrelation there. */
static void
print_lattice (const TsLattice *lattice, bool json)
{
  if (json)
    {
      fputs (", \"lattice\": ", stdout);
      print_number (lattice->lattice, true);
      fputs (", \"lattice_strength\": ", stdout);
      print_number (lattice->strength, true);
      fputs (", \"lattice_peaks\": [", stdout);
    }
  else if (ts_lattice_near_regular (lattice))
    printf ("lattice: %.4f\n", lattice->lattice);
  else if (lattice->n_peaks == 0)
    printf ("lattice: n/a (not near-regular: no peak at %d-%d px)\n", TS_LATTICE_MIN_LAG,
            TS_LATTICE_MAX_LAG);
  else
    printf ("lattice: n/a (not near-regular: strongest peak %.4f < %.1f)\n", lattice->strength,
            TS_LATTICE_NEAR_REGULAR);
  if (!json)
    printf ("lattice-strength: %.4f\n", lattice->strength);
  for (size_t i = 0; i < lattice->n_peaks; i++)
    {
      const TsLatticePeak *p = &lattice->peak[i];
      if (json)
        printf ("%s{\"dx\": %d, \"dy\": %d, \"exemplar\": ", i ? ", " : "", p->dx, p->dy);
      else
        printf ("lattice-peak: dx %d dy %d exemplar ", p->dx, p->dy);
      print_number (p->exemplar, json);
      fputs (json ? ", \"result\": " : " result ", stdout);
      print_number (p->result, json);
      fputs (json ? "}" : "\n", stdout);
    }
  if (json)
    fputs ("]", stdout);
}

/* One result's figures, after its "result: PATH" line when there are
 * several; with --json one object per line. `lattice` is NULL without
 * --lattice. */
static void
print_measures (const char *path, const TsMeasures *m, const TsLattice *lattice,
                const TsImage *exemplar, const TsImage *result, bool wrap_x, bool wrap_y, bool json,
                bool several)
{
  bool first = true, tileable = wrap_x || wrap_y;
  if (json)
    {
      fputs ("{\"result\": ", stdout);
      print_json_string (path);
      first = false;
    }
  else if (several)
    printf ("result: %s\n", path);
  print_value ("coherence", m->coherence, json, &first);
  print_value ("completeness", m->completeness, json, &first);
  if (tileable || json)
    print_value ("seam", m->seam, json, &first);
  print_value ("copy", m->copy, json, &first);
  print_value ("sharpness", m->sharpness, json, &first);
  print_value (json ? "axis_edges" : "axis-edges", m->axis_edges, json, &first);
  if (lattice)
    print_lattice (lattice, json);
  if (json)
    {
      print_value ("axis_edges_exemplar", m->axis_edges_exemplar, json, &first);
      print_value ("axis_edges_result", m->axis_edges_result, json, &first);
      print_value ("anisotropy_exemplar", m->anisotropy_exemplar, json, &first);
      printf (", \"tileable\": \"%s\", \"exemplar_size\": [%zu, %zu], "
              "\"result_size\": [%zu, %zu]}\n",
              wrap_x && wrap_y ? "xy" : wrap_x ? "x" : wrap_y ? "y" : "none",
              exemplar->width, exemplar->height, result->width, result->height);
    }
}

/* --lattice: the exemplar's peaks, with a message if it cannot have any. */
static bool
lattice_of_exemplar (const char *path, const TsImage *exemplar, TsLattice *out)
{
  TsMeasureStatus status = ts_lattice_exemplar (exemplar, out);
  if (status == TS_MEASURE_TOO_SMALL)
    fprintf (stderr,
             "texsynth-measure: '%s' is %zux%zu pixels; --lattice needs an exemplar of at "
             "least %dx%d\n",
             path, exemplar->width, exemplar->height, TS_LATTICE_MIN_SIDE, TS_LATTICE_MIN_SIDE);
  else if (status != TS_MEASURE_OK)
    fail ("%s", "out of memory: the exemplar is too large for --lattice");
  return status == TS_MEASURE_OK;
}

/* --lattice: the result's autocorrelation at the exemplar's peaks, with a
 * message if it is too small to hold their offsets. */
static bool
lattice_of_result (const char *path, const TsImage *result, TsLattice *lattice)
{
  size_t need_w, need_h;
  if (ts_lattice_result (result, lattice) == TS_MEASURE_OK)
    return true;
  ts_lattice_min_result_size (lattice, &need_w, &need_h);
  fprintf (stderr,
           "texsynth-measure: '%s' is %zux%zu pixels; the exemplar's lattice peaks (offsets up "
           "to %zu px across and %zu px down) need a result of at least %zux%zu\n",
           path, result->width, result->height, need_w / 2, need_h / 2, need_w, need_h);
  return false;
}

/* paths[1..] each against paths[0], read once; all are measured before
 * any is printed, so a failure prints no figures. */
static int
measure_results (const char *const *paths, int n_paths, bool wrap_x, bool wrap_y, bool lattice,
                 bool json, bool several)
{
  int n_results = n_paths - 1, measured = 0, code = EXIT_USAGE;
  TsMeasures *m = calloc ((size_t) n_results, sizeof *m);
  TsImage *sizes = calloc ((size_t) n_results, sizeof *sizes);
  TsLattice *lattices = lattice ? calloc ((size_t) n_results, sizeof *lattices) : NULL;
  TsLattice exemplar_lattice;
  TsImage exemplar = { 0 }, result = { 0 };

  if (!m || !sizes || (lattice && !lattices))
    {
      free (m);
      free (sizes);
      free (lattices);
      return fail ("%s", "out of memory");
    }
  ts_io_init ();
  if (load (paths[0], &exemplar)
      && (!lattice || lattice_of_exemplar (paths[0], &exemplar, &exemplar_lattice)))
    for (; measured < n_results; measured++)
      {
        TsMeasureStatus status = TS_MEASURE_OK;
        if (!load (paths[1 + measured], &result))
          break;
        if (lattice)
          {
            lattices[measured] = exemplar_lattice;
            if (!lattice_of_result (paths[1 + measured], &result, &lattices[measured]))
              {
                free (result.pixels);
                result.pixels = NULL;
                break;
              }
          }
        status = ts_measure_all (&exemplar, &result, wrap_x, wrap_y, &m[measured]);
        sizes[measured] = (TsImage) { result.width, result.height, NULL };
        free (result.pixels);
        result.pixels = NULL;
        if (status != TS_MEASURE_OK)
          {
            fail ("%s", status == TS_MEASURE_OUT_OF_MEMORY
                          ? "out of memory: the images are too large to measure"
                          : "an image is smaller than 7x7 pixels");
            break;
          }
      }
  if (measured == n_results)
    {
      for (int i = 0; i < n_results; i++)
        print_measures (paths[1 + i], &m[i], lattice ? &lattices[i] : NULL, &exemplar,
                        &sizes[i], wrap_x, wrap_y, json, several || n_results > 1);
      code = fflush (stdout) == 0 ? EXIT_SUCCESS : EXIT_USAGE;
    }
  free (exemplar.pixels);
  free (m);
  free (sizes);
  free (lattices);
  return code;
}

/* One argument list: argv[1..argc-1], argv[0] unused. `several`: there
 * are other lists, so every result's text figures are named. */
static int
measure_arguments (int argc, char **argv, bool several)
{
  /* the paths, gathered at the front of argv's arguments */
  const char *const *paths = (const char *const *) argv + 1;
  int n_paths = 0, phases = TS_SHAPE_DEFAULT_PHASES;
  bool json = false, wrap_x = false, wrap_y = false, options_done = false, shapes = false;
  bool lattice = false;
  const char *exemplar_guide = NULL, *target_guide = NULL, *style_target = NULL;

  for (int i = 1; i < argc; i++)
    {
      const char *a = argv[i];
      if (options_done || a[0] != '-' || a[1] == '\0')
        argv[1 + n_paths++] = argv[i];
      else if (strcmp (a, "--") == 0)
        options_done = true;
      else if (strcmp (a, "-h") == 0 || strcmp (a, "--help") == 0)
        {
          fputs (usage_text, stdout);
          return EXIT_SUCCESS;
        }
      else if (strcmp (a, "--json") == 0)
        json = true;
      else if (strcmp (a, "--shapes") == 0)
        shapes = true;
      else if (strcmp (a, "--lattice") == 0)
        lattice = true;
      else if (strncmp (a, "--exemplar-guide=", 17) == 0)
        exemplar_guide = a + 17;
      else if (strncmp (a, "--target-guide=", 15) == 0)
        target_guide = a + 15;
      else if (strncmp (a, "--style-target=", 15) == 0)
        style_target = a + 15;
      else if (strcmp (a, "--phases=2") == 0 || strcmp (a, "--phases=3") == 0)
        phases = a[9] - '0';
      else if (strncmp (a, "--phases", 8) == 0)
        return usage_error ("invalid phases in '%s': use --phases=2 or --phases=3", a);
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
  if (phases != TS_SHAPE_DEFAULT_PHASES && !shapes)
    return usage_error ("%s", "--phases needs --shapes");
  if ((wrap_x || wrap_y) && shapes)
    return usage_error ("%s", "--tileable does not apply to --shapes");
  if (lattice && shapes)
    return usage_error ("%s", "--lattice does not apply to --shapes");
  if (n_paths >= 2 && shapes)
    return measure_shapes (paths, n_paths, phases, json);
  if (n_paths < 2)
    return usage_error ("%s", n_paths == 0 ? "missing EXEMPLAR and RESULT"
                                           : "missing RESULT (expected EXEMPLAR RESULT)");

  if (!exemplar_guide != !target_guide)
    return usage_error ("%s", "--exemplar-guide and --target-guide go together");
  if (exemplar_guide || style_target)
    return ts_measure_guided_results (paths, n_paths, exemplar_guide, target_guide, style_target,
                                      json, several);
  return measure_results (paths, n_paths, wrap_x, wrap_y, lattice, json, several);
}

int
main (int argc, char **argv)
{
  return ts_run_argument_lists (argc, argv, measure_arguments, EXIT_SUCCESS);
}
