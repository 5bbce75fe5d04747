/* The automatic choice of the cell structure (cell-choice.c): on for the
 * cells truth and the bundled photographs of cells in thin dark joints
 * (ground1's cracked mud, stone33's stones in mortar); off for every
 * other bundled exemplar, for the blobs and grains truths, for round
 * pebbles in wide dark gaps (which pass the stones gate, so only the
 * thin-joints test keeps them off), for tiles and bricks in rows (thin
 * grout, but along the axes) and for a translucent exemplar. An
 * automatic run is the same volume as the explicit choice it makes, and
 * a value out of range is refused. */
#include "test-util.h"
#include "slice-figures.h"
#include "solid/solid.h"
#include "engine/rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The pebbles' spacing (pixels). */
#define LATTICE 14

static bool
automatic (const TsImage *ex)
{
  TsSolidParams params;
  const TsImage *ex3[3] = { ex, ex, ex };

  ts_solid_params_init (&params);
  return ts_solid_uses_cell_structure (&params, ex3);
}

static void
test_truths (void)
{
  static const struct
  {
    const char *kind;
    size_t      side;
    uint32_t    seed;
    bool        cells;
  } cases[] = {
    { "cells", 64, 1, true },   { "cells", 64, 2, true },   { "cells", 64, 3, true },
    { "cells", 128, 1, true },  { "blobs", 64, 1, false },  { "blobs", 128, 1, false },
    { "grains", 64, 1, false }, { "grains", 128, 1, false },
  };

  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    {
      size_t n = cases[i].side;
      float *truth = slice_truth_lab (cases[i].kind, n, cases[i].seed);
      TsImage ex = { n, n, truth }; /* the truth's slice z = 0 */
      bool cells = false;
      double thin = 0.0, axis = 0.0;
      if (!truth)
        {
          CHECK (0, "%s: out of memory or unknown solid", cases[i].kind);
          continue;
        }
      CHECK (ts_solid_cells_in_joints (&ex, &cells, &thin, &axis) == TS_OK, "%s: looked at",
             cases[i].kind);
      printf ("%-6s %zu^2 seed %u: thin joints %.3f, axis edges %.3f, cells %d\n", cases[i].kind, n,
              cases[i].seed, thin, axis, cells);
      CHECK (automatic (&ex) == cases[i].cells, "%s %zu^2 seed %u: the automatic choice is %s",
             cases[i].kind, n, cases[i].seed, cases[i].cells ? "on" : "off");
      free (truth);
    }
}

static void
test_photographs (void)
{
  static const struct
  {
    const char *name;
    bool        cells;
  } cases[] = {
    { "ground1.png", true },    { "stone33.png", true },   { "3dweave.png", false },
    { "bark.png", false },      { "bluemetal.png", false }, { "brick.png", false },
    { "burlap.png", false },    { "canyons2.png", false }, { "cracked.png", false },
    { "granite1.png", false },  { "java.png", false },     { "land1.png", false },
    { "leopard.png", false },   { "parque1.png", false },  { "rock.png", false },
    { "wood1.png", false },
  };

  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    {
      TsImage ex;
      bool cells = false;
      double thin = 0.0, axis = 0.0;
      test_load_exemplar (cases[i].name, &ex);
      CHECK (ts_solid_cells_in_joints (&ex, &cells, &thin, &axis) == TS_OK, "%s: looked at",
             cases[i].name);
      printf ("%-13s thin joints %.3f, axis edges %.3f, cells %d\n", cases[i].name, thin, axis,
              cells);
      CHECK (automatic (&ex) == cases[i].cells, "%s: the automatic choice is %s", cases[i].name,
             cases[i].cells ? "on" : "off");
      free (ex.pixels);
    }
}

/* Light, shaded, round pebbles of radius 4-6.5 pixels on a jittered
 * 14-pixel lattice: dark gaps of 0-6 pixels, widest where four meet. */
