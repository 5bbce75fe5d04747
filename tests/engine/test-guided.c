/* Guided synthesis: a two-texture exemplar with its label map grown into
 * discs, stripes and thin lines keeps each label's texture where the
 * target asks for it; style transfer follows the target's lightness;
 * results do not depend on threads; bad guides are refused.
 * With TEST_GUIDED_DUMP=DIR set, the results are also written there. */
#include "test-util.h"
#include "image-io.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define EX_W 128
#define EX_H 96
#define OUT 160
/* Pixels this close to a label edge (of the target) are not judged:
 * the edge's own placement is the guide weight's trade-off. */
#define EDGE_MARGIN 3

typedef enum { DISCS, STRIPES, LINES } Layout;

/* Left half of the exemplar from one texture, right half from another;
 * labels 0 and 1 (as guide values 0 and 1). */
static void
two_texture_exemplar (TsImage *ex, float *labels)
{
  TsImage a, b;

  test_load_exemplar ("cracked.png", &a);
  test_load_exemplar ("wood1.png", &b);
  ex->width = EX_W;
  ex->height = EX_H;
  ex->pixels = malloc (EX_W * EX_H * TS_CHANNELS * sizeof (float));
  for (size_t y = 0; y < EX_H; y++)
    for (size_t x = 0; x < EX_W; x++)
      {
        bool right = x >= EX_W / 2;
        const TsImage *src = right ? &b : &a;
        size_t sx = right ? x - EX_W / 2 : x;
        memcpy (ex->pixels + (y * EX_W + x) * TS_CHANNELS, src->pixels + (y * src->width + sx) * TS_CHANNELS,
                TS_CHANNELS * sizeof (float));
        labels[y * EX_W + x] = right ? 1.0f : 0.0f;
      }
  free (a.pixels);
  free (b.pixels);
}

static float
target_label (Layout layout, size_t x, size_t y)
{
  switch (layout)
    {
    case DISCS:
      {
        /* Discs of radius 26 on a 80-pixel grid. */
        double dx = (double) (x % 80) - 40.0, dy = (double) (y % 80) - 40.0;
        return dx * dx + dy * dy < 26.0 * 26.0 ? 1.0f : 0.0f;
      }
    case STRIPES:
      return (y / 32) % 2 ? 1.0f : 0.0f;
    case LINES:
      /* 10-pixel lines of label 1 every 40 pixels, slanted. */
      return ((x + y / 2) % 40) < 10 ? 1.0f : 0.0f;
    }
  return 0.0f;
}

static bool
near_edge (const float *map, size_t w, size_t h, size_t x, size_t y, size_t margin)
{
  for (size_t yy = y >= margin ? y - margin : 0; yy <= y + margin && yy < h; yy++)
    for (size_t xx = x >= margin ? x - margin : 0; xx <= x + margin && xx < w; xx++)
      if (map[yy * w + xx] != map[y * w + x])
        return true;
  return false;
}

/* Share of output pixels away from the target's label edges whose source
 * lies in the exemplar region of the label asked for. */
/* Share of the pixels whose source has the target's label: those at
 * least `margin` from a target edge (none with margin 0). */
static double
label_fidelity (const float *target, const float *ex_labels, const int32_t *sources, size_t margin)
{
  size_t judged = 0, right = 0;
  for (size_t y = 0; y < OUT; y++)
    for (size_t x = 0; x < OUT; x++)
      {
        size_t p = y * OUT + x;
        if (margin && near_edge (target, OUT, OUT, x, y, margin))
          continue;
        judged++;
        right += ex_labels[sources[2 * p + 1] * EX_W + sources[2 * p]] == target[p];
      }
  return judged ? (double) right / (double) judged : 0.0;
}

static void
dump (const char *name, const TsImage *image)
{
  const char *dir = getenv ("TEST_GUIDED_DUMP");
  char path[512], why[256];
  if (!dir)
    return;
  snprintf (path, sizeof path, "%s/%s.png", dir, name);
  if (!ts_io_save (path, image, why, sizeof why))
    fprintf (stderr, "could not write %s: %s\n", path, why);
}

