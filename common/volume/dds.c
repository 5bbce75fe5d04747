/* Uncompressed DDS volume textures, 8 bits per channel (and solid
 * texture sources as R16G16B16A16_UINT, written only).
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Written as "DDS ", a DDS_HEADER (124 bytes) and a DDS_HEADER_DXT10
 * (20 bytes) declaring DXGI_FORMAT_R8G8B8A8_UNORM and a 3D resource, then
 * the slices (z), their rows (y), x fastest: 148 bytes before the voxels.
 * Read as well: the same with the B8G8R8A8/X8 DXGI formats, and legacy
 * headers without the DX10 extension whose pixel format is 32-bit RGB(A)
 * with byte-aligned masks. Anything else (block compression, other
 * formats, cube maps, arrays, 2D textures, non-cubic volumes) is refused
 * with a message saying what the file is. Mipmaps beyond level 0 are
 * ignored.
 */
#include "formats.h"

#include "atomic-file.h"
#include "engine/error.h"
#include "engine/i18n.h"

#include <stdlib.h>
#include <string.h>

/* Offsets from the start of the file. */
enum
{
  DDS_SIZE = 4,
  DDS_FLAGS = 8,
  DDS_HEIGHT = 12,
  DDS_WIDTH = 16,
  DDS_PITCH = 20,
  DDS_DEPTH = 24,
  DDS_MIPMAP_COUNT = 28,
  DDS_PF_SIZE = 76,
  DDS_PF_FLAGS = 80,
  DDS_PF_FOURCC = 84,
  DDS_PF_BIT_COUNT = 88,
  DDS_PF_R_MASK = 92,
  DDS_PF_G_MASK = 96,
  DDS_PF_B_MASK = 100,
  DDS_PF_A_MASK = 104,
  DDS_CAPS = 108,
  DDS_CAPS2 = 112,
  DX10_FORMAT = 128,
  DX10_DIMENSION = 132,
  DX10_MISC_FLAG = 136,
  DX10_ARRAY_SIZE = 140,
  DX10_MISC_FLAGS2 = 144
};

#define DDSD_CAPS 0x1u
#define DDSD_HEIGHT 0x2u
#define DDSD_WIDTH 0x4u
#define DDSD_PITCH 0x8u
#define DDSD_PIXELFORMAT 0x1000u
#define DDSD_DEPTH 0x800000u
#define DDPF_ALPHAPIXELS 0x1u
#define DDPF_FOURCC 0x4u
#define DDPF_RGB 0x40u
#define DDSCAPS_COMPLEX 0x8u
#define DDSCAPS_TEXTURE 0x1000u
#define DDSCAPS2_CUBEMAP 0x200u
#define DDSCAPS2_VOLUME 0x200000u
#define DDS_RESOURCE_MISC_TEXTURECUBE 0x4u
#define DXGI_FORMAT_R8G8B8A8_UNORM_SRGB 29
#define DXGI_FORMAT_B8G8R8A8_UNORM 87
#define DXGI_FORMAT_B8G8R8X8_UNORM 88
#define DXGI_FORMAT_B8G8R8A8_UNORM_SRGB 91
#define DXGI_FORMAT_B8G8R8X8_UNORM_SRGB 93

/* Where R, G, B and A sit in a stored 4-byte voxel; -1: opaque. */
typedef struct
{
  int byte[4];
} ChannelOrder;

static void
fill_header (uint8_t header[TS_DDS_DATA_OFFSET], uint32_t size, uint32_t dxgi_format,
             uint32_t voxel_bytes)
{
  memset (header, 0, TS_DDS_DATA_OFFSET);
  memcpy (header, "DDS ", 4);
  ts_put_le32 (header + DDS_SIZE, TS_DDS_HEADER_SIZE);
  ts_put_le32 (header + DDS_FLAGS, DDSD_CAPS | DDSD_HEIGHT | DDSD_WIDTH | DDSD_PITCH
                                   | DDSD_PIXELFORMAT | DDSD_DEPTH);
  ts_put_le32 (header + DDS_HEIGHT, size);
  ts_put_le32 (header + DDS_WIDTH, size);
  ts_put_le32 (header + DDS_PITCH, size * voxel_bytes);
  ts_put_le32 (header + DDS_DEPTH, size);
  ts_put_le32 (header + DDS_MIPMAP_COUNT, 1);
  ts_put_le32 (header + DDS_PF_SIZE, 32);
  ts_put_le32 (header + DDS_PF_FLAGS, DDPF_FOURCC);
  memcpy (header + DDS_PF_FOURCC, "DX10", 4);
  ts_put_le32 (header + DDS_CAPS, DDSCAPS_COMPLEX | DDSCAPS_TEXTURE);
  ts_put_le32 (header + DDS_CAPS2, DDSCAPS2_VOLUME);
  ts_put_le32 (header + DX10_FORMAT, dxgi_format);
  ts_put_le32 (header + DX10_DIMENSION, TS_DDS_DIMENSION_TEXTURE3D);
  ts_put_le32 (header + DX10_MISC_FLAG, 0);
  ts_put_le32 (header + DX10_ARRAY_SIZE, 1);
  ts_put_le32 (header + DX10_MISC_FLAGS2, 0);
}

