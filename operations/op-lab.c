/* Pixels to CIE Lab and back with fixed arithmetic (see op-lab.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#include "op-lab.h"
#include "lab-arithmetic.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

typedef enum { CURVE_LINEAR, CURVE_SRGB, CURVE_GAMMA } Curve;

typedef struct
{
  const char *components;
  int         n;          /* components per pixel */
  gboolean    grey;
  gboolean    alpha;      /* the last component */
  gboolean    perceptual; /* "~": the sRGB curve whatever the space's */
  gboolean    linear;     /* no curve */
} Layout;

static const Layout layouts[] =
{
  { "R'G'B'",  3, FALSE, FALSE, FALSE, FALSE },
  { "R'G'B'A", 4, FALSE, TRUE,  FALSE, FALSE },
  { "RGB",     3, FALSE, FALSE, FALSE, TRUE  },
  { "RGBA",    4, FALSE, TRUE,  FALSE, TRUE  },
  { "R~G~B~",  3, FALSE, FALSE, TRUE,  FALSE },
  { "R~G~B~A", 4, FALSE, TRUE,  TRUE,  FALSE },
  { "Y'",      1, TRUE,  FALSE, FALSE, FALSE },
  { "Y'A",     2, TRUE,  TRUE,  FALSE, FALSE },
  { "Y",       1, TRUE,  FALSE, FALSE, TRUE  },
  { "YA",      2, TRUE,  TRUE,  FALSE, TRUE  },
  { "Y~",      1, TRUE,  FALSE, TRUE,  FALSE },
  { "Y~A",     2, TRUE,  TRUE,  TRUE,  FALSE },
};

/* A format as read and written here. */
typedef struct
{
  const Layout *layout;
  int           bytes;      /* per component: 1 (u8), 2 (u16) or 4 (float) */
  Curve         curve;
  double        gamma;
  double        rgb_to_xyz[9]; /* D50-adapted, as babl's spaces are */
} Coding;

/* ICC's D50 white, which babl's Lab uses too. */
static const double d50[3] = { 0.9642, 1.0, 0.8249 };

static void
mat_mul (const double *a, const double *b, double *out)
{
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++)
      out[3 * r + c] = a[3 * r] * b[c] + a[3 * r + 1] * b[3 + c] + a[3 * r + 2] * b[6 + c];
}

static void
mat_apply (const double *m, const double *v, double *out)
{
  for (int r = 0; r < 3; r++)
    out[r] = m[3 * r] * v[0] + m[3 * r + 1] * v[1] + m[3 * r + 2] * v[2];
}

static gboolean
mat_invert (const double *m, double *out)
{
  double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
               + m[2] * (m[3] * m[7] - m[4] * m[6]);

  if (fabs (det) < 1e-12)
    return FALSE;
  out[0] = (m[4] * m[8] - m[5] * m[7]) / det;
  out[1] = (m[2] * m[7] - m[1] * m[8]) / det;
  out[2] = (m[1] * m[5] - m[2] * m[4]) / det;
  out[3] = (m[5] * m[6] - m[3] * m[8]) / det;
  out[4] = (m[0] * m[8] - m[2] * m[6]) / det;
  out[5] = (m[2] * m[3] - m[0] * m[5]) / det;
  out[6] = (m[3] * m[7] - m[4] * m[6]) / det;
  out[7] = (m[1] * m[6] - m[0] * m[7]) / det;
  out[8] = (m[0] * m[4] - m[1] * m[3]) / det;
  return TRUE;
}

/* The RGB to XYZ matrix of the primaries and white point, adapted to D50
 * with the Bradford transform. */
static gboolean
space_matrix (const Babl *space, double *out)
{
  static const double bradford[9] = { 0.8951, 0.2664, -0.1614,
                                      -0.7502, 1.7135, 0.0367,
                                      0.0389, -0.0685, 1.0296 };
  double xw, yw, xy[6], primaries[9], inverse[9], white[3], scale[3];
  double bradford_inv[9], cone_src[3], cone_dst[3], adapt[9], tmp[9], diag[9] = { 0 };

  babl_space_get (space, &xw, &yw, &xy[0], &xy[1], &xy[2], &xy[3], &xy[4], &xy[5],
                  NULL, NULL, NULL);
  if (yw <= 0.0 || xy[1] <= 0.0 || xy[3] <= 0.0 || xy[5] <= 0.0)
    return FALSE;
  for (int c = 0; c < 3; c++)
    {
      double x = xy[2 * c], y = xy[2 * c + 1];

      primaries[c] = x / y;
      primaries[3 + c] = 1.0;
      primaries[6 + c] = (1.0 - x - y) / y;
    }
  white[0] = xw / yw;
  white[1] = 1.0;
  white[2] = (1.0 - xw - yw) / yw;
  if (!mat_invert (primaries, inverse) || !mat_invert (bradford, bradford_inv))
    return FALSE;
  mat_apply (inverse, white, scale);
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++)
      primaries[3 * r + c] *= scale[c];

  mat_apply (bradford, white, cone_src);
  mat_apply (bradford, d50, cone_dst);
  for (int i = 0; i < 3; i++)
    diag[4 * i] = cone_dst[i] / cone_src[i];
  mat_mul (bradford_inv, diag, tmp);
  mat_mul (tmp, bradford, adapt);
  mat_mul (adapt, primaries, out);
  return TRUE;
}

