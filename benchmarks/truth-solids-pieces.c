/* Truth solids made of pieces in a matrix: balls, ellipsoids, rods and
 * angular chips, placed at random positions and orientations in the
 * periodic cube. Each piece has a signed distance (negative inside);
 * its edge is blended over one voxel, so slices in any direction show
 * smooth outlines rather than voxel steps.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "truth-solids-internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
/* Most planes cutting one chip. */
#define CHIP_MAX_FACES 12
/* Distances beyond this (voxels, outside a piece) leave a voxel as matrix. */
#define EDGE_BAND 1.0
/* Placement attempts per piece wanted before a kind gives up filling. */
#define ATTEMPTS_PER_PIECE 40

typedef enum
{
  SHAPE_BALL,
  SHAPE_ELLIPSOID,
  SHAPE_ROD,
  SHAPE_CHIP
} Shape;

typedef struct
{
  Shape  shape;
  double centre[3];
  double reach;     /* radius of a ball around the centre holding the piece */
  double radius;    /* ball, rod */
  double axis[3];   /* rod: unit direction */
  double half_length;
  double rotation[9]; /* ellipsoid: rows are the body axes */
  double semi[3];
  int    faces;     /* chip: half-spaces n . q <= offset */
  double normal[CHIP_MAX_FACES][3];
  double offset[CHIP_MAX_FACES];
  double colour[3];
} Piece;

typedef struct
{
  Piece *pieces;
  size_t count, capacity;
  /* Per voxel: the nearest and second nearest piece's signed distance
   * and index (NO_PIECE: none within EDGE_BAND). */
  float    *near1, *near2;
  uint32_t *owner1, *owner2;
  uint8_t  *taken;  /* separate pieces: voxels already claimed */
  double    filled; /* voxels inside pieces so far */
} Pack;

#define NO_PIECE UINT32_MAX

/* How a kind looks and how its pieces are drawn. */
typedef struct
{
  const char *name;
  uint32_t    stream;
  double      fill;     /* pieces' summed volume over the cube's */
  double      gap;      /* separate pieces: least distance between them; < 0 may overlap */
  bool        largest_first; /* separate pieces of many sizes: place the big ones first */
  /* a piece of size quantile `size` in [0, 1), its centre left unset */
  void (*draw) (const TruthSolid *s, uint32_t stream, uint64_t key, double size, Piece *piece);
  double      matrix[3], matrix_noise, piece_noise;
} Kind;

static double
u01 (const TruthSolid *s, uint32_t stream, uint64_t key, int slot)
{
  return truth_uniform (s, stream, key * 64u + (uint64_t) slot);
}

static void
random_direction (const TruthSolid *s, uint32_t stream, uint64_t key, int slot, double d[3])
{
  double z = 2.0 * u01 (s, stream, key, slot) - 1.0, phi = 2.0 * PI * u01 (s, stream, key, slot + 1);
  double r = sqrt (fmax (0.0, 1.0 - z * z));
  d[0] = r * cos (phi);
  d[1] = r * sin (phi);
  d[2] = z;
}

/* A uniformly random rotation, from a uniformly random unit quaternion. */
static void
random_rotation (const TruthSolid *s, uint32_t stream, uint64_t key, int slot, double m[9])
{
  double u1 = u01 (s, stream, key, slot), u2 = 2.0 * PI * u01 (s, stream, key, slot + 1),
         u3 = 2.0 * PI * u01 (s, stream, key, slot + 2);
  double w = sqrt (1.0 - u1) * sin (u2), x = sqrt (1.0 - u1) * cos (u2);
  double y = sqrt (u1) * sin (u3), z = sqrt (u1) * cos (u3);
  m[0] = 1 - 2 * (y * y + z * z), m[1] = 2 * (x * y - z * w), m[2] = 2 * (x * z + y * w);
  m[3] = 2 * (x * y + z * w), m[4] = 1 - 2 * (x * x + z * z), m[5] = 2 * (y * z - x * w);
  m[6] = 2 * (x * z - y * w), m[7] = 2 * (y * z + x * w), m[8] = 1 - 2 * (x * x + y * y);
}