/* One row of `channels`-channel voxels as RGBA. */
static void
expand_row (const uint8_t *in, unsigned channels, size_t count, uint8_t *out)
{
  for (size_t i = 0; i < count; i++, in += channels, out += 4)
    switch (channels)
      {
      case 1: out[0] = out[1] = out[2] = in[0]; out[3] = 255; break;
      case 2: out[0] = out[1] = out[2] = in[0]; out[3] = in[1]; break;
      default: out[0] = in[0]; out[1] = in[1]; out[2] = in[2]; out[3] = 255; break;
      }
}

TsStatus
ts_volume_write_dds (const char *path, const TsVolume8 *v, TsError *error)
{
  uint8_t header[TS_DDS_DATA_OFFSET];
  TsAtomicFile f;
  uint8_t *row = NULL;
  size_t bytes = 0;
  TsStatus status;

  status = ts_volume_check_writable (v, error);
  if (status != TS_OK)
    return status;
  ts_volume_bytes (v->size, v->channels, &bytes);
  if (v->channels != 4)
    {
      row = malloc (v->size * 4);
      if (!row)
        return ts_fail (error, TS_ERROR_OUT_OF_MEMORY, "out of memory writing '%s'", path);
    }
  fill_header (header, (uint32_t) v->size, TS_DXGI_FORMAT_R8G8B8A8_UNORM, 4);

  status = ts_atomic_open (&f, path, error);
  if (status == TS_OK)
    status = ts_atomic_write (&f, header, sizeof header, error);
  if (status == TS_OK && !row)
    status = ts_atomic_write (&f, v->voxels, bytes, error);
  for (size_t r = 0; status == TS_OK && row && r < v->size * v->size; r++)
    {
      expand_row (v->voxels + r * v->size * v->channels, v->channels, v->size, row);
      status = ts_atomic_write (&f, row, v->size * 4, error);
    }
  free (row);
  if (status == TS_OK)
    return ts_atomic_commit (&f, error);
  if (f.temp_path)
    ts_atomic_abort (&f);
  return status;
}

TsStatus
ts_volume_write_dds_sources (const char *path, size_t size, const uint16_t *voxels,
                             TsError *error)
{
  uint8_t header[TS_DDS_DATA_OFFSET];
  TsVolume8 as_bytes = { size, 4, false, (uint8_t *) voxels }; /* for the checks only */
  TsAtomicFile f;
  uint8_t *row;
  TsStatus status = ts_volume_check_writable (&as_bytes, error);

  if (status != TS_OK)
    return status;
  row = malloc (size * 8);
  if (!row)
    return ts_fail (error, TS_ERROR_OUT_OF_MEMORY, "out of memory writing '%s'", path);
  fill_header (header, (uint32_t) size, TS_DXGI_FORMAT_R16G16B16A16_UINT, 8);
  status = ts_atomic_open (&f, path, error);
  if (status == TS_OK)
    status = ts_atomic_write (&f, header, sizeof header, error);
  for (size_t r = 0; status == TS_OK && r < size * size; r++)
    {
      /* Little-endian whatever the host. */
      for (size_t i = 0; i < size * 4; i++)
        {
          uint16_t value = voxels[r * size * 4 + i];
          row[2 * i] = (uint8_t) value;
          row[2 * i + 1] = (uint8_t) (value >> 8);
        }
      status = ts_atomic_write (&f, row, size * 8, error);
    }
  free (row);
  if (status == TS_OK)
    return ts_atomic_commit (&f, error);
  if (f.temp_path)
    ts_atomic_abort (&f);
  return status;
}

/* --- reading ------------------------------------------------------------ */