/* How to read and write `format` here; FALSE if babl must do it. */
static gboolean
coding_for (const Babl *format, Coding *coding)
{
  const char *encoding = babl_format_get_encoding (format);
  const char *type = encoding ? strrchr (encoding, ' ') : NULL;
  const Babl *space = babl_format_get_space (format);
  const Babl *red, *green, *blue;
  size_t length;

  if (!type || !space || babl_space_is_cmyk (space) || babl_space_is_gray (space))
    return FALSE;
  length = (size_t) (type - encoding);
  type++;
  coding->layout = NULL;
  for (size_t i = 0; i < G_N_ELEMENTS (layouts); i++)
    if (strlen (layouts[i].components) == length &&
        strncmp (layouts[i].components, encoding, length) == 0)
      coding->layout = &layouts[i];
  if (!coding->layout)
    return FALSE;
  if (strcmp (type, "u8") == 0)
    coding->bytes = 1;
  else if (strcmp (type, "u16") == 0)
    coding->bytes = 2;
  else if (strcmp (type, "float") == 0)
    coding->bytes = 4;
  else
    return FALSE;
  if (babl_format_get_bytes_per_pixel (format) != coding->layout->n * coding->bytes)
    return FALSE;

  babl_space_get (space, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, &red, &green, &blue);
  green = green ? green : red;
  blue = blue ? blue : red;
  coding->gamma = 1.0;
  if (coding->layout->linear)
    coding->curve = CURVE_LINEAR;
  else if (coding->layout->perceptual)
    coding->curve = CURVE_SRGB;
  else if (red != green || red != blue)
    return FALSE;
  else if (red == babl_trc ("sRGB"))
    coding->curve = CURVE_SRGB;
  else if (red == babl_trc ("linear"))
    coding->curve = CURVE_LINEAR;
  else if ((coding->gamma = babl_space_get_gamma (space)) > 0.0)
    coding->curve = CURVE_GAMMA;
  else
    return FALSE;
  return space_matrix (space, coding->rgb_to_xyz);
}

static double
to_linear (const Coding *coding, double v)
{
  double a = fabs (v), linear;

  switch (coding->curve)
    {
    case CURVE_SRGB:
      linear = ts_srgb_to_linear (a);
      break;
    case CURVE_GAMMA:
      linear = pow (a, coding->gamma);
      break;
    default:
      return v;
    }
  return v < 0.0 ? -linear : linear;
}

/* Component `c` of the pixel at `p`, as stored. */
static double
component (const Coding *coding, const guchar *p, int c)
{
  switch (coding->bytes)
    {
    case 1:
      return p[c] / 255.0;
    case 2:
      {
        uint16_t v;
        memcpy (&v, p + 2 * c, sizeof v);
        return v / 65535.0;
      }
    default:
      {
        float v;
        memcpy (&v, p + 4 * c, sizeof v);
        return v;
      }
    }
}

static void
decode (const Coding *coding, const guchar *raw, size_t n, float *lab)
{
  const Layout *layout = coding->layout;
  size_t stride = (size_t) layout->n * (size_t) coding->bytes;

  for (size_t i = 0; i < n; i++, raw += stride, lab += 4)
    {
      double rgb[3], xyz[3];

      for (int c = 0; c < 3; c++)
        rgb[c] = to_linear (coding, component (coding, raw, layout->grey ? 0 : c));
      mat_apply (coding->rgb_to_xyz, rgb, xyz);
      ts_xyz_to_lab (xyz, d50, lab);
      lab[3] = layout->alpha ? (float) component (coding, raw, layout->n - 1) : 1.0f;
    }
}

static double
from_linear (const Coding *coding, double v)
{
  double a = fabs (v), encoded;

  switch (coding->curve)
    {
    case CURVE_SRGB:
      encoded = ts_linear_to_srgb (a);
      break;
    case CURVE_GAMMA:
      encoded = pow (a, 1.0 / coding->gamma);
      break;
    default:
      return v;
    }
  return v < 0.0 ? -encoded : encoded;
}