static void
pebbles (TsImage *img, size_t side)
{
  uint32_t state = 12345u;

  CHECK (ts_image_alloc (img, side, side) == TS_OK, "alloc");
  for (size_t i = 0; i < side * side; i++)
    {
      float *p = img->pixels + i * TS_CHANNELS;
      p[0] = 18.0f + (float) (i * 7 % 5);
      p[1] = p[2] = 0.0f;
      p[3] = 1.0f;
    }
  for (size_t cy = 0; cy < side / LATTICE; cy++)
    for (size_t cx = 0; cx < side / LATTICE; cx++)
      {
        float jitter[2], radius;
        for (int k = 0; k < 2; k++)
          {
            jitter[k] = (float) ts_lcg_next24 (&state) / 16777216.0f * 2.0f - 1.0f;
          }
        radius = 4.0f + 2.5f * (float) ts_lcg_next24 (&state) / 16777216.0f;
        float ox = (float) (cx * LATTICE) + 7.0f + jitter[0], oy = (float) (cy * LATTICE) + 7.0f + jitter[1];
        for (size_t y = cy * LATTICE; y < cy * LATTICE + LATTICE; y++)
          for (size_t x = cx * LATTICE; x < cx * LATTICE + LATTICE; x++)
            {
              float dx = (float) x - ox, dy = (float) y - oy;
              float q = (dx * dx + dy * dy) / (radius * radius);
              if (q <= 1.0f)
                img->pixels[(y * side + x) * TS_CHANNELS] = 85.0f - 25.0f * q;
            }
      }
}

static void
test_pebbles (void)
{
  TsImage ex;
  float phase, joint;
  bool stones = false, cells = true;
  double thin = 1.0, axis = 0.0;

  pebbles (&ex, 126);
  ts_solid_splits (&ex, &phase, &joint);
  CHECK (ts_solid_phase_in_pieces (&ex, phase) == TS_SOLID_LIGHT_PIECES
           && ts_solid_exemplar_stones (&ex, phase, &stones) == TS_OK && stones,
         "the pebbles pass the stones gate");
  CHECK (ts_solid_cells_in_joints (&ex, &cells, &thin, &axis) == TS_OK, "pebbles: looked at");
  printf ("pebbles       thin joints %.3f, cells %d\n", thin, cells);
  CHECK (thin < 0.5 && !cells && !automatic (&ex),
         "round pebbles in wide gaps keep the cell structure off (thin joints %.3f)", thin);
  free (ex.pixels);
}

/* Light tiles of tile_w x tile_h pixels in 2-pixel dark grout, each row
 * shifted by `bond` pixels against the one above (0: a square grid). */
static void
tiles (TsImage *img, size_t side, size_t tile_w, size_t tile_h, size_t bond)
{
  CHECK (ts_image_alloc (img, side, side) == TS_OK, "alloc");
  for (size_t y = 0; y < side; y++)
    for (size_t x = 0; x < side; x++)
      {
        size_t row = y / tile_h, u = (x + row * bond) % side, column = u / tile_w;
        bool grout = y % tile_h < 2 || u % tile_w < 2;
        float *p = img->pixels + (y * side + x) * TS_CHANNELS;
        p[0] = grout ? 20.0f : 55.0f + (float) ((row * 7 + column * 13) % 11) * 3.0f
                                 + (float) ((x + y) % 3);
        p[1] = p[2] = 0.0f;
        p[3] = 1.0f;
      }
}

/* Tiles and bricks in rows have thin grout between separate stones, but
 * the cell structure would turn their grid into polygons. */
static void
test_rows (void)
{
  static const struct
  {
    const char *name;
    size_t      tile_w, tile_h, bond;
  } cases[] = { { "square tiles", 16, 16, 0 }, { "running bond", 24, 12, 12 } };

  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    {
      TsImage ex;
      bool cells = true;
      double thin = 0.0, axis = 0.0;
      tiles (&ex, 96, cases[i].tile_w, cases[i].tile_h, cases[i].bond);
      CHECK (ts_solid_cells_in_joints (&ex, &cells, &thin, &axis) == TS_OK, "%s: looked at",
             cases[i].name);
      printf ("%-13s thin joints %.3f, axis edges %.3f, cells %d\n", cases[i].name, thin, axis,
              cells);
      CHECK (thin >= 0.75 && axis > 0.8 && !cells && !automatic (&ex),
             "%s: thin grout along the axes keeps the cell structure off (thin joints %.3f, "
             "axis edges %.3f)", cases[i].name, thin, axis);
      free (ex.pixels);
    }
}