static TsStatus
dx10_order (const char *path, uint32_t format, ChannelOrder *order, TsError *error)
{
  switch (format)
    {
    case TS_DXGI_FORMAT_R8G8B8A8_UNORM:
    case DXGI_FORMAT_R8G8B8A8_UNORM_SRGB:
      *order = (ChannelOrder) { { 0, 1, 2, 3 } };
      return TS_OK;
    case DXGI_FORMAT_B8G8R8A8_UNORM:
    case DXGI_FORMAT_B8G8R8A8_UNORM_SRGB:
      *order = (ChannelOrder) { { 2, 1, 0, 3 } };
      return TS_OK;
    case DXGI_FORMAT_B8G8R8X8_UNORM:
    case DXGI_FORMAT_B8G8R8X8_UNORM_SRGB:
      *order = (ChannelOrder) { { 2, 1, 0, -1 } };
      return TS_OK;
    default:
      return ts_fail (error, TS_ERROR_BAD_FILE,
                      "'%s' uses DXGI format %lu; only uncompressed 8-bit RGBA or BGRA "
                      "DDS volumes (e.g. format 28, R8G8B8A8_UNORM) are supported",
                      path, (unsigned long) format);
    }
}

static int
mask_byte (uint32_t mask)
{
  for (int b = 0; b < 4; b++)
    if (mask == 0xffu << (8 * b))
      return b;
  return -1;
}

static TsStatus
legacy_order (const char *path, const uint8_t *header, ChannelOrder *order, TsError *error)
{
  uint32_t flags = ts_get_le32 (header + DDS_PF_FLAGS);
  uint32_t alpha_mask = ts_get_le32 (header + DDS_PF_A_MASK);
  bool ok = (flags & DDPF_RGB) && ts_get_le32 (header + DDS_PF_BIT_COUNT) == 32;

  order->byte[0] = mask_byte (ts_get_le32 (header + DDS_PF_R_MASK));
  order->byte[1] = mask_byte (ts_get_le32 (header + DDS_PF_G_MASK));
  order->byte[2] = mask_byte (ts_get_le32 (header + DDS_PF_B_MASK));
  order->byte[3] = (flags & DDPF_ALPHAPIXELS) && alpha_mask ? mask_byte (alpha_mask) : -1;
  ok = ok && order->byte[0] >= 0 && order->byte[1] >= 0 && order->byte[2] >= 0
       && (order->byte[3] >= 0 || !((flags & DDPF_ALPHAPIXELS) && alpha_mask));
  /* No two channels may share a byte. */
  for (int i = 0; ok && i < 4; i++)
    for (int j = i + 1; j < 4; j++)
      if (order->byte[i] >= 0 && order->byte[i] == order->byte[j])
        ok = false;
  if (!ok)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' has a pixel format other than uncompressed 32-bit RGBA or BGRA "
                    "(%lu bits, flags 0x%lx); only those DDS volumes are supported",
                    path, (unsigned long) ts_get_le32 (header + DDS_PF_BIT_COUNT),
                    (unsigned long) flags);
  return TS_OK;
}

/* The four characters of a FourCC, printable or as '?'. */
static void
fourcc_text (const uint8_t *p, char text[5])
{
  for (int i = 0; i < 4; i++)
    text[i] = p[i] >= 32 && p[i] < 127 ? (char) p[i] : '?';
  text[4] = '\0';
}

/* Checks the header fields that say what kind of texture the file holds,
 * and finds its channel order and where its voxels start. */
static TsStatus
parse_header (TsInputFile *f, const uint8_t *header, ChannelOrder *order,
              size_t *data_offset, TsError *error)
{
  uint32_t pf_flags = ts_get_le32 (header + DDS_PF_FLAGS);
  uint32_t caps2 = ts_get_le32 (header + DDS_CAPS2);
  uint32_t depth = ts_get_le32 (header + DDS_DEPTH);
  TsStatus status;

  if (ts_get_le32 (header + DDS_SIZE) != TS_DDS_HEADER_SIZE)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is malformed: its DDS header size is %lu, not %d", f->path,
                    (unsigned long) ts_get_le32 (header + DDS_SIZE), TS_DDS_HEADER_SIZE);
  if (caps2 & DDSCAPS2_CUBEMAP)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is a DDS cube map, not a volume texture", f->path);

  if ((pf_flags & DDPF_FOURCC) && memcmp (header + DDS_PF_FOURCC, "DX10", 4) == 0)
    {
      uint32_t dimension = ts_get_le32 (header + DX10_DIMENSION);
      uint32_t array_size = ts_get_le32 (header + DX10_ARRAY_SIZE);

      if (f->length < TS_DDS_DATA_OFFSET)
        return ts_fail (error, TS_ERROR_BAD_FILE,
                        "'%s' is truncated: its DX10 DDS header needs %d bytes, the file "
                        "has %llu", f->path, TS_DDS_DATA_OFFSET,
                        (unsigned long long) f->length);
      if (dimension != TS_DDS_DIMENSION_TEXTURE3D)
        return ts_fail (error, TS_ERROR_BAD_FILE,
                        /* TRANSLATORS: the second %s is "1D", "2D" or the
                         * translation of "malformed", describing the texture. */
                        "'%s' is a %s DDS texture, not a volume (3D) texture", f->path,
                        dimension == 2 ? "1D" : dimension == 3 ? "2D" : TS_ ("malformed"));
      if (ts_get_le32 (header + DX10_MISC_FLAG) & DDS_RESOURCE_MISC_TEXTURECUBE)
        return ts_fail (error, TS_ERROR_BAD_FILE,
                        "'%s' is a DDS cube map, not a volume texture", f->path);
      if (array_size != 1)
        return ts_fail (error, TS_ERROR_BAD_FILE,
                        "'%s' is a DDS texture array of %lu; only single volumes are supported",
                        f->path, (unsigned long) array_size);
      status = dx10_order (f->path, ts_get_le32 (header + DX10_FORMAT), order, error);
      *data_offset = TS_DDS_DATA_OFFSET;
    }
  else if (pf_flags & DDPF_FOURCC)
    {
      char text[5];
      fourcc_text (header + DDS_PF_FOURCC, text);
      return ts_fail (error, TS_ERROR_BAD_FILE,
                      "'%s' is a compressed or special-format DDS texture (FourCC '%s'); "
                      "only uncompressed 8-bit RGBA or BGRA volumes are supported",
                      f->path, text);
    }
  else
    {
      if (!(caps2 & DDSCAPS2_VOLUME) && !(ts_get_le32 (header + DDS_FLAGS) & DDSD_DEPTH))
        return ts_fail (error, TS_ERROR_BAD_FILE,
                        "'%s' is a 2D DDS texture, not a volume texture", f->path);
      status = legacy_order (f->path, header, order, error);
      *data_offset = TS_DDS_LEGACY_DATA_OFFSET;
    }
  if (status != TS_OK)
    return status;

  if (depth == 0)
    return ts_fail (error, TS_ERROR_BAD_FILE, "'%s' is malformed: its depth is 0", f->path);
  return TS_OK;
}