static TsStatus
run_guided (const TsImage *ex, const TsGuides *guides, uint32_t seed, TsImage *out,
            int32_t *sources, bool wrap)
{
  TsParams p;
  TsError error;
  TsStatus status;

  ts_params_init (&p);
  p.output_width = OUT;
  p.output_height = OUT;
  p.seed = seed;
  p.wrap_x = p.wrap_y = wrap;
  p.guides = guides;
  p.source_map = sources;
  out->width = OUT;
  out->height = OUT;
  status = ts_synthesize (&p, ex, out, NULL, NULL, &error);
  if (status != TS_OK)
    fprintf (stderr, "guided synthesis failed: %s\n", error.message);
  return status;
}

static void
test_texture_by_numbers (void)
{
  static const char *names[] = { "discs", "stripes", "lines" };
  float *ex_labels = malloc (EX_W * EX_H * sizeof (float));
  float *target = malloc (OUT * OUT * sizeof (float));
  int32_t *sources = malloc (OUT * OUT * 2 * sizeof (int32_t));
  TsImage ex, out = { OUT, OUT, malloc (OUT * OUT * TS_CHANNELS * sizeof (float)) };
  TsGuides guides;

  two_texture_exemplar (&ex, ex_labels);
  dump ("exemplar", &ex);
  ts_guides_init (&guides);
  guides.exemplar_guide = ex_labels;
  guides.target_guide = target;
  for (int blend = 0; blend <= 1; blend++)
    for (Layout layout = DISCS; layout <= LINES; layout++)
      {
        TsParams p;
        const char *how = blend ? "blended edges" : "layers";
        for (size_t y = 0; y < OUT; y++)
          for (size_t x = 0; x < OUT; x++)
            target[y * OUT + x] = target_label (layout, x, y);
        guides.blend_edges = blend;
        ts_params_init (&p);
        p.output_width = p.output_height = OUT;
        p.guides = &guides;
        CHECK (ts_guides_use_labels (&p, &ex), "%s: a two-value map compares as labels",
               names[layout]);
        if (run_guided (&ex, &guides, 3, &out, sources, layout == STRIPES) != TS_OK)
          {
            CHECK (false, "%s, %s: guided synthesis ran", names[layout], how);
            continue;
          }
        double fidelity = label_fidelity (target, ex_labels, sources, EDGE_MARGIN);
        double everywhere = label_fidelity (target, ex_labels, sources, 0);
        printf ("%-8s %-13s label fidelity %.3f, at every pixel %.3f\n", names[layout], how,
                fidelity, everywhere);
        if (!test_small ())
          CHECK (fidelity >= 0.95, "%s, %s: label fidelity %.3f >= 0.95", names[layout], how,
                 fidelity);
        /* In layers every pixel, edges included, takes its label's texture. */
        if (!blend)
          CHECK (everywhere == 1.0, "%s, layers: every pixel's source has its label (%.4f)",
                 names[layout], everywhere);
        if (!blend)
          dump (names[layout], &out);
      }
  free (ex.pixels);
  free (out.pixels);
  free (ex_labels);
  free (target);
  free (sources);
}

/* Runs the guides in layers; every pixel's source must have its label. */
static void
expect_every_label (const TsImage *ex, const TsGuides *guides, TsImage *out, int32_t *sources,
                    const char *what)
{
  if (run_guided (ex, guides, 5, out, sources, false) != TS_OK)
    {
      CHECK (false, "%s: guided synthesis ran", what);
      return;
    }
  double everywhere = label_fidelity (guides->target_guide, guides->exemplar_guide, sources, 0);
  CHECK (everywhere == 1.0, "%s: every pixel's source has its label (%.4f)", what, everywhere);
}

static void
expect_sources_inside (const TsImage *ex, const TsGuides *guides, TsImage *out, int32_t *sources,
                       const char *what)
{
  bool inside = true;

  if (run_guided (ex, guides, 5, out, sources, false) != TS_OK)
    {
      CHECK (false, "%s: guided synthesis ran", what);
      return;
    }
  for (size_t i = 0; i < OUT * OUT; i++)
    inside &= sources[2 * i] >= 0 && (size_t) sources[2 * i] < EX_W && sources[2 * i + 1] >= 0
              && (size_t) sources[2 * i + 1] < EX_H;
  CHECK (inside, "%s: every source inside the exemplar", what);
}

/* Regions of one pixel and one pixel wide grow in layers too, each
 * pixel from its own label, in the target and in the exemplar. */
