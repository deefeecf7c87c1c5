#!/usr/bin/env python3
"""Writes uv_grid.png: a 512x256 uv test grid for checking texture orientation by eye.

Pure Python 3 standard library (zlib + struct). Run from anywhere:
    python3 textures/make_uv_grid.py [output.png]
The output is deterministic (same bytes on every run).

Layout (u = x / width left to right, v = 1 - y / height: v = 1 is the TOP row):
- 8 x 4 cells of 64 x 64 px. Hue follows the column (u), brightness the row (v):
  the top row (v in [0.75, 1]) is the brightest, the bottom row the darkest.
- Each cell is labelled with two digits "CR": C = column 0..7 (floor(8u)),
  R = row 0..3 counted from the BOTTOM (floor(4v)). Mirrored digits mean a
  mirrored mapping; "00" must sit at the bottom-left, "73" at the top-right.
- A big "N" in the top-left cell; a white band along the top edge (v near 1, the
  north pole on a sphere) and a black band along the bottom edge (v near 0).
- A red stripe along the left edge (u near 0) only, so the side of the u seam that
  is u = 0 can be told apart from u = 1.
- Dark grid lines on the cell borders, faint lines every 16 px.
"""
import colorsys
import os
import struct
import sys
import zlib

WIDTH, HEIGHT = 512, 256
COLS, ROWS = 8, 4
CELL = 64

# 5x7 bitmap glyphs, '#' = ink.
GLYPHS = {
    "0": [" ### ", "#   #", "#  ##", "# # #", "##  #", "#   #", " ### "],
    "1": ["  #  ", " ##  ", "# #  ", "  #  ", "  #  ", "  #  ", "#####"],
    "2": [" ### ", "#   #", "    #", "   # ", "  #  ", " #   ", "#####"],
    "3": ["#####", "   # ", "  #  ", "   # ", "    #", "#   #", " ### "],
    "4": ["   # ", "  ## ", " # # ", "#  # ", "#####", "   # ", "   # "],
    "5": ["#####", "#    ", "#### ", "    #", "    #", "#   #", " ### "],
    "6": ["  ## ", " #   ", "#    ", "#### ", "#   #", "#   #", " ### "],
    "7": ["#####", "    #", "   # ", "  #  ", " #   ", " #   ", " #   "],
    "N": ["#   #", "##  #", "# # #", "#  ##", "#   #", "#   #", "#   #"],
}


def cell_colour(col, row_from_bottom):
    """sRGB colour of a cell: hue by column, value by row (top row brightest)."""
    hue = col / COLS
    value = 0.40 + 0.18 * row_from_bottom
    r, g, b = colorsys.hsv_to_rgb(hue, 0.65, value)
    return [int(round(255 * c)) for c in (r, g, b)]


def draw_text(pixels, text, x0, y0, scale, colour):
    for i, ch in enumerate(text):
        glyph = GLYPHS[ch]
        gx = x0 + i * 6 * scale
        for gy, line in enumerate(glyph):
            for gxi, mark in enumerate(line):
                if mark != "#":
                    continue
                for dy in range(scale):
                    for dx in range(scale):
                        x, y = gx + gxi * scale + dx, y0 + gy * scale + dy
                        if 0 <= x < WIDTH and 0 <= y < HEIGHT:
                            pixels[y][x] = list(colour)


def make_pixels():
    pixels = [[None] * WIDTH for _ in range(HEIGHT)]
    for y in range(HEIGHT):
        row_from_bottom = ROWS - 1 - y // CELL
        for x in range(WIDTH):
            c = cell_colour(x // CELL, row_from_bottom)
            if x % 16 == 0 or y % 16 == 0:  # faint sub-grid
                c = [int(v * 0.8) for v in c]
            if x % CELL in (0, CELL - 1) or y % CELL in (0, CELL - 1):  # cell borders (2 px across)
                c = [30, 30, 30]
            pixels[y][x] = c
    # Labels "CR" (column, row from the bottom), 3x scale: 33 x 21 px, centred.
    for row in range(ROWS):
        for col in range(COLS):
            label = f"{col}{ROWS - 1 - row}"
            draw_text(pixels, label, col * CELL + (CELL - 33) // 2, row * CELL + (CELL - 21) // 2 + 6, 3,
                      (255, 255, 255) if row > 0 else (0, 0, 0))
    # North marker: a big "N" in the top-left cell, above its label.
    draw_text(pixels, "N", 8, 9, 2, (0, 0, 0))
    # Bands: white along the top edge (v ~ 1), black along the bottom (v ~ 0).
    for y in range(6):
        for x in range(WIDTH):
            pixels[y][x] = [255, 255, 255]
            pixels[HEIGHT - 1 - y][x] = [0, 0, 0]
    # Red stripe along the left edge only (u ~ 0).
    for y in range(HEIGHT):
        for x in range(4):
            pixels[y][x] = [230, 0, 0]
    return pixels


def png_chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def write_png(path, pixels):
    raw = bytearray()
    for row in pixels:
        raw.append(0)  # filter type 0 (None)
        for r, g, b in row:
            raw += bytes((r, g, b))
    ihdr = struct.pack(">IIBBBBB", WIDTH, HEIGHT, 8, 2, 0, 0, 0)  # 8-bit RGB
    data = b"\x89PNG\r\n\x1a\n"
    data += png_chunk(b"IHDR", ihdr)
    data += png_chunk(b"sRGB", b"\x00")  # sRGB, perceptual intent
    data += png_chunk(b"IDAT", zlib.compress(bytes(raw), 9))
    data += png_chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(data)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "uv_grid.png")
    write_png(out, make_pixels())
    print(f"wrote {out} ({WIDTH}x{HEIGHT})")


if __name__ == "__main__":
    main()
