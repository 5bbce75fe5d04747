/* The phase guide's parts (phase-guide.c, neck-walls.c): which
 * exemplars turn it on, the walls that part two light balls joined by a
 * neck and leave a lone ball alone, and the clipped signed distances. */
#include "test-util.h"
#include "solid/solid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define LIGHT_L 80.0f
#define DARK_L 20.0f
#define SPLIT 50.0f

/* Discs of radius 5 on a 12-pixel lattice, light on dark or dark on
 * light, side x side. */
static void
discs (TsImage *img, size_t side, bool light_discs)
{
  CHECK (ts_image_alloc (img, side, side) == TS_OK, "alloc");
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      {
        float dx = (float) (x % 12) - 6.0f, dy = (float) (y % 12) - 6.0f;
        bool in = dx * dx + dy * dy <= 25.0f;
        float *p = img->pixels + (y * side + x) * TS_CHANNELS;
        p[0] = in == light_discs ? LIGHT_L : DARK_L;
        p[1] = p[2] = 0.0f;
        p[3] = 1.0f;
      }
}

static void
test_gate (void)
{
  TsImage img;
  discs (&img, 48, true);
  CHECK (ts_solid_pieces_apart (&img, SPLIT), "light discs on dark ground: pieces apart");
  free (img.pixels);
  discs (&img, 48, false);
  CHECK (!ts_solid_pieces_apart (&img, SPLIT), "dark discs on light ground: one light piece");
  free (img.pixels);
}

#define N 32

/* A periodic N^3 level, dark but for balls of radius 6 at (cx, 16, 16),
 * and a light rod of radius 1 along x between them if `neck`. */
static float *
balls (TsSolidLevel *level, const float *cx, size_t count, bool neck)
{
  float *value = calloc ((size_t) N * N * N * TS_CHANNELS, sizeof (float));
  CHECK (value != NULL, "alloc");
  memset (level, 0, sizeof *level);
  level->n = N;
  level->periodic = true;
  level->value = value;
  for (size_t p = 0; value && p < (size_t) N * N * N; p++)
    {
      float x = (float) (p % N), y = (float) (p / N % N), z = (float) (p / N / N);
      bool in = neck && fabsf (y - 16.0f) <= 1.0f && fabsf (z - 16.0f) <= 1.0f && x >= cx[0]
                && x <= cx[count - 1];
      for (size_t b = 0; b < count; b++)
        in = in || (x - cx[b]) * (x - cx[b]) + (y - 16.0f) * (y - 16.0f) + (z - 16.0f) * (z - 16.0f) <= 36.0f;
      value[p * TS_CHANNELS] = in ? LIGHT_L : DARK_L;
      value[p * TS_CHANNELS + 3] = 1.0f;
    }
  return value;
}

/* 6-connected light pieces of the level. */
static size_t
light_pieces (const TsSolidLevel *level)
{
  size_t voxels = (size_t) N * N * N, pieces = 0;
  uint8_t *seen = calloc (voxels, 1);
  size_t *stack = malloc (voxels * sizeof (size_t));
  for (size_t p0 = 0; seen && stack && p0 < voxels; p0++)
    {
      if (seen[p0] || !ts_solid_is_light (level->value + p0 * TS_CHANNELS, SPLIT))
        continue;
      size_t top = 0;
      pieces++;
      stack[top++] = p0;
      seen[p0] = 1;
      while (top > 0)
        {
          size_t p = stack[--top], xyz[3] = { p % N, p / N % N, p / N / N };
          for (int k = 0; k < 6; k++)
            {
              size_t q = ts_solid_face_neighbour (level, xyz, k / 2, k & 1);
              if (!seen[q] && ts_solid_is_light (level->value + q * TS_CHANNELS, SPLIT))
                {
                  seen[q] = 1;
                  stack[top++] = q;
                }
            }
        }
    }
  free (seen);
  free (stack);
  return pieces;
}

