#!/usr/bin/python3
"""Writes the example height map maps/hills.png (16-bit grey) and maps/hills.yaml.

Gentle hills over 8 m x 8 m at 0.1 m/pixel (81 x 81 samples, x and y in [-4, 4] m): a few
Gaussian bumps and hollows on a slight tilt. Each bump of height a and width s has its
largest principal curvature |a| / s^2 at a hollow's bottom and 0.45 a / s^2 on a hill's flank;
the largest here is 0.41 1/m (the map's bound, HeightMapSurface::maxPrincipalCurvature, 0.47 1/m),
so the terrain stack's sphere (R = 0.2 m, urdf/terrain_robot.urdf) keeps single-point contact
with R k < 0.1, and the built-in circle (radius 2 m about the
origin) stays 2 m inside the map's edges. The heights are stored as 16-bit grey levels between
min_height and max_height (one level is 7 um).

Run:  /usr/bin/python3 derivations/make_hills_map.py [OUTPUT_DIRECTORY]   (default maps/)
"""
import os
import struct
import sys
import zlib

import numpy as np

RESOLUTION = 0.1         # [m/pixel]
HALF_EXTENT = 4.0        # [m]: samples from -4 to 4 m
TILT = (0.02, -0.01)     # dz/dx, dz/dy
# (x, y, height a [m], width s [m]): hills a > 0, hollows a < 0.
BUMPS = [(1.5, 1.0, 0.30, 0.9), (-1.8, 1.6, 0.25, 0.8), (-1.0, -2.2, 0.20, 1.0),
         (2.2, -1.7, -0.20, 0.7), (0.0, 0.3, -0.10, 0.8), (-2.8, -0.5, 0.15, 0.6)]


def heights():
    """Heights [m] with row 0 the map's +y edge, column 0 its -x edge (an image's layout)."""
    samples = np.arange(-HALF_EXTENT, HALF_EXTENT + RESOLUTION / 2, RESOLUTION)
    x, y = np.meshgrid(samples, samples[::-1])
    z = TILT[0] * x + TILT[1] * y
    for cx, cy, a, s in BUMPS:
        z += a * np.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2 * s * s))
    return z


def png_16bit_grey(levels):
    """A PNG file's bytes for a 2-D array of 16-bit grey levels (each row with the Up filter,
    which suits a smooth surface)."""
    height, width = levels.shape
    raw = levels.astype('>u2').view(np.uint8).reshape(height, 2 * width)
    up = raw.astype(np.int16) - np.vstack([np.zeros((1, 2 * width), np.int16), raw[:-1].astype(np.int16)])
    rows = np.hstack([np.full((height, 1), 2, np.uint8), (up % 256).astype(np.uint8)])

    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data))
    header = struct.pack('>IIBBBBB', width, height, 16, 0, 0, 0, 0)  # 16-bit grey, no interlace
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header) +
            chunk(b'IDAT', zlib.compress(rows.tobytes(), 9)) + chunk(b'IEND', b''))


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..', 'maps')
    z = heights()
    low, high = np.floor(z.min() * 100) / 100, np.ceil(z.max() * 100) / 100
    levels = np.round((z - low) / (high - low) * 65535).astype(np.uint16)
    with open(os.path.join(directory, 'hills.png'), 'wb') as f:
        f.write(png_16bit_grey(levels))
    corner = -HALF_EXTENT - RESOLUTION / 2  # map_server's origin: the bottom-left pixel's outer corner
    with open(os.path.join(directory, 'hills.yaml'), 'w') as f:
        f.write('# Example height map: gentle hills, 8 m x 8 m (derivations/make_hills_map.py).\n'
                '# Format: docs/conventions.md, "Height maps".\n'
                'image: hills.png      # 16-bit grey, 81 x 81 pixels\n'
                'resolution: %g       # [m/pixel]\n'
                'origin: [%g, %g, 0.0]  # [m] outer corner of the bottom-left pixel\n'
                'min_height: %g     # [m] grey level 0\n'
                'max_height: %g      # [m] grey level 65535\n' % (RESOLUTION, corner, corner, low, high))


if __name__ == '__main__':
    main()
