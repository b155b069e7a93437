#!/usr/bin/env python3
"""Checks captured PNGs: each has the expected size and more than one colour.

Reads PNGs with zlib only (no third-party modules) so the check runs on a bare Debian."""
import re
import struct
import sys
import zlib
from pathlib import Path


def read_png(path):
    data = path.read_bytes()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, width, height, ctype = 8, b"", 0, 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, ctype = struct.unpack(">IIBB", chunk[:10])
            if depth != 8:
                raise ValueError(f"{path}: bit depth {depth} not handled")
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, channels, rows


def main():
    args = sys.argv[1:]
    # --min-content F: in the band between the tab bar and the status bar, more than the fraction
    # F of the sampled pixels differ from that band's most common colour (a tab that drew nothing
    # but its chrome has none; a form of text about 5 %).
    min_content = 0.0
    if "--min-content" in args:
        i = args.index("--min-content")
        min_content = float(args[i + 1])
        del args[i:i + 2]
    folder, want_w, want_h = Path(args[0]), int(args[1]), int(args[2])
    pngs = sorted(folder.glob("*.png"))
    if not pngs:
        print(f"no PNG written to {folder}")
        return 1
    status = 0
    for p in pngs:
        w, h, ch, rows = read_png(p)
        colours = set()
        band = {}
        for y in range(0, h, 7):
            row = rows[y]
            for x in range(0, w, 5):
                c = row[x * ch:x * ch + 3]
                colours.add(c)
                if 50 <= y < h - 30:
                    band[c] = band.get(c, 0) + 1
        content = 1 - max(band.values()) / sum(band.values()) if band else 0
        # NAME@WxH.png is a picture taken again at a second window size (--also-size).
        size = re.search(r"@(\d+)x(\d+)$", p.stem)
        want = (int(size.group(1)), int(size.group(2))) if size else (want_w, want_h)
        ok = (w, h) == want and len(colours) > 8 and content > min_content
        print(f"{p.name}: {w}x{h}, {len(colours)} sampled colours, {100 * content:.1f} % drawn on: "
              f"{'ok' if ok else 'FAIL'}")
        status |= 0 if ok else 1
    print(f"all {len(pngs)} captures look right" if status == 0 else "capture check failed")
    return status


if __name__ == "__main__":
    sys.exit(main())
