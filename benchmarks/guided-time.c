/* guided-time: times guided synthesis (ts_synthesize with guides) alone,
 * without GEGL start-up, loading or saving: texture by numbers from a
 * two-texture exemplar (the left half of LEFT beside the left half of
 * RIGHT, with their label map) grown to SIZE x SIZE discs, and style
 * transfer of RIGHT restyling LEFT scaled to SIZE. Prints the median
 * wall and CPU seconds and, for the labels, the label fidelity by source map (the share
 * of pixels more than 3 px from a target edge whose source lies in the
 * label's half).
 *
 * Usage: guided-time [-s SIZE] [-r RUNS] [-e SEED] LEFT.png RIGHT.png
 *   -s  output side (1024)    -r  runs, the median is shown (1)   -e  seed (1)
 * Both exemplars must have the same height. Threads: OMP_NUM_THREADS.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "image-io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MAX_RUNS 99
#define EDGE_MARGIN 3

static double
now (clockid_t clock)
{
  struct timespec t;
  clock_gettime (clock, &t);
  return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

static int
compare_double (const void *a, const void *b)
{
  double x = *(const double *) a, y = *(const double *) b;
  return (x > y) - (x < y);
}

/* Discs of a fifth of the side, on a grid of half the side. */
static float
disc_label (size_t x, size_t y, size_t side)
{
  double cell = (double) side / 2.0, r = (double) side / 5.0;
  double dx = (double) x - (floor ((double) x / cell) + 0.5) * cell;
  double dy = (double) y - (floor ((double) y / cell) + 0.5) * cell;
  return dx * dx + dy * dy < r * r ? 1.0f : 0.0f;
}

static bool
near_edge (const float *map, size_t side, size_t x, size_t y)
{
  for (size_t yy = y >= EDGE_MARGIN ? y - EDGE_MARGIN : 0; yy <= y + EDGE_MARGIN && yy < side; yy++)
    for (size_t xx = x >= EDGE_MARGIN ? x - EDGE_MARGIN : 0; xx <= x + EDGE_MARGIN && xx < side; xx++)
      if (map[yy * side + xx] != map[y * side + x])
        return true;
  return false;
}

/* Median wall seconds; *cpu the CPU seconds of all threads in that run
 * (on a busy machine, a bound on what two idle cores would take). */
static double
timed (const TsParams *p, const TsImage *ex, TsImage *out, int runs, double *cpu)
{
  double t[MAX_RUNS], c[MAX_RUNS];
  TsError error;
  for (int r = 0; r < runs; r++)
    {
      double t0 = now (CLOCK_MONOTONIC), c0 = now (CLOCK_PROCESS_CPUTIME_ID);
      if (ts_synthesize (p, ex, out, NULL, NULL, &error) != TS_OK)
        {
          fprintf (stderr, "guided-time: %s\n", error.message);
          exit (1);
        }
      t[r] = now (CLOCK_MONOTONIC) - t0;
      c[r] = now (CLOCK_PROCESS_CPUTIME_ID) - c0;
    }
  qsort (t, (size_t) runs, sizeof t[0], compare_double);
  qsort (c, (size_t) runs, sizeof c[0], compare_double);
  *cpu = c[runs / 2];
  return t[runs / 2];
}

int
main (int argc, char **argv)
{
  size_t side = 1024;
  int runs = 1, opt;
  uint32_t seed = 1;
  TsImage left, right, ex, out;
  char why[512];

  while ((opt = getopt (argc, argv, "s:r:e:")) != -1)
    switch (opt)
      {
      case 's': side = (size_t) atoi (optarg); break;
      case 'r': runs = atoi (optarg); break;
      case 'e': seed = (uint32_t) strtoul (optarg, NULL, 10); break;
      default: return 2;
      }
  if (optind + 2 != argc || side < 16 || side > 8192 || runs < 1 || runs > MAX_RUNS)
    {
      fprintf (stderr, "usage: guided-time [-s SIZE] [-r RUNS] [-e SEED] LEFT.png RIGHT.png\n");
      return 2;
    }
  ts_io_init ();
  if (!ts_io_load (argv[optind], &left, why, sizeof why) ||
      !ts_io_load (argv[optind + 1], &right, why, sizeof why))
    {
      fprintf (stderr, "guided-time: %s\n", why);
      return 2;
    }
  if (left.height != right.height)
    {
      fprintf (stderr, "guided-time: LEFT and RIGHT must have the same height\n");
      return 2;
    }
  size_t half_l = left.width / 2, half_r = right.width / 2, ew = half_l + half_r, eh = left.height;
  size_t n = side * side;
  float *ex_labels = malloc (ew * eh * sizeof (float)), *target = malloc (n * sizeof (float));
  int32_t *sources = malloc (n * 2 * sizeof (int32_t));
  ex = (TsImage) { ew, eh, malloc (ew * eh * TS_CHANNELS * sizeof (float)) };
  out = (TsImage) { side, side, malloc (n * TS_CHANNELS * sizeof (float)) };
  if (!ex_labels || !target || !sources || !ex.pixels || !out.pixels)
    {
      fprintf (stderr, "guided-time: out of memory\n");
      return 1;
    }
  for (size_t y = 0; y < eh; y++)
    for (size_t x = 0; x < ew; x++)
      {
        bool r = x >= half_l;
        const TsImage *src = r ? &right : &left;
        size_t sx = r ? x - half_l : x;
        memcpy (ex.pixels + (y * ew + x) * TS_CHANNELS, src->pixels + (y * src->width + sx) * TS_CHANNELS,
                TS_CHANNELS * sizeof (float));
        ex_labels[y * ew + x] = r ? 1.0f : 0.0f;
      }
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      target[y * side + x] = disc_label (x, y, side);

  TsParams p;
  TsGuides g;
  ts_params_init (&p);
  p.output_width = p.output_height = side;
  p.seed = seed;
  p.guides = &g;
  p.source_map = sources;
  ts_guides_init (&g);
  g.exemplar_guide = ex_labels;
  g.target_guide = target;
  double cpu_labels, cpu_style;
  double t_labels = timed (&p, &ex, &out, runs, &cpu_labels);
  size_t judged = 0, right_label = 0;
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      if (!near_edge (target, side, x, y))
        {
          judged++;
          right_label += ex_labels[(size_t) sources[2 * (y * side + x)]] == target[y * side + x];
        }
  printf ("labels  %zux%zu from %zux%zu  %.3f s (CPU %.3f s)  label fidelity %.4f\n", side, side,
          ew, eh, t_labels, cpu_labels, (double) right_label / (double) judged);

  /* Style transfer: LEFT's lightness, nearest-scaled to the output. */
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      target[y * side + x] =
        left.pixels[((y * left.height / side) * left.width + x * left.width / side) * TS_CHANNELS] / 100.0f;
  g.exemplar_guide = NULL;
  p.source_map = NULL;
  double t_style = timed (&p, &right, &out, runs, &cpu_style);
  printf ("style   %zux%zu from %zux%zu  %.3f s (CPU %.3f s)\n", side, side, right.width,
          right.height, t_style, cpu_style);
  free (ex_labels);
  free (target);
  free (sources);
  free (ex.pixels);
  free (out.pixels);
  free (left.pixels);
  free (right.pixels);
  return 0;
}
