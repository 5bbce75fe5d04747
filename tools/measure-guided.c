/* texsynth-measure's guided measures (see measure-guided.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "measure-guided.h"
#include "guided-metrics.h"
#include "image-io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXIT_USAGE 2

typedef struct
{
  TsLabelMeasures labels;
  double style_correlation, sharpness;
} Figures;

static bool
load (const char *path, TsImage *image)
{
  char why[512];
  if (ts_io_load (path, image, why, sizeof why))
    return true;
  fprintf (stderr, "texsynth-measure: %s\n", why);
  return false;
}

static bool
same_size (const char *what, const char *path, const TsImage *image, const TsImage *like)
{
  if (image->width == like->width && image->height == like->height)
    return true;
  fprintf (stderr, "texsynth-measure: %s '%s' is %zux%zu; it must be %zux%zu\n", what, path,
           image->width, image->height, like->width, like->height);
  return false;
}

static void
print_figure (const char *text_name, const char *json_name, double value, bool json)
{
  if (json)
    printf (", \"%s\": ", json_name);
  else
    printf ("%s: ", text_name);
  if (isfinite (value))
    printf (json ? "%.6g" : "%.4f\n", value);
  else
    fputs (json ? "null" : "nan\n", stdout);
}

static void
print_figures (const char *path, const Figures *f, bool labels, bool style, bool json,
               bool several)
{
  if (json)
    printf ("{\"result\": \"%s\"", path);
  else if (several)
    printf ("result: %s\n", path);
  if (labels)
    {
      print_figure ("label-fidelity", "label_fidelity", f->labels.fidelity, json);
      print_figure ("label-edge-offset", "label_edge_offset", f->labels.edge_offset, json);
      if (json)
        fputs (", \"region_coherence\": [", stdout);
      for (size_t l = 0; l < f->labels.labels; l++)
        {
          double v = f->labels.region_coherence[l];
          if (json)
            printf (isfinite (v) ? "%s%.6g" : "%snull", l ? ", " : "", v);
          else
            printf ("region-coherence: label %zu %.4f\n", l, v);
        }
      if (json)
        fputs ("]", stdout);
    }
  if (style)
    {
      print_figure ("style-correlation", "style_correlation", f->style_correlation, json);
      print_figure ("sharpness", "sharpness", f->sharpness, json);
    }
  if (json)
    fputs ("}\n", stdout);
}

int
ts_measure_guided_results (const char *const *paths, int n_paths, const char *exemplar_guide,
                           const char *target_guide, const char *style_target, bool json,
                           bool several)
{
  bool labels = exemplar_guide && target_guide, style = style_target != NULL, ok;
  TsImage exemplar = { 0 }, ex_guide = { 0 }, t_guide = { 0 }, style_img = { 0 }, result = { 0 };
  uint8_t *ex_labels = NULL, *t_labels = NULL;
  Figures *figures = calloc ((size_t) n_paths, sizeof *figures);
  size_t label_count = 0;
  int measured = 0, code = EXIT_USAGE;

  ts_io_init ();
  ok = figures && load (paths[0], &exemplar);
  if (ok && labels)
    ok = load (exemplar_guide, &ex_guide) && load (target_guide, &t_guide)
         && same_size ("the exemplar guide", exemplar_guide, &ex_guide, &exemplar);
  if (ok && labels)
    {
      ex_labels = malloc (ex_guide.width * ex_guide.height);
      t_labels = malloc (t_guide.width * t_guide.height);
      ok = ex_labels && t_labels;
      if (ok && !ts_guide_label_maps (&ex_guide, &t_guide, ex_labels, t_labels, &label_count))
        {
          fprintf (stderr, "texsynth-measure: the exemplar guide '%s' has more than %d colours: "
                   "too many labels\n", exemplar_guide, TS_LABEL_MAX);
          ok = false;
        }
    }
  if (ok && style)
    ok = load (style_target, &style_img);
  for (; ok && measured < n_paths - 1; measured++)
    {
      Figures *f = &figures[measured];
      TsMeasureStatus status = TS_MEASURE_OK;
      const char *path = paths[1 + measured];
      ok = load (path, &result)
           && (!labels || same_size ("the target guide", target_guide, &t_guide, &result))
           && (!style || same_size ("the style target", style_target, &style_img, &result));
      if (ok && labels)
        status = ts_measure_labels (&exemplar, ex_labels, &result, t_labels, label_count,
                                    &f->labels);
      if (ok && style && status == TS_MEASURE_OK)
        status = ts_measure_style_correlation (&style_img, &result, &f->style_correlation);
      if (ok && style && status == TS_MEASURE_OK)
        status = ts_measure_sharpness (&exemplar, &result, &f->sharpness);
      free (result.pixels);
      result.pixels = NULL;
      if (ok && status != TS_MEASURE_OK)
        {
          fprintf (stderr, "texsynth-measure: %s\n",
                   status == TS_MEASURE_OUT_OF_MEMORY ? "out of memory: the images are too large"
                                                      : "an image is smaller than 7x7 pixels");
          ok = false;
        }
    }
  if (ok)
    {
      for (int i = 0; i < n_paths - 1; i++)
        print_figures (paths[1 + i], &figures[i], labels, style, json, several || n_paths > 2);
      code = fflush (stdout) == 0 ? EXIT_SUCCESS : EXIT_USAGE;
    }
  free (figures);
  free (exemplar.pixels);
  free (ex_guide.pixels);
  free (t_guide.pixels);
  free (style_img.pixels);
  free (ex_labels);
  free (t_labels);
  return code;
}