static void
test_tiny_regions (void)
{
  float *ex_labels = malloc (EX_W * EX_H * sizeof (float));
  float *target = calloc (OUT * OUT, sizeof (float));
  int32_t *sources = malloc (OUT * OUT * 2 * sizeof (int32_t));
  TsImage ex, ex2, out = { OUT, OUT, malloc (OUT * OUT * TS_CHANNELS * sizeof (float)) };
  TsGuides guides;

  two_texture_exemplar (&ex, ex_labels);
  target[40 * OUT + 40] = 1.0f;
  for (size_t y = 0; y < OUT; y++)
    target[y * OUT + 100] = 1.0f;
  ts_guides_init (&guides);
  guides.exemplar_guide = ex_labels;
  guides.target_guide = target;
  expect_every_label (&ex, &guides, &out, sources, "a one-pixel dot and line");
  /* An exemplar whose label 1 is a single pixel: that label's areas take
   * that pixel (a texture of one colour), and nothing fails. */
  for (size_t i = 0; i < EX_W * EX_H; i++)
    ex_labels[i] = i == 20 * EX_W + 30 ? 1.0f : 0.0f;
  expect_every_label (&ex, &guides, &out, sources, "a one-pixel label in the exemplar");
  /* More specks than a label is split into separate syntheses for. */
  free (ex.pixels);
  two_texture_exemplar (&ex, ex_labels);
  for (size_t y = 0; y < OUT; y++)
    for (size_t x = 0; x < OUT; x++)
      target[y * OUT + x] = x % 12 == 5 && y % 12 == 5 ? 1.0f : 0.0f;
  expect_every_label (&ex, &guides, &out, sources, "169 one-pixel specks");
  /* An exemplar of non-finite values and alpha out of range (a float
   * file's): the layers' result holds them as the engine reads them,
   * finite, alpha in [0, 1], as a plain synthesis's does. */
  for (size_t i = 0; i < EX_W * EX_H; i += 3)
    {
      ex.pixels[i * TS_CHANNELS] = NAN;
      ex.pixels[i * TS_CHANNELS + 1] = INFINITY;
      ex.pixels[i * TS_CHANNELS + 3] = i % 2 ? 7.0f : 1.0f;
    }
  if (run_guided (&ex, &guides, 5, &out, sources, false) == TS_OK)
    {
      bool readable = true;
      for (size_t i = 0; i < OUT * OUT * TS_CHANNELS; i++)
        readable &= isfinite (out.pixels[i]) && (i % TS_CHANNELS != 3 || out.pixels[i] <= 1.0f);
      CHECK (readable, "non-finite exemplar values: the result is finite, alpha at most 1");
    }
  else
    CHECK (false, "non-finite exemplar values: guided synthesis ran");
  /* A distinct exemplar value that no exemplar pixel is nearest to: 3e-24
   * lies within float underflow of label 0, which comes first, but a
   * target value of 1e-21 is nearer to it. It has no texture; its target
   * pixels take a label the exemplar has (it made a layer of a box
   * turned inside out, read beyond the exemplar). */
  two_texture_exemplar (&ex2, ex_labels);
  CHECK (ex_labels[0] == 0.0f, "label 0 comes first");
  for (size_t i = 1; i < EX_W * EX_H; i += 7)
    if (ex_labels[i] == 0.0f)
      ex_labels[i] = 3e-24f;
  for (size_t i = 0; i < OUT * OUT; i += 5)
    target[i] = 1e-21f;
  guides.compare = TS_GUIDE_LABELS;
  expect_sources_inside (&ex2, &guides, &out, sources, "a label only the target has");
  guides.blend_edges = true;
  expect_sources_inside (&ex2, &guides, &out, sources,
                         "a label only the target has, blended edges");
  free (ex2.pixels);
  free (ex.pixels);
  free (out.pixels);
  free (ex_labels);
  free (target);
  free (sources);
}

/* A target that is its own lightness (a disc and a gradient, as a
 * photo's layout would be) restyled with bark: the result's blurred L
 * follows the target's. */
static double
blurred_correlation (const float *a, size_t stride_a, const float *b, size_t stride_b)
{
  enum { BLOCK = 8 };
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, n = 0;
  for (size_t by = 0; by < OUT / BLOCK; by++)
    for (size_t bx = 0; bx < OUT / BLOCK; bx++)
      {
        double ma = 0, mb = 0;
        for (size_t y = by * BLOCK; y < (by + 1) * BLOCK; y++)
          for (size_t x = bx * BLOCK; x < (bx + 1) * BLOCK; x++)
            {
              ma += a[(y * OUT + x) * stride_a];
              mb += b[(y * OUT + x) * stride_b];
            }
        sa += ma;
        sb += mb;
        saa += ma * ma;
        sbb += mb * mb;
        sab += ma * mb;
        n += 1;
      }
  return (sab - sa * sb / n) / sqrt ((saa - sa * sa / n) * (sbb - sb * sb / n));
}

