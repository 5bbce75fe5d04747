/* The guided measures (tools/guided-metrics.c) on built cases: a
 * three-texture exemplar (cracked | wood1 | granite1) with its label map,
 * and targets of discs, stripes and thin lines.
 * - a result pasted from the right regions scores fidelity ~1 and edges
 *   on the target's; with the labels swapped, fidelity ~0;
 * - guided syntheses (the engine) keep fidelity >= 0.95, their edges
 *   within 2 px, and each region's coherence within 1.2x that of a plain
 *   synthesis of its texture alone at the output's size: in layers (the
 *   default) in every layout, with blended edges in the discs;
 * - style correlation is 1 for the target itself and about -1 for its
 *   negative. */
#include "test-util.h"
#include "guided-metrics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define STRIP 48
#define EX_W (3 * STRIP)
#define EX_H 96
#define OUT 160

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
      /* 10-pixel slanted lines of labels 1 and 2 on 0. */
      return ((x + y / 2) % 40) < 10 ? (uint8_t) (1 + (x + y / 2) / 40 % 2) : 0;
    }
  return 0;
}

static void
three_textures (TsImage *ex, uint8_t *labels)
{
  static const char *names[] = { "cracked.png", "wood1.png", "granite1.png" };
  ex->width = EX_W;
  ex->height = EX_H;
  ex->pixels = malloc (EX_W * EX_H * TS_CHANNELS * sizeof (float));
  for (size_t l = 0; l < 3; l++)
    {
      TsImage t;
      test_load_exemplar (names[l], &t);
      for (size_t y = 0; y < EX_H; y++)
        for (size_t x = 0; x < STRIP; x++)
          {
            memcpy (ex->pixels + (y * EX_W + l * STRIP + x) * TS_CHANNELS,
                    t.pixels + (y * t.width + x) * TS_CHANNELS, TS_CHANNELS * sizeof (float));
            labels[y * EX_W + l * STRIP + x] = (uint8_t) l;
          }
      free (t.pixels);
    }
}

/* Each result pixel pasted from its label's strip (the strip repeated),
 * or from the next label's with `swap`. */
static void
pasted (const TsImage *ex, const uint8_t *target, bool swap, TsImage *out)
{
  for (size_t y = 0; y < OUT; y++)
    for (size_t x = 0; x < OUT; x++)
      {
        size_t l = (target[y * OUT + x] + (swap ? 1u : 0u)) % 3;
        memcpy (out->pixels + (y * OUT + x) * TS_CHANNELS,
                ex->pixels + ((y % EX_H) * EX_W + l * STRIP + x % STRIP) * TS_CHANNELS,
                TS_CHANNELS * sizeof (float));
      }
}

static void
synthesize (const TsImage *ex, const TsGuides *guides, size_t w, size_t h, uint32_t seed,
            TsImage *out)
{
  TsParams p;
  TsError error;
  ts_params_init (&p);
  p.output_width = w;
  p.output_height = h;
  p.seed = seed;
  p.guides = guides;
  out->width = w;
  out->height = h;
  CHECK (ts_synthesize (&p, ex, out, NULL, NULL, &error) == TS_OK, "synthesis: %s",
         error.message);
}

/* Seeds of the figures: one seed's coherence of a mostly flat texture
 * (the cracked strip) swings by a factor of 3, so each figure is the
 * median of three. */
#define SEEDS 3
#define FIRST_SEED 4

static double
median3 (const double v[SEEDS])
{
  double lo = fmin (v[0], v[1]), hi = fmax (v[0], v[1]);
  return fmax (lo, fmin (hi, v[2]));
}

/* Coherence of plain syntheses of strip l alone, as large as the guided
 * results: the median over the seeds. */
static double
plain_coherence (const TsImage *ex, size_t l)
{
  TsImage strip = { STRIP, EX_H, malloc (STRIP * EX_H * TS_CHANNELS * sizeof (float)) };
  TsImage out = { OUT, OUT, malloc (OUT * OUT * TS_CHANNELS * sizeof (float)) };
  double coherence[SEEDS], seam;

  for (size_t y = 0; y < EX_H; y++)
    memcpy (strip.pixels + y * STRIP * TS_CHANNELS,
            ex->pixels + (y * EX_W + l * STRIP) * TS_CHANNELS, STRIP * TS_CHANNELS * sizeof (float));
  for (uint32_t s = 0; s < SEEDS; s++)
    {
      synthesize (&strip, NULL, OUT, OUT, FIRST_SEED + s, &out);
      ts_measure_coherence (&strip, &out, false, false, &coherence[s], &seam);
    }
  free (strip.pixels);
  free (out.pixels);
  return median3 (coherence);
}

