/* guided-regions: texture by numbers on built cases of any three
 * textures. The exemplar is the left 48x96 of each texture side by side
 * with its label map; the 160x160 targets are discs, 24 px stripes and
 * 10 px slanted lines (those of tests/measure/test-guided-metrics.c).
 * For labels in layers (the default) and with blended edges, prints the
 * label fidelity, the label edge offset and each region's coherence over
 * that of a plain synthesis of its texture alone at 160x160 (the aim is
 * <= 1.2), medians over seeds 4, 5 and 6; with -o DIR also writes the
 * seed-4 results there.
 *
 * Usage: guided-regions [-o DIR] FIRST.png SECOND.png THIRD.png
 * Each texture must be at least 48x96. Threads: OMP_NUM_THREADS.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "guided-metrics.h"
#include "image-io.h"
#include "metrics.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define STRIP 48
#define EX_W (3 * STRIP)
#define EX_H 96
#define OUT 160
#define SEEDS 3
#define FIRST_SEED 4

typedef enum { DISCS, STRIPES, LINES } Layout;
static const char *layout_name[] = { "discs", "stripes", "lines" };

static uint8_t
target_label (Layout layout, size_t x, size_t y)
{
  switch (layout)
    {
    case DISCS:
      {
        double dx = (double) (x % 80) - 40.0, dy = (double) (y % 80) - 40.0;
        return dx * dx + dy * dy < 26.0 * 26.0 ? (uint8_t) (1 + (x / 80 + y / 80) % 2) : 0;
      }
    case STRIPES:
      return (uint8_t) ((y / 24) % 3);
    case LINES:
      return ((x + y / 2) % 40) < 10 ? (uint8_t) (1 + (x + y / 2) / 40 % 2) : 0;
    }
  return 0;
}

static double
median3 (const double v[SEEDS])
{
  double lo = fmin (v[0], v[1]), hi = fmax (v[0], v[1]);
  return fmax (lo, fmin (hi, v[2]));
}

static void *
checked_malloc (size_t bytes)
{
  void *p = malloc (bytes);
  if (!p)
    {
      fprintf (stderr, "guided-regions: out of memory\n");
      exit (1);
    }
  return p;
}

static void
synthesize (const TsImage *ex, const TsGuides *guides, uint32_t seed, TsImage *out)
{
  TsParams p;
  TsError error;

  ts_params_init (&p);
  p.output_width = out->width;
  p.output_height = out->height;
  p.seed = seed;
  p.guides = guides;
  if (ts_synthesize (&p, ex, out, NULL, NULL, &error) != TS_OK)
    {
      fprintf (stderr, "guided-regions: synthesis failed: %s\n", error.message);
      exit (1);
    }
}

/* Median coherence of plain syntheses of strip l alone. */
static double
plain_coherence (const TsImage *ex, size_t l)
{
  TsImage strip = { STRIP, EX_H, checked_malloc (STRIP * EX_H * TS_CHANNELS * sizeof (float)) };
  TsImage out = { OUT, OUT, checked_malloc (OUT * OUT * TS_CHANNELS * sizeof (float)) };
  double coherence[SEEDS], seam;

  for (size_t y = 0; y < EX_H; y++)
    memcpy (strip.pixels + y * STRIP * TS_CHANNELS,
            ex->pixels + (y * EX_W + l * STRIP) * TS_CHANNELS, STRIP * TS_CHANNELS * sizeof (float));
  for (uint32_t s = 0; s < SEEDS; s++)
    {
      synthesize (&strip, NULL, FIRST_SEED + s, &out);
      ts_measure_coherence (&strip, &out, false, false, &coherence[s], &seam);
    }
  free (strip.pixels);
  free (out.pixels);
  return median3 (coherence);
}