/* Integers as babl stores them: clamped to 0..1, rounded half up; NaN is 0. */
static void
store (const Coding *coding, guchar *p, int c, double v)
{
  double clamped = v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;

  switch (coding->bytes)
    {
    case 1:
      p[c] = (guchar) (clamped * 255.0 + 0.5);
      break;
    case 2:
      {
        uint16_t u = (uint16_t) (clamped * 65535.0 + 0.5);
        memcpy (p + 2 * c, &u, sizeof u);
      }
      break;
    default:
      {
        float f = (float) v;
        memcpy (p + 4 * c, &f, sizeof f);
      }
    }
}

static void
encode (const Coding *coding, const double *xyz_to_rgb, const float *lab, size_t n, guchar *raw)
{
  const Layout *layout = coding->layout;
  size_t stride = (size_t) layout->n * (size_t) coding->bytes;

  for (size_t i = 0; i < n; i++, raw += stride, lab += 4)
    {
      double rgb[3], xyz[3];

      ts_lab_to_xyz (lab, d50, xyz);
      if (layout->grey)
        /* rgb_to_xyz's Y row sums to 1: grey's linear value is Y. */
        store (coding, raw, 0, from_linear (coding, xyz[1]));
      else
        {
          mat_apply (xyz_to_rgb, xyz, rgb);
          for (int c = 0; c < 3; c++)
            store (coding, raw, c, from_linear (coding, rgb[c]));
        }
      if (layout->alpha)
        store (coding, raw, layout->n - 1, lab[3]);
    }
}

/* How to write `format` here, with its XYZ-to-RGB matrix; FALSE if babl
 * must do it. */
static gboolean
encoding_for (const Babl *format, Coding *coding, double xyz_to_rgb[9])
{
  return coding_for (format, coding) && mat_invert (coding->rgb_to_xyz, xyz_to_rgb);
}

void
ts_op_lab_to_format (const float *lab, const Babl *format, void *out, size_t n)
{
  Coding coding;
  double xyz_to_rgb[9];

  if (encoding_for (format, &coding, xyz_to_rgb))
    encode (&coding, xyz_to_rgb, lab, n, out);
  else
    babl_process (babl_fish (babl_format (TS_OP_FORMAT), format), lab, out, (long) n);
}

void
ts_op_write_lab (GeglBuffer *buffer, const GeglRectangle *rect, const float *lab, size_t stride)
{
  const Babl *format = gegl_buffer_get_format (buffer);
  size_t bpp = (size_t) babl_format_get_bytes_per_pixel (format);
  size_t width = (size_t) rect->width, height = (size_t) rect->height;
  guchar *raw = g_try_malloc (width * height * bpp);

  if (!raw)
    {
      /* Short of memory: babl converts on the way in instead. */
      gegl_buffer_set (buffer, rect, 0, babl_format (TS_OP_FORMAT), lab, (gint) stride);
      return;
    }
  Coding coding;
  double xyz_to_rgb[9];
  /* Our own coding converts the rows on all threads, where a large
   * result's conversion would be a serial tail after a parallel synthesis
   * (4096x4096, 2 threads: 0.79 -> 0.46 s); babl's fish keeps to one. */
  gboolean own = encoding_for (format, &coding, xyz_to_rgb);
  const Babl *fish = own ? NULL : babl_fish (babl_format (TS_OP_FORMAT), format);
#pragma omp parallel for schedule(static) if (own && width * height >= 65536)
  for (size_t y = 0; y < height; y++)
    {
      const float *row = (const float *) ((const guchar *) lab + y * stride);
      if (own)
        encode (&coding, xyz_to_rgb, row, width, raw + y * width * bpp);
      else
        babl_process (fish, row, raw + y * width * bpp, (long) width);
    }
  gegl_buffer_set (buffer, rect, 0, format, raw, GEGL_AUTO_ROWSTRIDE);
  g_free (raw);
}

void
ts_op_read_lab (GeglBuffer *buffer, const GeglRectangle *rect, float *lab)
{
  const Babl *format = gegl_buffer_get_format (buffer);
  size_t n = (size_t) rect->width * (size_t) rect->height;
  Coding coding;
  guchar *raw = NULL;

  /* The buffer's own format: a plain copy, no babl path involved. */
  if (coding_for (format, &coding) &&
      (raw = g_try_malloc (n * (size_t) babl_format_get_bytes_per_pixel (format))))
    {
      gegl_buffer_get (buffer, rect, 1.0, format, raw, GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
      decode (&coding, raw, n, lab);
      g_free (raw);
      return;
    }
  gegl_buffer_get (buffer, rect, 1.0, babl_format (TS_OP_FORMAT), lab,
                   GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
}