static void
test_style_transfer (void)
{
  float *target = malloc (OUT * OUT * sizeof (float));
  int32_t *sources = malloc (OUT * OUT * 2 * sizeof (int32_t));
  TsImage ex, out = { OUT, OUT, malloc (OUT * OUT * TS_CHANNELS * sizeof (float)) };
  TsGuides guides;

  test_load_exemplar ("bark.png", &ex);
  for (size_t y = 0; y < OUT; y++)
    for (size_t x = 0; x < OUT; x++)
      {
        double dx = (double) x - 80.0, dy = (double) y - 80.0;
        target[y * OUT + x] = (float) (0.2 + 0.4 * (double) x / OUT +
                                       (dx * dx + dy * dy < 40.0 * 40.0 ? 0.3 : 0.0));
      }
  ts_guides_init (&guides);
  guides.target_guide = target;
  if (run_guided (&ex, &guides, 5, &out, sources, false) == TS_OK)
    {
      double r = blurred_correlation (target, 1, out.pixels, TS_CHANNELS);
      printf ("style transfer: blurred L correlation %.3f\n", r);
      if (!test_small ())
        CHECK (r >= 0.9, "style transfer: blurred L correlation %.3f >= 0.9", r);
      dump ("style", &out);
    }
  else
    CHECK (false, "style transfer ran");
  free (ex.pixels);
  free (out.pixels);
  free (target);
  free (sources);
}

/* Style transfer from an exemplar of extreme values (the largest
 * floats, infinities, NaN) and a target of the largest finite floats:
 * the guides built from them must neither overflow into undefined casts
 * (the sanitized run checks) nor give anything but finite pixels or a
 * refusal with a message. */
static void
test_extreme_style (void)
{
  const size_t side = 24, out_side = 40;
  const float extremes[] = { FLT_MAX, -FLT_MAX, INFINITY, -INFINITY, NAN, 50.0f };
  float *target = malloc (out_side * out_side * sizeof (float));
  TsImage ex = { side, side, malloc (side * side * TS_CHANNELS * sizeof (float)) };
  TsImage out = { out_side, out_side, malloc (out_side * out_side * TS_CHANNELS * sizeof (float)) };
  TsParams p;
  TsError error = { 0 };
  TsGuides guides;
  TsStatus status;

  for (size_t i = 0; i < side * side; i++)
    {
      float *px = ex.pixels + i * TS_CHANNELS;
      px[0] = extremes[i * 7 % 6];
      px[1] = px[2] = 0.0f;
      px[3] = 1.0f;
    }
  for (size_t i = 0; i < out_side * out_side; i++)
    target[i] = i * 13 % 3 == 0 ? FLT_MAX : -FLT_MAX;
  ts_guides_init (&guides);
  guides.target_guide = target;
  ts_params_init (&p);
  p.output_width = p.output_height = out_side;
  p.guides = &guides;
  status = ts_synthesize (&p, &ex, &out, NULL, NULL, &error);
  if (status == TS_OK)
    {
      bool finite = true;
      for (size_t i = 0; i < out_side * out_side * TS_CHANNELS; i++)
        finite = finite && isfinite (out.pixels[i]);
      CHECK (finite, "style transfer from extreme values gives finite pixels");
    }
  else
    CHECK (error.message[0] != '\0', "style transfer from extreme values is refused with a message");
  printf ("extreme style transfer: %s\n", status == TS_OK ? "finite result" : error.message);
  free (ex.pixels);
  free (out.pixels);
  free (target);
}

