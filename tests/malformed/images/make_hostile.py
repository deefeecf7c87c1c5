#!/usr/bin/env python3
"""Writes the hostile image files of the malformed corpus into this directory (they are
committed; rerun this to remake them). Each is a few bytes whose header claims much more,
or whose content disagrees with its name, or a file a decoder reads past its data."""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
EARTH = os.path.join(HERE, "..", "..", "..", "textures", "earth.jpg")


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


def png(width, height, color_type, raw_rows, plte=None):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0))
    if plte is not None:
        out += chunk(b"PLTE", plte)
    return out + chunk(b"IDAT", zlib.compress(raw_rows, 9)) + chunk(b"IEND", b"")


def gray_png(width, height):
    return png(width, height, 0, (b"\x00" + b"\x80" * width) * height)


# A 35-byte GIF: a 16384 x 16384 canvas holding a 1 x 1 image.
gif = b"GIF89a" + struct.pack("<HHBBB", 16384, 16384, 0x80, 0, 0) + b"\x00\x00\x00\xff\xff\xff"
gif += b"," + struct.pack("<HHHHB", 0, 0, 1, 1, 0) + b"\x02\x02\x44\x01\x00;"
write("canvas-16384.gif", gif)
# A 19-byte PPM header declaring 16384 x 16384 and no pixels.
write("header-only.ppm", b"P6\n16384 16384\n255\n")
# A 54-byte BMP header (file header and BITMAPINFOHEADER), 16384 x 16384, 24 bits, no pixels.
write("header-only.bmp", b"BM" + struct.pack("<IHHI", 54 + 16384 * 16384 * 3, 0, 0, 54) +
      struct.pack("<IiiHHIIiiII", 40, 16384, 16384, 1, 24, 0, 0, 2835, 2835, 0, 0))
# An 18-byte TGA header (uncompressed true colour, 16384 x 16384, 24 bits), as .tga and as .png.
tga = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, 16384, 16384, 24, 0)
write("header-only.tga", tga)
write("tga-named.png", tga)
# A JPEG named .png.
with open(EARTH, "rb") as f:
    earth = f.read()
write("jpeg-named.png", earth[:2048])
# earth.jpg cut after 4 KiB: its header and the start of its scan.
write("truncated.jpg", earth[:4096])
# A 4 x 4 palette PNG with a palette of 2 colours whose pixels use indices up to 255.
indices = bytes([0, 1, 2, 3, 0, 1, 200, 255, 0, 1, 0, 1, 17, 1, 0, 1])
rows = b"".join(b"\x00" + indices[y * 4:(y + 1) * 4] for y in range(4))
write("palette-out-of-range.png", png(4, 4, 3, rows, plte=b"\xff\x00\x00\x00\x00\xff"))
# One side over 16384, and a wide and a tall image (each its own size: 128 KiB together).
write("wide-16385.png", gray_png(16385, 1))
write("wide-16384.png", gray_png(16384, 1))
write("tall-16384.png", gray_png(1, 16384))
# A 16384 x 16384 PNG's signature and IHDR chunk, then IEND (no pixel data): 1 GiB on the
# GPU, over the default budget.
write("header-16384.png", png(16384, 16384, 0, b"")[:8 + 25] + png(1, 1, 0, b"")[-12:])
# MAX_IMAGES (16) distinct 1 x 1 images: a scene naming a 17th is refused before it is opened.
os.makedirs(os.path.join(HERE, "count"), exist_ok=True)
for i in range(1, 17):
    write(os.path.join("count", "%02d.png" % i), gray_png(1, 1))
