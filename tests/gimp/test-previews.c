/* The GIMP dialogs' previews (gimp-plugin/plugin-preview.c) without GIMP:
 * each kind run on bundled exemplars as a dialog would run it, checking
 * the preview's size, that it is a result (opaque where the op fills; the
 * ops' failure result is transparent) and what each kind promises: the
 * seamless preview repeats 2x2, the heal previews keep the pixels they do
 * not fill, the guided one refuses a guide of another size.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plugin-preview.h"

/* A preview that has not finished by then hangs: a failure. */
#define WAIT_LIMIT_S 300

static int failures;

static void
check (gboolean ok, const gchar *what)
{
  printf ("%s: %s\n", ok ? "ok" : "FAIL", what);
  if (!ok)
    failures++;
}

/* A bundled exemplar as "R'G'B'A float" at (0, 0); exits if missing. */
static GeglBuffer *
load (const gchar *name)
{
  const gchar *root = g_getenv ("TEXSYNTH_SOURCE_ROOT");
  gchar *path = g_build_filename (root ? root : ".", "tests", "exemplars", name, NULL);
  GeglNode *graph = gegl_node_new ();
  GeglNode *source = gegl_node_new_child (graph, "operation", "gegl:load", "path", path, NULL);
  GeglRectangle rect = gegl_node_get_bounding_box (source);
  GeglBuffer *buffer = NULL;

  if (rect.width < 1 || !g_file_test (path, G_FILE_TEST_EXISTS))
    {
      fprintf (stderr, "test-previews: cannot read the exemplar %s\n", path);
      exit (1);
    }
  buffer = gegl_buffer_new (&rect, babl_format ("R'G'B'A float"));
  gegl_node_blit_buffer (source, buffer, &rect, 0, GEGL_ABYSS_NONE);
  g_object_unref (graph);
  g_free (path);
  return buffer;
}

/* The preview's pixels (copied: R'G'B'A u8) once it has finished; NULL,
 * with a failure, if it never starts or finishes. */
static guchar *
finish (TsPreview *preview, const gchar *what, gint *width, gint *height)
{
  guchar *pixels;
  gint waited_ms = 0;

  if (!preview)
    {
      check (FALSE, what);
      return NULL;
    }
  while (!ts_preview_done (preview) && waited_ms < WAIT_LIMIT_S * 1000)
    {
      g_usleep (10000);
      waited_ms += 10;
    }
  if (!ts_preview_done (preview))
    {
      fprintf (stderr, "test-previews: %s has not finished after %d s\n", what, WAIT_LIMIT_S);
      exit (1);
    }
  pixels = (guchar *) ts_preview_pixels (preview, width, height);
  pixels = g_memdup2 (pixels, (gsize) *width * *height * 4);
  ts_preview_free (preview);
  return pixels;
}

static gboolean
all_opaque (const guchar *pixels, gint width, gint height)
{
  for (gsize i = 0; i < (gsize) width * height; i++)
    if (pixels[4 * i + 3] != 255)
      return FALSE;
  return TRUE;
}

/* Runs one preview and checks its size and that every pixel is opaque. */
static guchar *
run (const TsPreviewInput *input, const TsPreviewSettings *settings, const gchar *what,
     gint width, gint height)
{
  gint w = 0, h = 0;
  guchar *pixels = finish (ts_preview_start (input, settings), what, &w, &h);
  gchar *text;

  if (!pixels)
    return NULL;
  text = g_strdup_printf ("%s: %dx%d (expected %dx%d), every pixel opaque", what, w, h,
                          width, height);
  check (w == width && h == height && all_opaque (pixels, w, h), text);
  g_free (text);
  return pixels;
}

static void
settings_init (TsPreviewSettings *settings)
{
  memset (settings, 0, sizeof *settings);
  ts_render_args_init (&settings->render);
  ts_solid_args_init (&settings->solid);
  ts_heal_args_init (&settings->heal);
  ts_tileable_args_init (&settings->tileable);
  ts_guided_args_init (&settings->guided);
  settings->render.seed = settings->solid.seed = settings->heal.seed = 3;
  settings->tileable.seed = settings->guided.seed = 3;
}

/* `rect` of `source` as R'G'B'A u8. */
static guchar *
read_u8 (GeglBuffer *source, const GeglRectangle *rect)
{
  guchar *pixels = g_malloc ((gsize) rect->width * rect->height * 4);

  gegl_buffer_get (source, rect, 1.0, babl_format ("R'G'B'A u8"), pixels, GEGL_AUTO_ROWSTRIDE,
                   GEGL_ABYSS_NONE);
  return pixels;
}