int
main (int argc, char **argv)
{
  const char *dir = NULL;
  TsImage ex = { EX_W, EX_H, checked_malloc (EX_W * EX_H * TS_CHANNELS * sizeof (float)) };
  TsImage out = { OUT, OUT, checked_malloc (OUT * OUT * TS_CHANNELS * sizeof (float)) };
  uint8_t *ex_labels = checked_malloc (EX_W * EX_H), *target = checked_malloc (OUT * OUT);
  float *ex_guide = checked_malloc (EX_W * EX_H * sizeof (float));
  float *t_guide = checked_malloc (OUT * OUT * sizeof (float));
  double plain[3];
  TsGuides guides;
  char why[256];
  int opt;

  while ((opt = getopt (argc, argv, "o:")) != -1)
    if (opt == 'o')
      dir = optarg;
    else
      return 2;
  if (argc - optind != 3)
    {
      fprintf (stderr, "usage: guided-regions [-o DIR] FIRST.png SECOND.png THIRD.png\n");
      return 2;
    }
  ts_io_init ();
  for (size_t l = 0; l < 3; l++)
    {
      TsImage t;
      if (!ts_io_load (argv[optind + l], &t, why, sizeof why))
        {
          fprintf (stderr, "guided-regions: %s: %s\n", argv[optind + l], why);
          return 1;
        }
      if (t.width < STRIP || t.height < EX_H)
        {
          fprintf (stderr, "guided-regions: %s is %zux%zu, smaller than %dx%d\n",
                   argv[optind + l], t.width, t.height, STRIP, EX_H);
          return 1;
        }
      for (size_t y = 0; y < EX_H; y++)
        for (size_t x = 0; x < STRIP; x++)
          {
            memcpy (ex.pixels + (y * EX_W + l * STRIP + x) * TS_CHANNELS,
                    t.pixels + (y * t.width + x) * TS_CHANNELS, TS_CHANNELS * sizeof (float));
            ex_labels[y * EX_W + l * STRIP + x] = (uint8_t) l;
            ex_guide[y * EX_W + l * STRIP + x] = (float) l / 2.0f;
          }
      free (t.pixels);
    }
  for (size_t l = 0; l < 3; l++)
    plain[l] = plain_coherence (&ex, l);
  printf ("plain coherence at %dx%d: %.3f %.3f %.3f\n", OUT, OUT, plain[0], plain[1], plain[2]);
  ts_guides_init (&guides);
  guides.exemplar_guide = ex_guide;
  guides.target_guide = t_guide;
  for (Layout layout = DISCS; layout <= LINES; layout++)
    {
      for (size_t y = 0; y < OUT; y++)
        for (size_t x = 0; x < OUT; x++)
          {
            target[y * OUT + x] = target_label (layout, x, y);
            t_guide[y * OUT + x] = (float) target[y * OUT + x] / 2.0f;
          }
      for (int blend = 0; blend <= 1; blend++)
        {
          double fidelity[SEEDS], offset[SEEDS], region[3][SEEDS];
          guides.blend_edges = blend;
          for (uint32_t s = 0; s < SEEDS; s++)
            {
              TsLabelMeasures m;
              synthesize (&ex, &guides, FIRST_SEED + s, &out);
              ts_measure_labels (&ex, ex_labels, &out, target, 3, &m);
              fidelity[s] = m.fidelity;
              offset[s] = m.edge_offset;
              for (size_t l = 0; l < 3; l++)
                region[l][s] = m.region_coherence[l];
              if (dir && s == 0)
                {
                  char path[4096];
                  snprintf (path, sizeof path, "%s/%s-%s.png", dir, layout_name[layout],
                            blend ? "blended" : "layers");
                  if (!ts_io_save (path, &out, why, sizeof why))
                    fprintf (stderr, "guided-regions: %s: %s\n", path, why);
                }
            }
          printf ("%-8s %-7s fidelity %.3f  edge offset %.2f px  coherence / plain:", layout_name[layout],
                  blend ? "blended" : "layers", median3 (fidelity), median3 (offset));
          for (size_t l = 0; l < 3; l++)
            printf (" %.2f", median3 (region[l]) / plain[l]);
          putchar ('\n');
        }
    }
  free (ex.pixels);
  free (out.pixels);
  free (ex_labels);
  free (target);
  free (ex_guide);
  free (t_guide);
  return 0;
}