static void
place_centre (const TruthSolid *s, uint32_t stream, uint64_t key, Piece *piece)
{
  for (int a = 0; a < 3; a++)
    piece->centre[a] = (double) s->n * u01 (s, stream, key, a);
}

static void
tone (double colour[3], const double base[3], double amount)
{
  for (int c = 0; c < 3; c++)
    colour[c] = base[c] + amount;
}

/* Signed distance from the piece's centre + q to its surface, in voxels
 * (exact for balls and rods, first order near the surface otherwise). */
static double
signed_distance (const Piece *piece, const double q[3])
{
  switch (piece->shape)
    {
    case SHAPE_BALL:
      return sqrt (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) - piece->radius;
    case SHAPE_ROD:
      {
        double t = q[0] * piece->axis[0] + q[1] * piece->axis[1] + q[2] * piece->axis[2], d = 0.0;
        t = fmax (-piece->half_length, fmin (piece->half_length, t));
        for (int a = 0; a < 3; a++)
          d += (q[a] - t * piece->axis[a]) * (q[a] - t * piece->axis[a]);
        return sqrt (d) - piece->radius;
      }
    case SHAPE_ELLIPSOID:
      {
        double f = 0.0, g = 0.0;
        for (int a = 0; a < 3; a++)
          {
            const double *row = piece->rotation + 3 * a;
            double body = row[0] * q[0] + row[1] * q[1] + row[2] * q[2];
            double k = body / (piece->semi[a] * piece->semi[a]);
            f += body * k;
            g += k * k;
          }
        f = sqrt (f);
        /* (f - 1) / |grad f|, with |grad f| = sqrt (g) / f */
        return f < 1e-9 ? -fmin (piece->semi[0], fmin (piece->semi[1], piece->semi[2]))
                        : (f - 1.0) * f / sqrt (g);
      }
    case SHAPE_CHIP:
      {
        /* a bounding ball keeps a chip finite whichever planes it drew */
        double d = sqrt (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) - piece->reach;
        for (int f = 0; f < piece->faces; f++)
          d = fmax (d, piece->normal[f][0] * q[0] + piece->normal[f][1] * q[1]
                         + piece->normal[f][2] * q[2] - piece->offset[f]);
        return d;
      }
    }
  return INFINITY;
}


typedef enum
{
  VISIT_CHECK_FREE, /* false as soon as a voxel within `band` is taken */
  VISIT_CLAIM,      /* marks the voxels within `band` taken */
  VISIT_RECORD      /* keeps the two nearest pieces of every voxel within EDGE_BAND */
} Visit;

static void
record (Pack *pack, uint32_t index, size_t voxel, double d)
{
  float f = (float) d;
  if (d < 0.0)
    pack->filled += 1.0;
  if (f < pack->near1[voxel])
    {
      pack->near2[voxel] = pack->near1[voxel];
      pack->owner2[voxel] = pack->owner1[voxel];
      pack->near1[voxel] = f;
      pack->owner1[voxel] = index;
    }
  else if (f < pack->near2[voxel])
    {
      pack->near2[voxel] = f;
      pack->owner2[voxel] = index;
    }
}

/* Visits every voxel within `band` of the piece, the cube wrapping
 * around (a piece wider than the cube meets its own images, as a
 * periodic volume should). */
static bool
visit_voxels (Pack *pack, const TruthSolid *s, const Piece *piece, uint32_t index, Visit what, double band)
{
  long lo[3], hi[3];
  for (int a = 0; a < 3; a++)
    {
      lo[a] = (long) floor (piece->centre[a] - piece->reach - band);
      hi[a] = (long) ceil (piece->centre[a] + piece->reach + band);
    }
  for (long z = lo[2]; z <= hi[2]; z++)
    for (long y = lo[1]; y <= hi[1]; y++)
      for (long x = lo[0]; x <= hi[0]; x++)
        {
          double q[3] = { (double) x - piece->centre[0], (double) y - piece->centre[1],
                          (double) z - piece->centre[2] };
          double d = signed_distance (piece, q);
          size_t voxel;
          if (d >= band)
            continue;
          voxel = (truth_wrap (z, s->n) * s->n + truth_wrap (y, s->n)) * s->n + truth_wrap (x, s->n);
          if (what == VISIT_CHECK_FREE && pack->taken[voxel])
            return false;
          if (what == VISIT_CLAIM)
            pack->taken[voxel] = 1;
          if (what == VISIT_RECORD)
            record (pack, index, voxel, d);
        }
  return true;
}

