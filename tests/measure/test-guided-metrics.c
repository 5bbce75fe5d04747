/* The guided measures (tools/guided-metrics.c) on built cases
 * (tools/guided-cases.c): a three-texture exemplar (cracked | wood1 |
 * granite1) with its label map, and targets of discs, stripes and thin
 * lines.
 * - a result pasted from the right regions scores fidelity ~1 and edges
 *   on the target's; with the labels swapped, fidelity ~0;
 * - guided syntheses (the engine) keep fidelity >= 0.95, their edges
 *   within 2 px, and each region's coherence within 1.2x that of a plain
 *   synthesis of its texture alone at the output's size: in layers (the
 *   default) in every layout, with blended edges in the discs;
 * - style correlation is 1 for the target itself and about -1 for its
 *   negative. */
#include "test-util.h"
#include "guided-cases.h"
#include "guided-metrics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define OUT TS_CASE_OUT

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
                ex->pixels + ((y % TS_CASE_EX_H) * TS_CASE_EX_W + l * TS_CASE_STRIP
                              + x % TS_CASE_STRIP) * TS_CHANNELS,
                TS_CHANNELS * sizeof (float));
      }
}

/* The pasted results, right and swapped. */
static void
check_pasted (const TsImage *ex, const uint8_t *ex_labels, TsCaseLayout layout, TsImage *out)
{
  const char *name = ts_case_layout_name[layout];
  uint8_t target[OUT * OUT];
  TsLabelMeasures m;

  for (size_t y = 0; y < OUT; y++)
    for (size_t x = 0; x < OUT; x++)
      target[y * OUT + x] = ts_case_target_label (layout, x, y);
  pasted (ex, target, false, out);
  CHECK (ts_measure_labels (ex, ex_labels, out, target, 3, &m) == TS_MEASURE_OK, "measured");
  printf ("%-8s pasted:  fidelity %.3f edge offset %.2f\n", name, m.fidelity, m.edge_offset);
  CHECK (m.fidelity >= 0.98, "%s pasted: fidelity %.3f >= 0.98", name, m.fidelity);
  CHECK (m.edge_offset <= 1.0, "%s pasted: edge offset %.2f <= 1", name, m.edge_offset);
  pasted (ex, target, true, out);
  ts_measure_labels (ex, ex_labels, out, target, 3, &m);
  printf ("%-8s swapped: fidelity %.3f\n", name, m.fidelity);
  CHECK (m.fidelity <= 0.05, "%s swapped: fidelity %.3f <= 0.05", name, m.fidelity);
}

/* Guided syntheses of `layout`, in layers and with blended edges. */
static void
check_guided (const TsImage *ex, const uint8_t *ex_labels, TsCaseLayout layout,
              const double plain[3])
{
  const char *name = ts_case_layout_name[layout];

  for (int blend = 0; blend <= 1; blend++)
    {
      const char *how = blend ? "blended" : "layers";
      TsCaseFigures f;
      TsError error = { TS_OK, "" };
      TsStatus status = ts_case_guided (ex, ex_labels, layout, blend, TS_CASE_SEEDS, &f, NULL,
                                        &error);
      if (status != TS_OK)
        {
          CHECK (false, "%s %s: synthesis: %s", name, how,
                 error.message[0] ? error.message : ts_status_string (status));
          continue;
        }
      printf ("%-8s %-7s fidelity %.3f edge offset %.2f region coherence", name, how,
              ts_case_median (f.fidelity, TS_CASE_SEEDS),
              ts_case_median (f.offset, TS_CASE_SEEDS));
      for (size_t l = 0; l < 3; l++)
        printf (" %.3f (plain %.3f)", ts_case_median (f.region[l], TS_CASE_SEEDS), plain[l]);
      putchar ('\n');
      for (uint32_t s = 0; s < TS_CASE_SEEDS; s++)
        {
          CHECK (f.fidelity[s] >= 0.95, "%s %s seed %u: fidelity %.3f >= 0.95", name, how,
                 TS_CASE_FIRST_SEED + s, f.fidelity[s]);
          CHECK (f.offset[s] <= 2.0, "%s %s seed %u: edge offset %.2f <= 2", name, how,
                 TS_CASE_FIRST_SEED + s, f.offset[s]);
        }
      /* With blended edges, the coarse levels see too little of a 24 px
       * stripe or a 10 px line and its coherence falls short: those
       * figures are printed only. */
      for (size_t l = 0; l < 3 && (!blend || layout == TS_CASE_DISCS); l++)
        CHECK (!(ts_case_median (f.region[l], TS_CASE_SEEDS) > 1.2 * plain[l]),
               "%s %s: region %zu coherence %.3f <= 1.2 x plain %.3f", name, how, l,
               ts_case_median (f.region[l], TS_CASE_SEEDS), plain[l]);
    }
}

/* Style: a layout correlates fully with itself, and negatively with its
 * negative, whatever the grain added. */
static void
check_style_correlation (void)
{
  TsImage a = { OUT, OUT, calloc (OUT * OUT * TS_CHANNELS, sizeof (float)) };
  TsImage b = { OUT, OUT, calloc (OUT * OUT * TS_CHANNELS, sizeof (float)) };
  double r_same, r_other;

  for (size_t y = 0; y < OUT; y++)
    for (size_t x = 0; x < OUT; x++)
      {
        float label = (float) ts_case_target_label (TS_CASE_DISCS, x, y);
        a.pixels[(y * OUT + x) * TS_CHANNELS] = 30.0f * label;
        b.pixels[(y * OUT + x) * TS_CHANNELS] = 60.0f - 30.0f * label
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

int
main (void)
{
  static const char *names[] = { "cracked.png", "wood1.png", "granite1.png" };
  uint8_t *ex_labels = malloc (TS_CASE_EX_W * TS_CASE_EX_H);
  TsImage textures[3], ex, out = { OUT, OUT, malloc (OUT * OUT * TS_CHANNELS * sizeof (float)) };
  double plain[3];

  for (size_t l = 0; l < 3; l++)
    test_load_exemplar (names[l], &textures[l]);
  bool built = ts_case_exemplar (textures, &ex, ex_labels);
  for (size_t l = 0; l < 3; l++)
    free (textures[l].pixels);
  CHECK (built, "the three-texture exemplar is built");
  if (!built)
    return test_finish ("test-guided-metrics");
  for (size_t l = 0; l < 3 && !test_small (); l++)
    {
      TsError error = { TS_OK, "" };
      CHECK (ts_case_plain_coherence (&ex, l, TS_CASE_SEEDS, &plain[l], &error) == TS_OK,
             "plain synthesis: %s", error.message);
    }
  for (TsCaseLayout layout = TS_CASE_DISCS; layout < TS_CASE_LAYOUTS; layout++)
    {
      check_pasted (&ex, ex_labels, layout, &out);
      if (!test_small ())
        check_guided (&ex, ex_labels, layout, plain);
    }
  check_style_correlation ();
  free (ex.pixels);
  free (out.pixels);
  free (ex_labels);
  return test_finish ("test-guided-metrics");
}
