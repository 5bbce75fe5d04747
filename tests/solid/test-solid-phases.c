/* The phase guide's parts (phase-guide.c, neck-walls.c,
 * piece-topology.c): which exemplars turn it on and for which phase, and
 * which have stones, the walls that part two balls (light on dark, or
 * dark on light) joined by a neck and leave a lone ball alone, the test
 * that keeps two stones apart, and the clipped signed distances. */
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

/* Discs of the radius on a 12-pixel lattice, light on dark or dark on
 * light, side x side. */
static void
discs_of (TsImage *img, size_t side, bool light_discs, float radius)
{
  CHECK (ts_image_alloc (img, side, side) == TS_OK, "alloc");
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      {
        float dx = (float) (x % 12) - 6.0f, dy = (float) (y % 12) - 6.0f;
        bool in = dx * dx + dy * dy <= radius * radius;
        float *p = img->pixels + (y * side + x) * TS_CHANNELS;
        p[0] = in == light_discs ? LIGHT_L : DARK_L;
        p[1] = p[2] = 0.0f;
        p[3] = 1.0f;
      }
}

static void
discs (TsImage *img, size_t side, bool light_discs)
{
  discs_of (img, side, light_discs, 5.0f);
}

static void
test_gate (void)
{
  TsImage img;
  discs (&img, 48, true);
  CHECK (ts_solid_phase_in_pieces (&img, SPLIT) == TS_SOLID_LIGHT_PIECES,
         "light discs on dark ground: the light phase in pieces");
  free (img.pixels);
  discs (&img, 48, false);
  CHECK (ts_solid_phase_in_pieces (&img, SPLIT) == TS_SOLID_DARK_PIECES,
         "dark discs on light ground: the dark phase in pieces");
  /* Light left half, dark right half: each phase one piece. */
  for (size_t i = 0; i < 48 * 48; i++)
    img.pixels[i * TS_CHANNELS] = i % 48 < 24 ? LIGHT_L : DARK_L;
  CHECK (ts_solid_phase_in_pieces (&img, SPLIT) == TS_SOLID_NO_PIECES, "two halves: no pieces");
  free (img.pixels);
  /* Transparent pixels are neither phase: dark discs on a transparent
   * ground are still dark pieces, light ones none. */
  discs (&img, 48, false);
  for (size_t i = 0; i < 48 * 48; i++)
    if (img.pixels[i * TS_CHANNELS] == LIGHT_L)
      img.pixels[i * TS_CHANNELS + 3] = 0.0f;
  CHECK (ts_solid_phase_in_pieces (&img, SPLIT) == TS_SOLID_DARK_PIECES,
         "dark discs on a transparent ground: the dark phase in pieces");
  free (img.pixels);
}

/* The plan of a run on one exemplar; whether it holds stones. */
static bool
planned_stones (const TsImage *img, TsSolidPhasePlan *plan)
{
  const TsImage *finest[1] = { img };
  const int exemplar_of[TS_SOLID_AXES] = { 0, 0, 0 };

  CHECK (ts_solid_phase_plan (plan, finest, 1, exemplar_of) == TS_OK, "the phase plan is made");
  return plan->stones;
}

/* Stones are light pieces with insides: discs of radius 5 are, grains
 * of radius 1.5 are not. Stones are parted at the joint split, other
 * pieces at the phase split. */
static void
test_stones (void)
{
  TsImage img;
  TsSolidPhasePlan plan;
  float phase, joint;

  discs (&img, 48, true);
  ts_solid_splits (&img, &phase, &joint);
  CHECK (planned_stones (&img, &plan) && plan.pieces == TS_SOLID_LIGHT_PIECES,
         "discs of radius 5: stones");
  CHECK (joint < phase && plan.split[0] == joint, "stones are parted at the joint split");
  CHECK (plan.neck_height == TS_SOLID_STONE_NECK_HEIGHT && TS_SOLID_STONE_NECK_HEIGHT < TS_SOLID_NECK_HEIGHT,
         "stones are walled at lower necks than other pieces: %g", (double) plan.neck_height);
  ts_solid_phase_plan_free (&plan);
  free (img.pixels);
  discs_of (&img, 48, true, 1.5f);
  ts_solid_splits (&img, &phase, &joint);
  CHECK (!planned_stones (&img, &plan) && plan.pieces == TS_SOLID_LIGHT_PIECES,
         "grains of radius 1.5: light pieces, not stones");
  CHECK (plan.split[0] == phase, "grains are parted at the phase split");
  CHECK (plan.neck_height == TS_SOLID_NECK_HEIGHT, "grains are walled at the pieces' neck height: %g",
         (double) plan.neck_height);
  ts_solid_phase_plan_free (&plan);
  free (img.pixels);
}