/* Reorder stored voxels into RGBA in place. */
static void
to_rgba (uint8_t *voxels, size_t count, ChannelOrder order)
{
  if (order.byte[0] == 0 && order.byte[1] == 1 && order.byte[2] == 2 && order.byte[3] == 3)
    return;
  for (size_t i = 0; i < count; i++, voxels += 4)
    {
      uint8_t in[4] = { voxels[0], voxels[1], voxels[2], voxels[3] };
      for (int c = 0; c < 4; c++)
        voxels[c] = order.byte[c] >= 0 ? in[order.byte[c]] : 255;
    }
}

TsStatus
ts_volume_read_dds_file (TsInputFile *f, size_t max_bytes, TsVolume8 *v, TsError *error)
{
  uint8_t header[TS_DDS_DATA_OFFSET] = { 0 };
  ChannelOrder order;
  size_t data_offset = 0, bytes;
  uint32_t width, height, depth;
  TsStatus status;
  void *data;

  if (f->length < TS_DDS_LEGACY_DATA_OFFSET)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is truncated: a DDS header is %d bytes, the file has only %llu",
                    f->path, TS_DDS_LEGACY_DATA_OFFSET, (unsigned long long) f->length);
  status = ts_input_read (f, header, f->length < TS_DDS_DATA_OFFSET
                                     ? TS_DDS_LEGACY_DATA_OFFSET : TS_DDS_DATA_OFFSET, error);
  if (status == TS_OK)
    status = parse_header (f, header, &order, &data_offset, error);
  if (status != TS_OK)
    return status;

  width = ts_get_le32 (header + DDS_WIDTH);
  height = ts_get_le32 (header + DDS_HEIGHT);
  depth = ts_get_le32 (header + DDS_DEPTH);
  if (width != height || width != depth)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is a %lux%lux%lu volume; only cubes (equal sides) are supported",
                    f->path, (unsigned long) width, (unsigned long) height,
                    (unsigned long) depth);
  status = ts_volume_check_size (f->path, width, 4, max_bytes, &bytes, error);
  if (status != TS_OK)
    return status;
  if (f->length - data_offset < bytes)
    return ts_fail (error, TS_ERROR_BAD_FILE,
                    "'%s' is truncated: its header announces %lu^3 RGBA voxels (%zu bytes) "
                    "but only %llu bytes follow the header", f->path, (unsigned long) width,
                    bytes, (unsigned long long) (f->length - data_offset));

  if (fseek (f->file, (long) data_offset, SEEK_SET) != 0)
    return ts_fail (error, TS_ERROR_IO, "cannot read '%s'", f->path);
  status = ts_input_read_new (f, bytes, &data, error);
  if (status != TS_OK)
    return status;
  v->voxels = data;
  to_rgba (v->voxels, bytes / 4, order);
  v->size = width;
  v->channels = 4;
  v->wrap = false;
  return TS_OK;
}