static bool
add_piece (Pack *pack, const TruthSolid *s, const Piece *piece, double gap)
{
  if (gap >= 0.0 && !visit_voxels (pack, s, piece, 0, VISIT_CHECK_FREE, 0.5 * gap))
    return true; /* not placed, not an error */
  if (pack->count == pack->capacity)
    {
      size_t capacity = pack->capacity ? 2 * pack->capacity : 256;
      Piece *grown = realloc (pack->pieces, capacity * sizeof *grown);
      if (!grown)
        return false;
      pack->pieces = grown;
      pack->capacity = capacity;
    }
  if (gap >= 0.0)
    visit_voxels (pack, s, piece, 0, VISIT_CLAIM, 0.5 * gap);
  pack->pieces[pack->count] = *piece;
  visit_voxels (pack, s, piece, (uint32_t) pack->count, VISIT_RECORD, EDGE_BAND);
  pack->count++;
  return true;
}

/* Beads: separate glass balls of one size in a dark resin. */
static void
draw_bead (const TruthSolid *s, uint32_t stream, uint64_t key, double size, Piece *piece)
{
  static const double glass[3] = { 150, 170, 185 };
  (void) size;
  piece->shape = SHAPE_BALL;
  piece->radius = piece->reach = 5.0;
  tone (piece->colour, glass, 40.0 * (u01 (s, stream, key, 10) - 0.5));
}

/* Balls: overlapping terracotta balls of many sizes (many small, a few
 * large) on a plain pale ground. */
static void
draw_ball (const TruthSolid *s, uint32_t stream, uint64_t key, double size, Piece *piece)
{
  static const double terracotta[3] = { 165, 90, 60 };
  piece->shape = SHAPE_BALL;
  piece->radius = piece->reach = 2.5 + 9.0 * size * size;
  tone (piece->colour, terracotta, 50.0 * (u01 (s, stream, key, 10) - 0.5));
}

/* Droplets: separate amber droplets of many sizes in a slate matrix. */
static void
draw_droplet (const TruthSolid *s, uint32_t stream, uint64_t key, double size, Piece *piece)
{
  static const double amber[3] = { 205, 150, 65 };
  piece->shape = SHAPE_BALL;
  piece->radius = piece->reach = 2.0 + 6.0 * pow (size, 1.5);
  tone (piece->colour, amber, 40.0 * (u01 (s, stream, key, 10) - 0.5));
}

/* Ellipsoids: separate tan grains (three unequal axes) at random
 * orientations in a dark brown matrix. */
static void
draw_ellipsoid (const TruthSolid *s, uint32_t stream, uint64_t key, double size, Piece *piece)
{
  static const double tan_grain[3] = { 205, 180, 130 };
  static const double semi[3] = { 6.5, 3.2, 2.6 };
  double scale = 0.8 + 0.4 * size;
  piece->shape = SHAPE_ELLIPSOID;
  for (int a = 0; a < 3; a++)
    piece->semi[a] = scale * semi[a];
  piece->reach = piece->semi[0];
  random_rotation (s, stream, key, 11, piece->rotation);
  tone (piece->colour, tan_grain, 40.0 * (u01 (s, stream, key, 10) - 0.5));
}

/* Rods: straw fibres of random orientation, crossing one another, in a
 * dark epoxy. */