static void
test_copies (GeglBuffer *weave)
{
  gdouble ratio = 0.0;
  GeglBuffer *scaled = ts_preview_copy (weave, TS_PREVIEW_SIDE, TRUE, &ratio);
  GeglBuffer *middle = ts_preview_copy (weave, 100, FALSE, &ratio);
  const GeglRectangle *s = gegl_buffer_get_extent (scaled), *m = gegl_buffer_get_extent (middle);
  GeglRectangle inner = { 78, 78, 100, 100 }, whole = { 0, 0, 100, 100 };
  guchar *expected = read_u8 (weave, &inner), *got = read_u8 (middle, &whole);

  check (s->x == 0 && s->y == 0 && s->width == TS_PREVIEW_SIDE && s->height == TS_PREVIEW_SIDE,
         "a 256x256 layer scaled down fits the preview's side");
  check (m->width == 100 && m->height == 100 && ratio == 1.0 &&
         memcmp (expected, got, (gsize) 100 * 100 * 4) == 0,
         "the middle copy is the layer's middle pixels at full scale");
  g_free (expected);
  g_free (got);
  g_object_unref (scaled);
  g_object_unref (middle);
}

static void
test_heal (GeglBuffer *brick, GeglBuffer *weave)
{
  TsPreviewSettings settings;
  TsPreviewInput input = { .kind = TS_PREVIEW_HEAL_SELECTION, .ratio = 1.0 };
  GeglRectangle whole = { 0, 0, 96, 96 }, hole = { 30, 30, 30, 30 };
  GeglBuffer *mask = gegl_buffer_new (&whole, babl_format ("Y' float"));
  GeglBuffer *holed = gegl_buffer_dup (weave);
  const gfloat one = 1.0f, clear[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  guchar *before = read_u8 (brick, &whole), *after;
  gboolean kept = TRUE;

  settings_init (&settings);
  gegl_buffer_set_color_from_pixel (mask, &hole, &one, babl_format ("Y' float"));
  input.pixels = brick;
  input.mask = mask;
  after = run (&input, &settings, "heal selection", 96, 96);
  for (gint y = 0; after && y < 96; y++)
    for (gint x = 0; x < 96; x++)
      if (!gegl_rectangle_contains (&hole, &(GeglRectangle) { x, y, 1, 1 }))
        kept = kept && memcmp (before + 4 * (y * 96 + x), after + 4 * (y * 96 + x), 4) == 0;
  check (after && kept, "heal selection keeps every unselected pixel");
  g_free (before);
  g_free (after);
  g_object_unref (mask);

  /* A transparent square in a layer larger than the preview. */
  gegl_buffer_set_color_from_pixel (holed, &(GeglRectangle) { 100, 60, 50, 80 }, clear,
                                    babl_format ("R'G'B'A float"));
  input.kind = TS_PREVIEW_HEAL_TRANSPARENCY;
  input.mask = NULL;
  input.pixels = ts_preview_copy (holed, TS_PREVIEW_SIDE, TRUE, &input.ratio);
  settings.heal.context = 40;
  g_free (run (&input, &settings, "heal transparency, scaled down", TS_PREVIEW_SIDE,
               TS_PREVIEW_SIDE));
  g_object_unref (input.pixels);
  g_object_unref (holed);

  /* Uncrop of the whole brick by 50 %: 96 + 2 * 48 = 192, scaled to 160;
   * the border is filled, so every pixel is opaque. */
  input.kind = TS_PREVIEW_UNCROP;
  input.pixels = ts_preview_copy (brick, TS_PREVIEW_SIDE, TRUE, &input.ratio);
  input.image_width = input.image_height = 96;
  settings.heal.context = 0;
  settings.heal.percent = 50;
  g_free (run (&input, &settings, "uncrop by 50 %, scaled to fit", 80 + 2 * 40, 80 + 2 * 40));
  g_object_unref (input.pixels);
}

static void
test_tileable (GeglBuffer *weave)
{
  TsPreviewSettings settings;
  TsPreviewInput input = { .kind = TS_PREVIEW_TILEABLE };
  gint side = TS_PREVIEW_TILE_SIDE;
  guchar *pixels, *layer;
  gboolean repeats = TRUE, changed = FALSE;

  settings_init (&settings);
  input.pixels = ts_preview_copy (weave, side, TRUE, &input.ratio);
  pixels = run (&input, &settings, "make seamless, 2x2", 2 * side, 2 * side);
  for (gint y = 0; pixels && y < side; y++)
    for (gint x = 0; x < side; x++)
      {
        const guchar *p = pixels + 4 * (y * 2 * side + x);

        repeats = repeats && memcmp (p, p + 4 * side, 4) == 0
                  && memcmp (p, p + 4 * (gsize) side * 2 * side, 4) == 0;
      }
  check (pixels && repeats, "make seamless repeats the seamless layer 2x2");
  /* The op's failure leaves the layer as it was: the bands must change. */
  layer = read_u8 (input.pixels, gegl_buffer_get_extent (input.pixels));
  for (gint y = 0; pixels && y < side; y++)
    changed = changed || memcmp (layer + 4 * y * side, pixels + 4 * y * 2 * side, 4 * side) != 0;
  check (changed, "make seamless changes the layer");
  g_free (layer);
  g_free (pixels);
  g_object_unref (input.pixels);
}

static void
test_guided (GeglBuffer *brick, GeglBuffer *weave, GeglBuffer *bark)
{
  TsPreviewSettings settings;
  TsPreviewInput input = { .kind = TS_PREVIEW_GUIDED, .ratio = 1.0 };
  GeglRectangle left = { 0, 0, 48, 96 };
  const gfloat black[4] = { 0.0f, 0.0f, 0.0f, 1.0f }, white[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
  GeglBuffer *guide = gegl_buffer_new (gegl_buffer_get_extent (brick),
                                       babl_format ("R'G'B'A float"));

  settings_init (&settings);
  gegl_buffer_set_color_from_pixel (guide, gegl_buffer_get_extent (guide), white,
                                    babl_format ("R'G'B'A float"));
  gegl_buffer_set_color_from_pixel (guide, &left, black, babl_format ("R'G'B'A float"));
  input.pixels = ts_preview_copy (weave, TS_PREVIEW_SIDE, FALSE, &input.ratio);
  settings.exemplar = brick;
  settings.exemplar_guide = guide;
  g_free (run (&input, &settings, "texture by numbers, the target's middle", TS_PREVIEW_SIDE,
               TS_PREVIEW_SIDE));
  settings.exemplar_guide = NULL;
  g_free (run (&input, &settings, "style transfer, the target's middle", TS_PREVIEW_SIDE,
               TS_PREVIEW_SIDE));

  settings.exemplar = bark;
  settings.exemplar_guide = guide;
  check (ts_preview_start (&input, &settings) == NULL,
         "texture by numbers: no preview with a guide of another size than the exemplar");
  settings.exemplar = NULL;
  check (ts_preview_start (&input, &settings) == NULL,
         "texture by numbers: no preview without an exemplar");
  g_object_unref (input.pixels);
  g_object_unref (guide);
}

int
main (void)
{
  GeglBuffer *brick, *weave, *bark;
  TsPreviewSettings settings;
  TsExemplar exemplar = { 0 };
  TsPreviewInput input = { .kind = TS_PREVIEW_RENDER, .exemplars = &exemplar,
                           .n_exemplars = 1, .ratio = 1.0 };
  gboolean captioned = TRUE;
  gchar *missing;

  gegl_init (NULL, NULL);
  if ((missing = ts_plugin_check_ops (TS_OP_SYNTHESIZE, TS_OP_TILEABLE, TS_OP_HEAL,
                                      TS_OP_VOLUME_SLICE, TS_OP_GUIDED, NULL)))
    {
      fprintf (stderr, "test-previews: %s\n", missing);
      return 1;
    }
  brick = load ("brick.png");
  weave = load ("3dweave.png");
  bark = load ("bark.png");
  settings_init (&settings);

  test_copies (weave);
  exemplar.buffer = brick;
  settings.render.width = 300;
  settings.render.height = 100;
  g_free (run (&input, &settings, "render, at most the preview's side", TS_PREVIEW_SIDE, 100));
  input.kind = TS_PREVIEW_LAYERS;
  g_free (run (&input, &settings, "material set, the driving layer", TS_PREVIEW_SIDE, 100));
  input.kind = TS_PREVIEW_SOLID;
  g_free (run (&input, &settings, "solid, the middle slice of a small cube",
               TS_PREVIEW_SOLID_SIZE, TS_PREVIEW_SOLID_SIZE));
  test_heal (brick, weave);
  test_tileable (weave);
  test_guided (brick, weave, bark);
  for (gint kind = TS_PREVIEW_RENDER; kind <= TS_PREVIEW_GUIDED; kind++)
    captioned = captioned && strlen (ts_preview_caption (kind)) > 0;
  check (captioned, "every kind of preview has a caption");

  g_object_unref (brick);
  g_object_unref (weave);
  g_object_unref (bark);
  gegl_exit ();
  printf ("%d failure(s)\n", failures);
  return failures ? 1 : 0;
}
