/* Solid-texture files: the .vol format of Kopf et al. 2007's viewers and
 * uncompressed DDS volume textures, 8 bits per channel.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Plain C11, no GEGL types. Writers are atomic: the file appears complete
 * under its name or not at all, and an older file there survives any
 * failure. Readers check every header field against the file's length
 * before allocating, so malformed or hostile files only give a message.
 */
#ifndef TS_VOLUME_FILE_H
#define TS_VOLUME_FILE_H

#include "texsynth.h"

/* Largest cube edge either reader accepts (the header fields allow more). */
#define TS_VOLUME_MAX_SIZE 4096

/* .vol layout (all integers little-endian int32). */
#define TS_VOL_HEADER_SIZE 4096
#define TS_VOL_VERSION 4
#define TS_VOL_NAME_SIZE 256
#define TS_VOL_OFFSET_MAGIC 0
#define TS_VOL_OFFSET_VERSION 4
#define TS_VOL_OFFSET_NAME 8
#define TS_VOL_OFFSET_WRAP 264
#define TS_VOL_OFFSET_SIZE 268
#define TS_VOL_OFFSET_CHANNELS 272
#define TS_VOL_OFFSET_BYTES_PER_CHANNEL 276

/* DDS layout: "DDS " magic, DDS_HEADER, DDS_HEADER_DXT10, voxels. */
#define TS_DDS_HEADER_SIZE 124
#define TS_DDS_DX10_HEADER_SIZE 20
#define TS_DDS_DATA_OFFSET (4 + TS_DDS_HEADER_SIZE + TS_DDS_DX10_HEADER_SIZE)
#define TS_DDS_LEGACY_DATA_OFFSET (4 + TS_DDS_HEADER_SIZE)
#define TS_DXGI_FORMAT_R8G8B8A8_UNORM 28
#define TS_DXGI_FORMAT_R16G16B16A16_UINT 12
#define TS_DDS_DIMENSION_TEXTURE3D 4

typedef struct
{
  size_t   size;      /* edge of the cube in voxels */
  unsigned channels;  /* 1..4 (.vol); .dds is always 4 (RGBA8) */
  bool     wrap;      /* the volume is periodic (.vol header flag) */
  uint8_t *voxels;    /* size^3 * channels bytes, x fastest, then y, then z */
} TsVolume8;

typedef enum
{
  TS_VOLUME_FORMAT_VOL,
  TS_VOLUME_FORMAT_DDS
} TsVolumeFormat;

/* Write `v` as a .vol file; `name` (may be NULL) goes into the header's
 * name field, cut to 255 bytes. */
TsStatus ts_volume_write_vol (const char      *path,
                              const char      *name,
                              const TsVolume8 *v,
                              TsError         *error);

/* Write `v` as an RGBA8 DX10 DDS volume texture. 1 channel is written as
 * opaque grey, 2 as grey and alpha, 3 as opaque RGB. */
TsStatus ts_volume_write_dds (const char      *path,
                              const TsVolume8 *v,
                              TsError         *error);

/* Write a solid texture's sources as a DX10 DDS volume texture of
 * R16G16B16A16_UINT voxels (148-byte header, then x fastest, 8 bytes per
 * voxel, little-endian): `voxels` holds size^3 * 4 values, per voxel the
 * exemplar pixel's x and y, the orientation (0, 1, 2: the exemplar of the
 * slices across x, y, z) and 65535. Not readable by ts_volume_read. */
TsStatus ts_volume_write_dds_sources (const char     *path,
                                      size_t          size,
                                      const uint16_t *voxels,
                                      TsError        *error);

/* Read a .vol or .dds volume, recognised by its magic bytes. `max_bytes`
 * caps the voxel memory (0: no cap beyond TS_VOLUME_MAX_SIZE). Allocates
 * v->voxels with malloc (free with ts_volume8_clear); on failure `v` is
 * zeroed and nothing stays allocated. `format` may be NULL. */
TsStatus ts_volume_read (const char     *path,
                         size_t          max_bytes,
                         TsVolume8      *v,
                         TsVolumeFormat *format,
                         TsError        *error);

/* Free the voxels and zero `v`. */
void ts_volume8_clear (TsVolume8 *v);

/* size^3 * channels in bytes; false if it overflows size_t. */
bool ts_volume_bytes (size_t size, size_t channels, size_t *bytes);

#endif /* TS_VOLUME_FILE_H */
