/* Exemplar pixels to CIE Lab with fixed arithmetic (see op-lab.h).
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

typedef struct
{
  const Layout *layout;
  int           bytes;      /* per component: 1 (u8), 2 (u16) or 4 (float) */
  Curve         curve;
  double        gamma;
  double        rgb_to_xyz[9]; /* D50-adapted, as babl's spaces are */
} Decoder;

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

/* How to decode `format` here; FALSE if babl must do it. */
static gboolean
decoder_for (const Babl *format, Decoder *decoder)
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
  decoder->layout = NULL;
  for (size_t i = 0; i < G_N_ELEMENTS (layouts); i++)
    if (strlen (layouts[i].components) == length &&
        strncmp (layouts[i].components, encoding, length) == 0)
      decoder->layout = &layouts[i];
  if (!decoder->layout)
    return FALSE;
  if (strcmp (type, "u8") == 0)
    decoder->bytes = 1;
  else if (strcmp (type, "u16") == 0)
    decoder->bytes = 2;
  else if (strcmp (type, "float") == 0)
    decoder->bytes = 4;
  else
    return FALSE;
  if (babl_format_get_bytes_per_pixel (format) != decoder->layout->n * decoder->bytes)
    return FALSE;

  babl_space_get (space, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, &red, &green, &blue);
  green = green ? green : red;
  blue = blue ? blue : red;
  decoder->gamma = 1.0;
  if (decoder->layout->linear)
    decoder->curve = CURVE_LINEAR;
  else if (decoder->layout->perceptual)
    decoder->curve = CURVE_SRGB;
  else if (red != green || red != blue)
    return FALSE;
  else if (red == babl_trc ("sRGB"))
    decoder->curve = CURVE_SRGB;
  else if (red == babl_trc ("linear"))
    decoder->curve = CURVE_LINEAR;
  else if ((decoder->gamma = babl_space_get_gamma (space)) > 0.0)
    decoder->curve = CURVE_GAMMA;
  else
    return FALSE;
  return space_matrix (space, decoder->rgb_to_xyz);
}

static double
to_linear (const Decoder *decoder, double v)
{
  double a = fabs (v), linear;

  switch (decoder->curve)
    {
    case CURVE_SRGB:
      linear = ts_srgb_to_linear (a);
      break;
    case CURVE_GAMMA:
      linear = pow (a, decoder->gamma);
      break;
    default:
      return v;
    }
  return v < 0.0 ? -linear : linear;
}

/* Component `c` of the pixel at `p`, as stored. */
static double
component (const Decoder *decoder, const guchar *p, int c)
{
  switch (decoder->bytes)
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
decode (const Decoder *decoder, const guchar *raw, size_t n, float *lab)
{
  const Layout *layout = decoder->layout;
  size_t stride = (size_t) layout->n * (size_t) decoder->bytes;

  for (size_t i = 0; i < n; i++, raw += stride, lab += 4)
    {
      double rgb[3], xyz[3];

      for (int c = 0; c < 3; c++)
        rgb[c] = to_linear (decoder, component (decoder, raw, layout->grey ? 0 : c));
      mat_apply (decoder->rgb_to_xyz, rgb, xyz);
      ts_xyz_to_lab (xyz, d50, lab);
      lab[3] = layout->alpha ? (float) component (decoder, raw, layout->n - 1) : 1.0f;
    }
}

void
ts_op_read_lab (GeglBuffer *buffer, const GeglRectangle *rect, float *lab)
{
  const Babl *format = gegl_buffer_get_format (buffer);
  size_t n = (size_t) rect->width * (size_t) rect->height;
  Decoder decoder;
  guchar *raw = NULL;

  /* The buffer's own format: a plain copy, no babl path involved. */
  if (decoder_for (format, &decoder) &&
      (raw = g_try_malloc (n * (size_t) babl_format_get_bytes_per_pixel (format))))
    {
      gegl_buffer_get (buffer, rect, 1.0, format, raw, GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
      decode (&decoder, raw, n, lab);
      g_free (raw);
      return;
    }
  gegl_buffer_get (buffer, rect, 1.0, babl_format (TS_OP_FORMAT), lab,
                   GEGL_AUTO_ROWSTRIDE, GEGL_ABYSS_NONE);
}
