#!/usr/bin/env python3
"""X window dumps (xwd) to PNG, and PNG strips, in the standard library only (zlib, struct).

    xwd_png.py png FILE.xwd X Y W H OUT.png   crop a dump of the root window to X, Y, W x H
    xwd_png.py black FILE.xwd X Y W H         exit 0 if that region is all black (not drawn yet)
    xwd_png.py strip OUT.png SCALE A.png ...  the PNGs side by side, each shrunk by the integer
                                              SCALE (box filter), 4 px of grey between them

Used by tools/window_check_xvfb.sh and tools/walk_strips.sh. Reads the PNGs this module writes
(8-bit RGB, not interlaced), nothing else.
"""
import struct
import sys
import zlib


def xwd_rows(src, x0, y0, w, h):
    """The RGB rows of the window at x0, y0, w x h in a TrueColor ZPixmap X window dump of depth
    24 (Xvfb: 3 or 4 bytes a pixel, lines padded), each row a bytes of 3 * w."""
    with open(src, "rb") as f:
        d = f.read()
    hdr = struct.unpack(">25I", d[:100])
    header_size, fmt, depth = hdr[0], hdr[2], hdr[3]
    byte_order, bpp, line_bytes, ncolors = hdr[7], hdr[11], hdr[12], hdr[19]
    stride = bpp // 8
    if fmt != 2 or depth != 24 or stride not in (3, 4):
        sys.exit(f"xwd_png: {src}: expected a depth-24 ZPixmap dump (format {fmt}, depth {depth}, {bpp} bpp)")
    red_mask = hdr[14]
    pix = d[header_size + 12 * ncolors:]
    rows = []
    for y in range(y0, y0 + h):
        line = pix[y * line_bytes:(y + 1) * line_bytes]
        row = bytearray()
        for x in range(x0, x0 + w):
            p = int.from_bytes(line[stride * x:stride * x + stride], "little" if byte_order == 0 else "big")
            r, g, b = (p >> 16) & 255, (p >> 8) & 255, p & 255
            row += bytes((r, g, b) if red_mask == 0xFF0000 else (b, g, r))
        rows.append(bytes(row))
    return rows


def write_png(rows, w, h, dst):
    def chunk(t, c):
        return struct.pack(">I", len(c)) + t + c + struct.pack(">I", zlib.crc32(t + c) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(b"".join(b"\0" + r for r in rows), 9)) + chunk(b"IEND", b"")
    with open(dst, "wb") as f:
        f.write(png)


def read_png(src):
    """(rows, w, h) of an 8-bit RGB, non-interlaced PNG with filter type 0 rows (write_png's)."""
    with open(src, "rb") as f:
        d = f.read()
    pos, idat = 8, b""
    w = h = 0
    while pos < len(d):
        n, t = struct.unpack(">I4s", d[pos:pos + 8])
        body = d[pos + 8:pos + 8 + n]
        if t == b"IHDR":
            w, h, bits, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if (bits, colour, interlace) != (8, 2, 0):
                sys.exit(f"xwd_png: {src}: only 8-bit RGB, non-interlaced PNGs (this module's own)")
        elif t == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    rows = []
    for y in range(h):
        line = raw[y * (3 * w + 1):(y + 1) * (3 * w + 1)]
        if line[0] != 0:
            sys.exit(f"xwd_png: {src}: row {y} uses PNG filter {line[0]} (only 0 is read)")
        rows.append(line[1:])
    return rows, w, h


def shrink(rows, w, h, k):
    """Box filter by an integer factor k."""
    out = []
    for y in range(h // k):
        block = rows[y * k:(y + 1) * k]
        row = bytearray()
        for x in range(w // k):
            for c in range(3):
                row.append(sum(r[3 * (x * k + i) + c] for r in block for i in range(k)) // (k * k))
        out.append(bytes(row))
    return out, w // k, h // k


def strip(dst, k, sources):
    tiles = [shrink(*read_png(s), k) for s in sources]
    gap, grey = 4, b"\x80\x80\x80"
    h = max(t[2] for t in tiles)
    w = sum(t[1] for t in tiles) + gap * (len(tiles) - 1)
    rows = []
    for y in range(h):
        row = bytearray()
        for i, (r, tw, th) in enumerate(tiles):
            row += r[y] if y < th else grey * tw
            if i + 1 < len(tiles):
                row += grey * gap
        rows.append(bytes(row))
    write_png(rows, w, h, dst)


def main(argv):
    mode = argv[1] if len(argv) > 1 else ""
    if mode in ("png", "black") and len(argv) >= 7:
        x0, y0, w, h = map(int, argv[3:7])
        rows = xwd_rows(argv[2], x0, y0, w, h)
        if mode == "black":
            return 0 if all(not any(r) for r in rows) else 1
        write_png(rows, w, h, argv[7])
        return 0
    if mode == "strip" and len(argv) >= 5:
        strip(argv[2], int(argv[3]), argv[4:])
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