static void
draw_rod (const TruthSolid *s, uint32_t stream, uint64_t key, double size, Piece *piece)
{
  static const double straw[3] = { 215, 200, 150 };
  piece->shape = SHAPE_ROD;
  piece->radius = 1.6 + 0.4 * u01 (s, stream, key, 11);
  piece->half_length = 7.0 + 7.0 * size;
  piece->reach = piece->half_length + piece->radius;
  random_direction (s, stream, key, 12, piece->axis);
  tone (piece->colour, straw, 40.0 * (u01 (s, stream, key, 10) - 0.5));
}

/* Terrazzo: separate angular chips (random convex polyhedra) of several
 * stones in a grey cement. */
static void
draw_chip (const TruthSolid *s, uint32_t stream, uint64_t key, double size, Piece *piece)
{
  static const double stones[5][3] = {
    { 235, 232, 225 }, { 38, 38, 42 }, { 160, 62, 45 }, { 110, 135, 100 }, { 200, 160, 80 }
  };
  double radius = 3.0 + 6.0 * size;
  int stone = (int) (5.0 * u01 (s, stream, key, 11));
  piece->shape = SHAPE_CHIP;
  piece->reach = radius;
  piece->faces = 8 + (int) (5.0 * u01 (s, stream, key, 12));
  for (int f = 0; f < piece->faces; f++)
    {
      random_direction (s, stream, key, 13 + 3 * f, piece->normal[f]);
      piece->offset[f] = radius * (0.55 + 0.45 * u01 (s, stream, key, 15 + 3 * f));
    }
  tone (piece->colour, stones[stone], 30.0 * (u01 (s, stream, key, 10) - 0.5));
}

static const Kind kinds[] = {
  { "beads", 200, 0.30, 1.5, false, draw_bead, { 40, 34, 40 }, 12.0, 20.0 },
  { "balls", 210, 0.60, -1.0, false, draw_ball, { 228, 218, 198 }, 14.0, 20.0 },
  { "droplets", 220, 0.28, 1.2, true, draw_droplet, { 62, 72, 84 }, 14.0, 20.0 },
  { "ellipsoids", 230, 0.28, 1.0, false, draw_ellipsoid, { 85, 60, 45 }, 16.0, 20.0 },
  { "rods", 240, 0.22, -1.0, false, draw_rod, { 52, 46, 42 }, 12.0, 20.0 },
  { "terrazzo", 250, 0.35, 1.0, false, draw_chip, { 140, 138, 132 }, 26.0, 16.0 },
};

/* Pieces that failed to find room in a row before a kind stops filling. */
#define JAMMED 50

/* A ball's volume. */
static double
piece_volume (const Piece *piece)
{
  return 4.0 / 3.0 * PI * piece->radius * piece->radius * piece->radius;
}

static int
by_radius_descending (const void *a, const void *b)
{
  double ra = ((const Piece *) a)->radius, rb = ((const Piece *) b)->radius;
  return ra < rb ? 1 : ra > rb ? -1 : 0;
}

/* Draws and places the pieces until they fill kind->fill of the cube, or
 * until separate pieces no longer find room. */
static bool
fill (Pack *pack, const TruthSolid *s, const Kind *kind)
{
  double target = kind->fill * (double) s->n * (double) s->n * (double) s->n;
  Piece *queue = NULL;
  size_t queued = 0;
  bool ok = true;

  if (kind->largest_first)
    {
      /* balls only: draw sizes until their volume reaches the aim, then
       * place the largest first, which packs the many sizes closer */
      double volume = 0.0;
      size_t capacity = 0;
      for (uint64_t k = 0; volume < target; k++)
        {
          if (queued == capacity)
            {
              Piece *grown;
              capacity = capacity ? 2 * capacity : 256;
              grown = realloc (queue, capacity * sizeof *grown);
              if (!grown)
                {
                  free (queue);
                  return false;
                }
              queue = grown;
            }
          kind->draw (s, kind->stream, k, u01 (s, kind->stream, k, 9), &queue[queued]);
          volume += piece_volume (&queue[queued++]);
        }
      qsort (queue, queued, sizeof *queue, by_radius_descending);
    }
  for (uint64_t k = 0, failed = 0; ok && (kind->largest_first || failed < JAMMED); k++)
    {
      Piece piece;
      size_t placed = pack->count;
      if (kind->largest_first ? k >= queued : pack->filled >= target)
        break;
      if (kind->largest_first)
        piece = queue[k];
      else
        kind->draw (s, kind->stream, k, u01 (s, kind->stream, k, 9), &piece);
      for (int attempt = 0; ok && attempt < (kind->gap >= 0.0 ? ATTEMPTS_PER_PIECE : 1)
                            && pack->count == placed; attempt++)
        {
          place_centre (s, kind->stream + 1, k * ATTEMPTS_PER_PIECE + (uint64_t) attempt, &piece);
          ok = add_piece (pack, s, &piece, kind->gap);
        }
      failed = pack->count == placed ? failed + 1 : 0;
    }
  free (queue);
  return ok;
}