int
main (void)
{
  uint8_t *ex_labels = malloc (EX_W * EX_H), *target = malloc (OUT * OUT);
  float *ex_guide = malloc (EX_W * EX_H * sizeof (float)), *t_guide = malloc (OUT * OUT * sizeof (float));
  TsImage ex, out = { OUT, OUT, malloc (OUT * OUT * TS_CHANNELS * sizeof (float)) };
  TsLabelMeasures m;
  TsGuides guides;
  double plain[3];

  three_textures (&ex, ex_labels);
  for (size_t i = 0; i < EX_W * EX_H; i++)
    ex_guide[i] = (float) ex_labels[i] / 2.0f;
  for (size_t l = 0; l < 3; l++)
    plain[l] = plain_coherence (&ex, l);
  ts_guides_init (&guides);
  guides.exemplar_guide = ex_guide;
  guides.target_guide = t_guide;
  for (Layout layout = DISCS; layout <= LINES; layout++)
    {
      const char *name = layout_name[layout];
      for (size_t y = 0; y < OUT; y++)
        for (size_t x = 0; x < OUT; x++)
          {
            target[y * OUT + x] = target_label (layout, x, y);
            t_guide[y * OUT + x] = (float) target[y * OUT + x] / 2.0f;
          }
      pasted (&ex, target, false, &out);
      CHECK (ts_measure_labels (&ex, ex_labels, &out, target, 3, &m) == TS_MEASURE_OK, "measured");
      printf ("%-8s pasted:  fidelity %.3f edge offset %.2f\n", name, m.fidelity, m.edge_offset);
      CHECK (m.fidelity >= 0.98, "%s pasted: fidelity %.3f >= 0.98", name, m.fidelity);
      CHECK (m.edge_offset <= 1.0, "%s pasted: edge offset %.2f <= 1", name, m.edge_offset);
      pasted (&ex, target, true, &out);
      ts_measure_labels (&ex, ex_labels, &out, target, 3, &m);
      printf ("%-8s swapped: fidelity %.3f\n", name, m.fidelity);
      CHECK (m.fidelity <= 0.05, "%s swapped: fidelity %.3f <= 0.05", name, m.fidelity);
      if (test_small ())
        continue;
      for (int blend = 0; blend <= 1; blend++)
        {
          const char *how = blend ? "blended" : "layers";
          double fidelity[SEEDS], offset[SEEDS], region[3][SEEDS];
          guides.blend_edges = blend;
          for (uint32_t s = 0; s < SEEDS; s++)
            {
              synthesize (&ex, &guides, OUT, OUT, FIRST_SEED + s, &out);
              ts_measure_labels (&ex, ex_labels, &out, target, 3, &m);
              fidelity[s] = m.fidelity;
              offset[s] = m.edge_offset;
              for (size_t l = 0; l < 3; l++)
                region[l][s] = m.region_coherence[l];
            }
          printf ("%-8s %-7s fidelity %.3f edge offset %.2f region coherence", name, how,
                  median3 (fidelity), median3 (offset));
          for (size_t l = 0; l < 3; l++)
            printf (" %.3f (plain %.3f)", median3 (region[l]), plain[l]);
          putchar ('\n');
          for (uint32_t s = 0; s < SEEDS; s++)
            {
              CHECK (fidelity[s] >= 0.95, "%s %s seed %u: fidelity %.3f >= 0.95", name, how,
                     FIRST_SEED + s, fidelity[s]);
              CHECK (offset[s] <= 2.0, "%s %s seed %u: edge offset %.2f <= 2", name, how,
                     FIRST_SEED + s, offset[s]);
            }
          /* With blended edges, the coarse levels see too little of a
           * 24 px stripe or a 10 px line and its coherence falls short:
           * those figures are printed only. */
          for (size_t l = 0; l < 3 && (!blend || layout == DISCS); l++)
            CHECK (!(median3 (region[l]) > 1.2 * plain[l]),
                   "%s %s: region %zu coherence %.3f <= 1.2 x plain %.3f", name, how, l,
                   median3 (region[l]), plain[l]);
        }
    }
  /* Style: a layout correlates fully with itself, and negatively with
   * its negative, whatever the grain added. */
  {
    TsImage a = { OUT, OUT, calloc (OUT * OUT * TS_CHANNELS, sizeof (float)) };
    TsImage b = { OUT, OUT, calloc (OUT * OUT * TS_CHANNELS, sizeof (float)) };
    double r_same, r_other;
    for (size_t y = 0; y < OUT; y++)
      for (size_t x = 0; x < OUT; x++)
        {
          a.pixels[(y * OUT + x) * TS_CHANNELS] = 30.0f * target_label (DISCS, x, y);
          b.pixels[(y * OUT + x) * TS_CHANNELS] = 60.0f - 30.0f * target_label (DISCS, x, y)
                                                  + 20.0f * (float) ((x * 7 + y * 13) % 5) / 5.0f;
        }
    ts_measure_style_correlation (&a, &a, &r_same);
    ts_measure_style_correlation (&a, &b, &r_other);
    printf ("style correlation: same %.3f, other %.3f\n", r_same, r_other);
    CHECK (fabs (r_same - 1.0) < 1e-9, "a layout correlates fully with itself (%.6f)", r_same);
    CHECK (r_other < -0.9, "a layout and its grainy negative correlate negatively (%.3f)",
           r_other);
    free (a.pixels);
    free (b.pixels);
  }
  free (ex.pixels);
  free (out.pixels);
  free (ex_labels);
  free (target);
  free (ex_guide);
  free (t_guide);
  return test_finish ("test-guided-metrics");
}
