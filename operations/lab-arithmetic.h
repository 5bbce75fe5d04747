/* The CIE Lab arithmetic shared by op-lab.c and the benchmarks' truth
 * solids: the sRGB curve and XYZ to Lab, both ways. Plain C, no GEGL
 * types.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 */
#ifndef TEXSYNTH_LAB_ARITHMETIC_H
#define TEXSYNTH_LAB_ARITHMETIC_H

#include <math.h>

/* An sRGB-encoded value (0 to 1, or more) to linear light. */
static inline double
ts_srgb_to_linear (double v)
{
  return v <= 0.04045 ? v / 12.92 : pow ((v + 0.055) / 1.055, 2.4);
}

/* A linear-light value to the sRGB encoding: ts_srgb_to_linear's inverse. */
static inline double
ts_linear_to_srgb (double v)
{
  return v <= 0.0031308 ? v * 12.92 : 1.055 * pow (v, 1.0 / 2.4) - 0.055;
}

/* CIE's f(t) of the Lab definition. */
static inline double
ts_lab_f (double t)
{
  const double epsilon = 216.0 / 24389.0, kappa = 24389.0 / 27.0;

  return t > epsilon ? cbrt (t) : (kappa * t + 16.0) / 116.0;
}

/* XYZ to L, a, b relative to the white point `white` (XYZ, Y = 1). */
static inline void
ts_xyz_to_lab (const double xyz[3], const double white[3], float lab[3])
{
  double fx = ts_lab_f (xyz[0] / white[0]);
  double fy = ts_lab_f (xyz[1] / white[1]);
  double fz = ts_lab_f (xyz[2] / white[2]);

  lab[0] = (float) (116.0 * fy - 16.0);
  lab[1] = (float) (500.0 * (fx - fy));
  lab[2] = (float) (200.0 * (fy - fz));
}

/* f's inverse: t from f(t), with the same threshold, so that the two
 * meet at the seam. */
static inline double
ts_lab_f_inverse (double f)
{
  const double kappa = 24389.0 / 27.0;

  return f > 6.0 / 29.0 ? f * f * f : (116.0 * f - 16.0) / kappa;
}

/* L, a, b relative to the white point `white` back to XYZ. */
static inline void
ts_lab_to_xyz (const float lab[3], const double white[3], double xyz[3])
{
  double fy = ((double) lab[0] + 16.0) / 116.0;

  xyz[0] = white[0] * ts_lab_f_inverse (fy + (double) lab[1] / 500.0);
  xyz[1] = white[1] * ts_lab_f_inverse (fy);
  xyz[2] = white[2] * ts_lab_f_inverse (fy - (double) lab[2] / 200.0);
}

#endif /* TEXSYNTH_LAB_ARITHMETIC_H */