/* Matrix, pieces and their edges blended over about one voxel, and where
 * two overlapping pieces meet, their colours likewise. */
static void
paint (const Pack *pack, const TruthSolid *s, const Kind *kind, uint8_t *rgb)
{
  size_t n = s->n, fine = truth_lattice_period (s, 2.0);
  for (size_t z = 0; z < n; z++)
    for (size_t y = 0; y < n; y++)
      for (size_t x = 0; x < n; x++)
        {
          size_t v = (z * n + y) * n + x;
          double p[3] = { (double) x, (double) y, (double) z }, colour[3];
          double grain = truth_value_noise (s, kind->stream + 2, fine, p) - 0.5;
          double cover = fmin (1.0, fmax (0.0, 0.5 - pack->near1[v]));
          double first = 1.0;
          const double *a = kind->matrix, *b = kind->matrix;
          if (pack->owner1[v] != NO_PIECE)
            a = b = pack->pieces[pack->owner1[v]].colour;
          if (pack->owner2[v] != NO_PIECE && pack->near2[v] < 0.5)
            {
              b = pack->pieces[pack->owner2[v]].colour;
              first = 0.5 + 0.5 * fmin (1.0, pack->near2[v] - pack->near1[v]);
            }
          for (int c = 0; c < 3; c++)
            {
              double inside = first * a[c] + (1.0 - first) * b[c] + kind->piece_noise * grain;
              double outside = kind->matrix[c] + kind->matrix_noise * grain;
              colour[c] = cover * inside + (1.0 - cover) * outside;
            }
          for (int c = 0; c < 3; c++)
            rgb[3 * v + (size_t) c] = truth_byte (colour[c]);
        }
}

TruthStatus
truth_render_pieces (const char *kind_name, const TruthSolid *s, uint8_t *rgb)
{
  const Kind *kind = NULL;
  size_t voxels = s->n * s->n * s->n;
  Pack pack = { 0 };
  TruthStatus status = TRUTH_OUT_OF_MEMORY;

  for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
    if (!strcmp (kind_name, kinds[k].name))
      kind = &kinds[k];
  if (!kind)
    return TRUTH_UNKNOWN;
  pack.near1 = malloc (voxels * sizeof (float));
  pack.near2 = malloc (voxels * sizeof (float));
  pack.owner1 = malloc (voxels * sizeof (uint32_t));
  pack.owner2 = malloc (voxels * sizeof (uint32_t));
  pack.taken = calloc (voxels, 1);
  if (pack.near1 && pack.near2 && pack.owner1 && pack.owner2 && pack.taken)
    {
      for (size_t v = 0; v < voxels; v++)
        {
          pack.near1[v] = pack.near2[v] = (float) EDGE_BAND;
          pack.owner1[v] = pack.owner2[v] = NO_PIECE;
        }
      if (fill (&pack, s, kind))
        {
          paint (&pack, s, kind, rgb);
          status = TRUTH_DONE;
        }
    }
  free (pack.pieces);
  free (pack.near1);
  free (pack.near2);
  free (pack.owner1);
  free (pack.owner2);
  free (pack.taken);
  return status;
}