static void
test_walls (void)
{
  TsSolidLevel level;
  const float two[2] = { 9.0f, 23.0f }, one[1] = { 16.0f };

  float *value = balls (&level, two, 2, true);
  CHECK (light_pieces (&level) == 1, "the neck joins the balls: %zu pieces", light_pieces (&level));
  CHECK (ts_solid_wall_necks (&level, SPLIT) == TS_OK, "walls");
  CHECK (light_pieces (&level) == 2, "a wall parts the balls: %zu pieces", light_pieces (&level));
  size_t deep_light = 0;
  for (size_t p = 0; p < (size_t) N * N * N; p++)
    {
      float x = (float) (p % N), y = (float) (p / N % N), z = (float) (p / N / N);
      for (int b = 0; b < 2; b++)
        deep_light += (x - two[b]) * (x - two[b]) + (y - 16.0f) * (y - 16.0f) + (z - 16.0f) * (z - 16.0f) <= 9.0f
                      && value[p * TS_CHANNELS] == LIGHT_L;
    }
  CHECK (deep_light == 2 * 123, "the balls' cores stay light: %zu of %d voxels", deep_light, 2 * 123);
  free (value);

  value = balls (&level, one, 1, false);
  float *before = malloc ((size_t) N * N * N * TS_CHANNELS * sizeof (float));
  CHECK (before != NULL, "alloc");
  if (before)
    {
      memcpy (before, value, (size_t) N * N * N * TS_CHANNELS * sizeof (float));
      CHECK (ts_solid_wall_necks (&level, SPLIT) == TS_OK, "walls, one ball");
      CHECK (memcmp (before, value, (size_t) N * N * N * TS_CHANNELS * sizeof (float)) == 0,
             "a lone ball has no neck: nothing changes");
    }
  free (before);
  free (value);

  /* All light: no dark voxel to measure from, and nothing to do. */
  value = balls (&level, one, 0, false);
  for (size_t p = 0; p < (size_t) N * N * N; p++)
    value[p * TS_CHANNELS] = LIGHT_L;
  CHECK (ts_solid_wall_necks (&level, SPLIT) == TS_OK && light_pieces (&level) == 1, "all light");
  free (value);
}

static void
test_field (void)
{
  TsSolidLevel level;
  const float one[1] = { 16.0f };
  float *value = balls (&level, one, 1, false), *field = NULL;

  CHECK (ts_solid_phase_field (&level, SPLIT, &field) == TS_OK, "field");
  if (field)
    {
      size_t centre = (16 * N + 16) * N + 16, surface = (16 * N + 16) * N + 22,
             outside = (16 * N + 16) * N + 23, far = 0;
      CHECK (field[centre] == TS_SOLID_PHASE_CLIP, "the centre, clipped: %.2f", field[centre]);
      CHECK (field[far] == -TS_SOLID_PHASE_CLIP, "far outside, clipped: %.2f", field[far]);
      CHECK (field[surface] == 0.5f && field[outside] == -0.5f,
             "half a voxel off the boundary on either side: %.2f, %.2f", field[surface], field[outside]);
    }
  free (field);
  free (value);
}

/* A light-discs exemplar turns the guide on (96^2 gives the 32^3 volume
 * two levels; the guide needs a coarser one): the volume is still the
 * same at any thread count. */
static void
test_threads (void)
{
  TsImage img;
  TsSolidParams p;
  TsError error;
  size_t n = 32, floats = n * n * n * TS_CHANNELS;
  float *one = malloc (floats * sizeof (float)), *two = malloc (floats * sizeof (float));

  discs (&img, 96, true);
  /* Shade the discs so the volume's phases come from exemplar colours. */
  for (size_t i = 0; i < 96 * 96; i++)
    img.pixels[i * TS_CHANNELS + 1] = (float) (i % 7);
  const TsImage *ex[3] = { &img, &img, &img };
  ts_solid_params_init (&p);
  p.size = n;
  p.seed = 3;
  CHECK (one && two, "alloc");
#ifdef _OPENMP
  omp_set_num_threads (1);
#endif
  CHECK (one && ts_synthesize_solid (&p, ex, one, NULL, NULL, &error) == TS_OK, "1 thread");
#ifdef _OPENMP
  omp_set_num_threads (2);
#endif
  CHECK (two && ts_synthesize_solid (&p, ex, two, NULL, NULL, &error) == TS_OK, "2 threads");
  CHECK (one && two && memcmp (one, two, floats * sizeof (float)) == 0,
         "1 and 2 threads give identical volumes");
  free (one);
  free (two);
  free (img.pixels);
}

int
main (void)
{
  test_gate ();
  test_walls ();
  test_field ();
  test_threads ();
  return test_finish ("test-solid-phases");
}