/* The same seed gives the same sources on one thread and on two. */
static void
test_threads (void)
{
#ifdef _OPENMP
  float *ex_labels = malloc (EX_W * EX_H * sizeof (float));
  float *target = malloc (OUT * OUT * sizeof (float));
  int32_t *a = malloc (OUT * OUT * 2 * sizeof (int32_t)), *b = malloc (OUT * OUT * 2 * sizeof (int32_t));
  TsImage ex, out = { OUT, OUT, malloc (OUT * OUT * TS_CHANNELS * sizeof (float)) };
  TsGuides guides;
  int threads = omp_get_max_threads ();

  two_texture_exemplar (&ex, ex_labels);
  for (size_t y = 0; y < OUT; y++)
    for (size_t x = 0; x < OUT; x++)
      target[y * OUT + x] = target_label (DISCS, x, y) * 0.7f + (float) x / OUT * 0.3f;
  ts_guides_init (&guides);
  guides.exemplar_guide = ex_labels;
  guides.target_guide = target;
  guides.compare = TS_GUIDE_VALUES;
  omp_set_num_threads (1);
  CHECK (run_guided (&ex, &guides, 9, &out, a, true) == TS_OK, "one thread ran");
  omp_set_num_threads (threads > 1 ? threads : 2);
  CHECK (run_guided (&ex, &guides, 9, &out, b, true) == TS_OK, "two threads ran");
  omp_set_num_threads (threads);
  CHECK (memcmp (a, b, OUT * OUT * 2 * sizeof (int32_t)) == 0,
         "guided sources on one thread equal those on two");
  /* Labels, grown in layers. */
  for (size_t y = 0; y < OUT; y++)
    for (size_t x = 0; x < OUT; x++)
      target[y * OUT + x] = target_label (LINES, x, y);
  guides.compare = TS_GUIDE_LABELS;
  omp_set_num_threads (1);
  CHECK (run_guided (&ex, &guides, 9, &out, a, true) == TS_OK, "layers on one thread ran");
  omp_set_num_threads (threads > 1 ? threads : 2);
  CHECK (run_guided (&ex, &guides, 9, &out, b, true) == TS_OK, "layers on two threads ran");
  omp_set_num_threads (threads);
  CHECK (memcmp (a, b, OUT * OUT * 2 * sizeof (int32_t)) == 0,
         "layers' sources on one thread equal those on two");
  free (ex.pixels);
  free (out.pixels);
  free (ex_labels);
  free (target);
  free (a);
  free (b);
#endif
}

static void
expect_refused (const TsImage *ex, const TsGuides *guides, size_t out_side, const char *what)
{
  TsParams p;
  TsError error = { 0 };
  TsImage out = { out_side, out_side, malloc (out_side * out_side * TS_CHANNELS * sizeof (float)) };
  TsStatus status;

  ts_params_init (&p);
  p.output_width = p.output_height = out_side;
  p.guides = guides;
  status = ts_synthesize (&p, ex, &out, NULL, NULL, &error);
  CHECK (status != TS_OK && error.message[0], "%s is refused with a message", what);
  printf ("%s: %s\n", what, error.message);
  free (out.pixels);
}

static void
test_bad_guides (void)
{
  float *ex_labels = malloc (EX_W * EX_H * sizeof (float));
  float *target = calloc (OUT * OUT, sizeof (float));
  TsImage ex;
  TsGuides g;

  two_texture_exemplar (&ex, ex_labels);
  ts_guides_init (&g);
  g.exemplar_guide = ex_labels;
  g.target_guide = NULL;
  expect_refused (&ex, &g, OUT, "no target guide");
  g.target_guide = target;
  target[77] = NAN;
  expect_refused (&ex, &g, OUT, "a NaN in the target guide");
  target[77] = 0.0f;
  ex_labels[5] = INFINITY;
  expect_refused (&ex, &g, OUT, "an infinity in the exemplar guide");
  ex_labels[5] = 0.0f;
  g.weight = -1.0;
  expect_refused (&ex, &g, OUT, "a negative weight");
  g.weight = NAN;
  expect_refused (&ex, &g, OUT, "a NaN weight");
  g.weight = 1.0;
  g.channels = 4;
  expect_refused (&ex, &g, OUT, "four guide channels");
  g.channels = 1;
  g.exemplar_guide = NULL;
  g.compare = TS_GUIDE_LABELS;
  expect_refused (&ex, &g, OUT, "labels without an exemplar guide");
  for (size_t i = 0; i < EX_W * EX_H; i++)
    ex_labels[i] = (float) (i % 100);
  g.exemplar_guide = ex_labels;
  expect_refused (&ex, &g, OUT, "100 labels");
  free (ex.pixels);
  free (ex_labels);
  free (target);
}

int
main (void)
{
  test_bad_guides ();
  test_extreme_style ();
  test_texture_by_numbers ();
  test_tiny_regions ();
  test_style_transfer ();
  test_threads ();
  return test_finish ("test-guided");
}