#define N 32

/* A periodic N^3 level, dark but for balls of radius 6 at (cx, 16, 16),
 * and a light rod of radius 1 along x between them if `neck`; light and
 * dark swapped if `dark_balls`. */
static float *
balls (TsSolidLevel *level, const float *cx, size_t count, bool neck, bool dark_balls)
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
      value[p * TS_CHANNELS] = in != dark_balls ? LIGHT_L : DARK_L;
      value[p * TS_CHANNELS + 3] = 1.0f;
    }
  return value;
}

/* 6-connected pieces of the level's light (or dark) voxels. */
static size_t
phase_pieces (const TsSolidLevel *level, bool light)
{
  size_t voxels = (size_t) N * N * N, pieces = 0;
  uint8_t *seen = calloc (voxels, 1);
  size_t *stack = malloc (voxels * sizeof (size_t));
  for (size_t p0 = 0; seen && stack && p0 < voxels; p0++)
    {
      if (seen[p0] || ts_solid_is_light (level->value + p0 * TS_CHANNELS, SPLIT) != light)
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
              if (!seen[q] && ts_solid_is_light (level->value + q * TS_CHANNELS, SPLIT) == light)
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

/* Two balls joined by a neck, then a lone ball, of the phase in pieces
 * (light on dark, or dark on light). */
static void
test_walls (bool dark_balls)
{
  TsSolidLevel level;
  const float two[2] = { 9.0f, 23.0f }, one[1] = { 16.0f };
  TsSolidPieces pieces = dark_balls ? TS_SOLID_DARK_PIECES : TS_SOLID_LIGHT_PIECES;
  float ball_l = dark_balls ? DARK_L : LIGHT_L;
  const char *kind = dark_balls ? "dark balls" : "light balls";

  float *value = balls (&level, two, 2, true, dark_balls);
  CHECK (phase_pieces (&level, !dark_balls) == 1, "%s: the neck joins them: %zu pieces", kind,
         phase_pieces (&level, !dark_balls));
  CHECK (ts_solid_wall_necks (&level, SPLIT, pieces, TS_SOLID_NECK_HEIGHT, NULL) == TS_OK, "%s: walls", kind);
  CHECK (phase_pieces (&level, !dark_balls) == 2, "%s: a wall parts them: %zu pieces", kind,
         phase_pieces (&level, !dark_balls));
  CHECK (phase_pieces (&level, dark_balls) == 1, "%s: the ground stays one piece: %zu", kind,
         phase_pieces (&level, dark_balls));
  size_t deep = 0;
  for (size_t p = 0; p < (size_t) N * N * N; p++)
    {
      float x = (float) (p % N), y = (float) (p / N % N), z = (float) (p / N / N);
      for (int b = 0; b < 2; b++)
        deep += (x - two[b]) * (x - two[b]) + (y - 16.0f) * (y - 16.0f) + (z - 16.0f) * (z - 16.0f) <= 9.0f
                && value[p * TS_CHANNELS] == ball_l;
    }
  CHECK (deep == 2 * 123, "%s: their cores stay as they were: %zu of %d voxels", kind, deep, 2 * 123);
  free (value);

  /* The balls' peaks (radius 6) rise less than 7 voxels above the neck. */
  value = balls (&level, two, 2, true, dark_balls);
  CHECK (ts_solid_wall_necks (&level, SPLIT, pieces, 7.0f, NULL) == TS_OK
             && phase_pieces (&level, !dark_balls) == 1,
         "%s: no wall where the peaks rise less than the neck height: %zu pieces", kind,
         phase_pieces (&level, !dark_balls));
  free (value);

  value = balls (&level, one, 1, false, dark_balls);
  float *before = malloc ((size_t) N * N * N * TS_CHANNELS * sizeof (float));
  CHECK (before != NULL, "alloc");
  if (before)
    {
      memcpy (before, value, (size_t) N * N * N * TS_CHANNELS * sizeof (float));
      CHECK (ts_solid_wall_necks (&level, SPLIT, pieces, TS_SOLID_NECK_HEIGHT, NULL) == TS_OK,
             "%s: walls, one ball", kind);
      CHECK (memcmp (before, value, (size_t) N * N * N * TS_CHANNELS * sizeof (float)) == 0,
             "%s: a lone ball has no neck: nothing changes", kind);
    }
  free (before);
  free (value);

  /* All of the pieces' phase: no ground voxel to measure from, and
   * nothing to do. */
  value = balls (&level, one, 0, false, dark_balls);
  for (size_t p = 0; p < (size_t) N * N * N; p++)
    value[p * TS_CHANNELS] = ball_l;
  CHECK (ts_solid_wall_necks (&level, SPLIT, pieces, TS_SOLID_NECK_HEIGHT, NULL) == TS_OK
             && phase_pieces (&level, !dark_balls) == 1,
         "%s: all one phase", kind);
  free (value);
}

/* Two light balls two voxels apart: a voxel of the gap would join them,
 * one outside them would not; voxels of the E-step's current batch do
 * not count. */
static void
test_kept_apart (void)
{
  TsSolidLevel level;
  const float two[2] = { 9.0f, 23.0f };
  float *value = balls (&level, two, 2, false, false);
  uint8_t *batch_of = calloc ((size_t) N * N * N, 1);
  const size_t gap[3] = { 16, 16, 16 }, beside[3] = { 2, 16, 16 }, above[3] = { 16, 16, 20 };

  CHECK (batch_of != NULL, "alloc");
  CHECK (phase_pieces (&level, true) == 2, "two balls");
  CHECK (batch_of && ts_solid_joins_pieces (&level, gap, batch_of, 1, SPLIT, true),
         "a voxel between the balls joins them");
  CHECK (batch_of && !ts_solid_joins_pieces (&level, beside, batch_of, 1, SPLIT, true),
         "a voxel beside one ball joins nothing");
  CHECK (batch_of && !ts_solid_joins_pieces (&level, above, batch_of, 1, SPLIT, true),
         "a voxel far from both joins nothing");
  CHECK (batch_of && !ts_solid_joins_pieces (&level, gap, batch_of, 0, SPLIT, true),
         "neighbours in the current batch do not count");
  CHECK (batch_of && !ts_solid_joins_pieces (&level, gap, batch_of, 1, SPLIT, false),
         "the dark phase around the gap is one piece");
  free (batch_of);
  free (value);
}

static void
test_field (void)
{
  TsSolidLevel level;
  const float one[1] = { 16.0f };
  float *value = balls (&level, one, 1, false, false), *field = NULL;

  CHECK (ts_solid_phase_field (&level, SPLIT, &field, NULL) == TS_OK, "field");
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
  TsSolidPhasePlan plan;
  CHECK (planned_stones (&img, &plan), "the discs are stones, so the E-step keeps them apart");
  ts_solid_phase_plan_free (&plan);
  /* Shade the discs so the volume's phases come from exemplar colours. */
  for (size_t i = 0; i < 96 * 96; i++)
    img.pixels[i * TS_CHANNELS + 1] = (float) (i % 7);
  const TsImage *ex[3] = { &img, &img, &img };
  ts_solid_params_init (&p);
  p.size = n;
  p.seed = 3;
  /* The default path's phase guide and its E-step rule are under test. */
  p.cell_structure = TS_CELL_STRUCTURE_OFF;
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
  test_stones ();
  test_walls (false);
  test_kept_apart ();
  test_walls (true);
  test_field ();
  test_threads ();
  return test_finish ("test-solid-phases");
}
