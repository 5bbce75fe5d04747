/* Two texsynth nodes in one GEGL graph (synthesize, then tileable on its
 * result, composited over a second synthesize) rendered with 1 and with 4
 * GEGL threads, and the same graph processed from two threads at once:
 * every result must be bit-identical. Built in scripts/sanitize.sh's
 * ThreadSanitizer build too, where the op modules are instrumented.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include <gegl.h>
#include <pthread.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIDE 64
#define FORMAT "R'G'B'A float"

static int failures;

#define CHECK(cond, ...)                                              \
  do {                                                                \
    if (!(cond)) {                                                    \
      failures++;                                                     \
      fprintf (stderr, "%s:%d: CHECK failed: ", __FILE__, __LINE__);  \
      fprintf (stderr, __VA_ARGS__);                                  \
      fputc ('\n', stderr);                                           \
    }                                                                 \
  } while (0)

static const char *exemplar_path;

/* load -> synthesize(seed 1) -> tileable -> over <- synthesize(seed 2, half transparent) */
static float *
render_graph (void)
{
  GeglNode *graph = gegl_node_new ();
  GeglNode *load = gegl_node_new_child (graph, "operation", "gegl:load", "path", exemplar_path, NULL);
  GeglNode *a = gegl_node_new_child (graph, "operation", "texsynth:synthesize", "width", SIDE,
                                     "height", SIDE, "seed", 1, NULL);
  GeglNode *tile = gegl_node_new_child (graph, "operation", "texsynth:tileable", "seed", 3, NULL);
  GeglNode *b = gegl_node_new_child (graph, "operation", "texsynth:synthesize", "width", SIDE,
                                     "height", SIDE, "seed", 2, NULL);
  GeglNode *fade = gegl_node_new_child (graph, "operation", "gegl:opacity", "value", 0.5, NULL);
  GeglNode *over = gegl_node_new_child (graph, "operation", "gegl:over", NULL);
  GeglRectangle rect = { 0, 0, SIDE, SIDE };
  float *pixels = calloc (SIDE * SIDE * 4, sizeof (float));

  if (!pixels)
    {
      fprintf (stderr, "out of memory\n");
      exit (1);
    }
  gegl_node_link_many (load, a, tile, over, NULL);
  gegl_node_link_many (load, b, fade, NULL);
  gegl_node_connect_from (over, "aux", fade, "output");
  gegl_node_blit (over, 1.0, &rect, babl_format (FORMAT), pixels, GEGL_AUTO_ROWSTRIDE,
                  GEGL_BLIT_DEFAULT);
  g_object_unref (graph);
  return pixels;
}

static void *
render_thread (void *data)
{
  *(float **) data = render_graph ();
  return NULL;
}

static bool
same (const float *a, const float *b)
{
  return memcmp (a, b, SIDE * SIDE * 4 * sizeof (float)) == 0;
}

int
main (int argc, char **argv)
{
  float *serial, *threaded, *parallel[2] = { NULL, NULL };
  pthread_t threads[2];
  double alpha_sum = 0.0;
  int identical = 0;

  if (argc != 2)
    {
      fprintf (stderr, "usage: test-gegl-threads EXEMPLAR.png\n");
      return 2;
    }
  exemplar_path = argv[1];
  gegl_init (&argc, &argv);
  if (!gegl_has_operation ("texsynth:synthesize") || !gegl_has_operation ("texsynth:tileable"))
    {
      fprintf (stderr, "texsynth ops not found (GEGL_PATH=%s)\n", g_getenv ("GEGL_PATH"));
      return 1;
    }

  g_object_set (gegl_config (), "threads", 1, NULL);
  serial = render_graph ();
  for (size_t i = 0; i < SIDE * SIDE; i++)
    alpha_sum += serial[4 * i + 3];
  CHECK (alpha_sum > 0.99 * SIDE * SIDE, "the serial result is opaque (mean alpha %.3f)",
         alpha_sum / (SIDE * SIDE));

  g_object_set (gegl_config (), "threads", 4, NULL);
  threaded = render_graph ();
  CHECK (same (serial, threaded), "4 GEGL threads give the same pixels as 1");
  identical += same (serial, threaded);

  for (int t = 0; t < 2; t++)
    if (pthread_create (&threads[t], NULL, render_thread, &parallel[t]) != 0)
      {
        fprintf (stderr, "cannot start a thread\n");
        return 1;
      }
  for (int t = 0; t < 2; t++)
    {
      pthread_join (threads[t], NULL);
      CHECK (same (serial, parallel[t]), "graph processed in thread %d at once with another "
             "gives the serial pixels", t);
      identical += same (serial, parallel[t]);
    }
  printf ("GEGL concurrency figures: 2 texsynth:synthesize + 1 texsynth:tileable node per graph; "
          "%d of 3 renders (4 GEGL threads; 2 graphs in 2 threads at once) identical to the "
          "1-thread render\n", identical);

  free (serial);
  free (threaded);
  free (parallel[0]);
  free (parallel[1]);
  gegl_exit ();
  if (failures)
    fprintf (stderr, "test-gegl-threads: %d check(s) failed\n", failures);
  else
    printf ("test-gegl-threads: all checks passed\n");
  return failures ? 1 : 0;
}