/* A translucent pixel turns the automatic choice off, and the run goes
 * on without the error an explicit choice gets. */
static void
test_translucent (void)
{
  size_t n = 64, side = 16;
  float *truth = slice_truth_lab ("cells", n, 1);
  float *volume = malloc (side * side * side * TS_CHANNELS * sizeof (float));
  TsImage ex = { n, n, truth };
  TsSolidParams params;
  TsError error;

  if (!truth || !volume)
    {
      CHECK (0, "out of memory");
      free (truth), free (volume);
      return;
    }
  ex.pixels[5 * TS_CHANNELS + 3] = 0.5f;
  const TsImage *ex3[3] = { &ex, &ex, &ex };
  CHECK (!automatic (&ex), "a translucent cells exemplar: automatic is off");
  ts_solid_params_init (&params);
  params.size = side;
  CHECK (ts_synthesize_solid (&params, ex3, volume, NULL, NULL, &error) == TS_OK,
         "automatic on a translucent exemplar runs: %s", error.message);
  free (truth);
  free (volume);
}

/* The automatic run is the explicit one it chooses, voxel for voxel. */
static void
test_same_volume (const char *kind, TsCellStructure chosen)
{
  size_t n = 64, side = 24, floats = side * side * side * TS_CHANNELS;
  float *truth = slice_truth_lab (kind, n, 2);
  float *a = malloc (floats * sizeof (float)), *b = malloc (floats * sizeof (float));
  TsImage ex = { n, n, truth };
  TsSolidParams params;
  TsError error;

  if (!truth || !a || !b)
    {
      CHECK (0, "out of memory");
      free (truth), free (a), free (b);
      return;
    }
  const TsImage *ex3[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&params);
  params.size = side;
  params.seed = 4;
  CHECK (ts_synthesize_solid (&params, ex3, a, NULL, NULL, &error) == TS_OK, "%s automatic: %s",
         kind, error.message);
  params.cell_structure = chosen;
  CHECK (ts_synthesize_solid (&params, ex3, b, NULL, NULL, &error) == TS_OK, "%s chosen: %s", kind,
         error.message);
  CHECK (memcmp (a, b, floats * sizeof (float)) == 0,
         "%s: the automatic volume is the one with the cell structure %s", kind,
         chosen == TS_CELL_STRUCTURE_ON ? "on" : "off");
  params.cell_structure = chosen == TS_CELL_STRUCTURE_ON ? TS_CELL_STRUCTURE_OFF : TS_CELL_STRUCTURE_ON;
  CHECK (ts_synthesize_solid (&params, ex3, b, NULL, NULL, &error) == TS_OK, "%s other: %s", kind,
         error.message);
  CHECK (memcmp (a, b, floats * sizeof (float)) != 0, "%s: the other choice differs", kind);
  free (truth);
  free (a);
  free (b);
}

static void
test_explicit_and_invalid (void)
{
  TsImage ex;
  TsSolidParams params;
  TsError error;

  test_load_exemplar ("java.png", &ex);
  const TsImage *ex3[3] = { &ex, &ex, &ex };
  ts_solid_params_init (&params);
  CHECK (params.cell_structure == TS_CELL_STRUCTURE_AUTO, "automatic is the default");
  params.cell_structure = TS_CELL_STRUCTURE_ON;
  CHECK (ts_solid_uses_cell_structure (&params, ex3), "on is on whatever the exemplar");
  params.cell_structure = TS_CELL_STRUCTURE_OFF;
  CHECK (!ts_solid_uses_cell_structure (&params, ex3), "off is off");
  params.cell_structure = (TsCellStructure) 7;
  CHECK (ts_solid_params_validate (&params, ex3, &error) == TS_ERROR_BAD_PARAMETER
           && strstr (error.message, "cell structure must be off"),
         "a value out of range is refused: %s", error.message);
  free (ex.pixels);
}

int
main (void)
{
  test_truths ();
  test_photographs ();
  test_pebbles ();
  test_rows ();
  test_translucent ();
  test_same_volume ("cells", TS_CELL_STRUCTURE_ON);
  test_same_volume ("blobs", TS_CELL_STRUCTURE_OFF);
  test_explicit_and_invalid ();
  return test_finish ("test-solid-cell-choice");
}
