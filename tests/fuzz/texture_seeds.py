#!/usr/bin/env python3
"""texture_seeds.py - writes the seed corpus of fuzz_texture into
tests/fuzz/corpus/texture/: small PNG files written here byte by byte (every
colour type and bit depth, interlaced, each row filter, ancillary chunks)
and JPEG files made by cjpeg and jpegtran (libjpeg-turbo-progs: baseline,
each chroma sampling, progressive, greyscale, arithmetic coding, restart
markers, separate scans) or here (1000 and 1001 progressive scans), then
broken copies of both: truncated, corrupted, too large, refused for their
colour space. The output is the same bytes on every run with the same
cjpeg and zlib. Run from anywhere:
    python3 tests/fuzz/texture_seeds.py
"""
import os
import struct
import subprocess
import tempfile
import zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "texture")
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def write(name, data):
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)


# ---------------------------------------------------------------- PNG

def chunk(kind, body, crc=None):
    if crc is None:
        crc = zlib.crc32(kind + body)
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", crc)


def ihdr(w, h, depth, colour, interlace=0):
    return chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, colour, 0, 0, interlace))


CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}


def sample(x, y, c, depth):
    """A pattern that uses the whole range of a sample of `depth` bits."""
    top = (1 << depth) - 1
    return (x * 37 + y * 59 + c * 101 + x * y * 7) % (top + 1)


def pack_row(values, depth):
    if depth == 16:
        return b"".join(struct.pack(">H", v) for v in values)
    if depth == 8:
        return bytes(values)
    out, acc, bits = bytearray(), 0, 0
    for v in values:
        acc = acc << depth | v
        bits += depth
        if bits == 8:
            out.append(acc)
            acc, bits = 0, 0
    if bits:
        out.append(acc << (8 - bits))
    return bytes(out)


def raw_rows(w, h, depth, colour, filters=(0,), xs=None, ys=None):
    """Filtered scanlines (filter bytes as given, cycled; the data is left
    as it is, so other filters than 0 give other, still valid, pixels)."""
    n = CHANNELS[colour]
    xs = xs if xs is not None else range(w)
    ys = ys if ys is not None else range(h)
    out = bytearray()
    for i, y in enumerate(ys):
        out.append(filters[i % len(filters)])
        out += pack_row([sample(x, y, c, depth) for x in xs for c in range(n)], depth)
    return bytes(out)


def adam7_rows(w, h, depth, colour):
    passes = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]
    out = b""
    for x0, y0, dx, dy in passes:
        xs, ys = range(x0, w, dx), range(y0, h, dy)
        if len(xs) and len(ys):
            out += raw_rows(w, h, depth, colour, (0, 1, 2, 3, 4), xs, ys)
    return out


def png(w, h, depth, colour, extra=b"", interlace=0, plte=None, filters=(0,), idat_pieces=1, raw=None):
    if raw is None:
        raw = adam7_rows(w, h, depth, colour) if interlace else raw_rows(w, h, depth, colour, filters)
    data = zlib.compress(raw, 9)
    step = -(-len(data) // idat_pieces)
    idats = b"".join(chunk(b"IDAT", data[i:i + step]) for i in range(0, len(data), step))
    pal = chunk(b"PLTE", plte) if plte is not None else b""
    return PNG_MAGIC + ihdr(w, h, depth, colour, interlace) + extra + pal + idats + chunk(b"IEND", b"")


def palette(n):
    return bytes((i * 53 + c * 91) % 256 for i in range(n) for c in range(3))


def png_seeds():
    write("png-rgb8.png", png(8, 8, 8, 2))
    write("png-1x1.png", png(1, 1, 8, 2))
    write("png-grey8.png", png(9, 7, 8, 0))
    write("png-grey1.png", png(17, 5, 1, 0))
    write("png-grey2.png", png(11, 6, 2, 0))
    write("png-grey4-trns.png", png(10, 6, 4, 0, extra=chunk(b"tRNS", struct.pack(">H", 3))))
    write("png-grey16-gamma-linear.png", png(8, 8, 16, 0, extra=chunk(b"gAMA", struct.pack(">I", 100000))))
    write("png-grey-alpha8.png", png(8, 5, 8, 4))
    write("png-grey-alpha16.png", png(5, 4, 16, 4))
    write("png-palette8.png", png(8, 8, 8, 3, plte=palette(256)))
    write("png-palette4.png", png(9, 9, 4, 3, plte=palette(16)))
    # A palette with transparency entries (tRNS after PLTE, as required).
    p = png(7, 5, 2, 3, plte=palette(4))
    at = p.index(b"IDAT") - 4
    write("png-palette2-trns.png", p[:at] + chunk(b"tRNS", bytes([0, 128, 255])) + p[at:])
    write("png-palette1.png", png(20, 3, 1, 3, plte=palette(2)))
    write("png-rgb16.png", png(6, 6, 16, 2))
    write("png-rgb8-trns.png", png(6, 6, 8, 2, extra=chunk(b"tRNS", struct.pack(">HHH", 37, 101, 202))))
    write("png-rgba8.png", png(8, 8, 8, 6))
    write("png-rgba16.png", png(5, 5, 16, 6))
    write("png-interlaced-rgb8.png", png(13, 11, 8, 2, interlace=1))
    write("png-interlaced-palette2.png", png(11, 9, 2, 3, interlace=1, plte=palette(4)))
    write("png-interlaced-rgba16.png", png(9, 10, 16, 6, interlace=1))
    write("png-interlaced-tiny.png", png(3, 2, 8, 0, interlace=1))
    write("png-filters-rgb8.png", png(12, 10, 8, 2, filters=(0, 1, 2, 3, 4)))
    write("png-filters-grey16.png", png(7, 10, 16, 0, filters=(4, 3, 2, 1, 0)))
    write("png-idat-pieces.png", png(16, 16, 8, 2, idat_pieces=5))
    write("png-rgb8-40x30-filters.png", png(40, 30, 8, 2, filters=(1, 2, 3, 4, 0)))
    ancillary = (chunk(b"gAMA", struct.pack(">I", 45455))
                 + chunk(b"cHRM", struct.pack(">8I", 31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000))
                 + chunk(b"sBIT", bytes([5, 6, 5]))
                 + chunk(b"pHYs", struct.pack(">IIB", 2835, 2835, 1))
                 + chunk(b"tIME", struct.pack(">HBBBBB", 2024, 1, 2, 3, 4, 5))
                 + chunk(b"tEXt", b"Title\0glint seed")
                 + chunk(b"zTXt", b"Comment\0\0" + zlib.compress(b"a compressed comment"))
                 + chunk(b"iTXt", b"Author\0\0\0en\0Author\0glint"))
    write("png-ancillary.png", png(8, 6, 8, 2, extra=ancillary))
    write("png-srgb-bkgd.png", png(8, 6, 8, 2, extra=chunk(b"sRGB", b"\0") + chunk(b"bKGD", struct.pack(">HHH", 1, 2, 3))))
    write("png-iccp-bogus.png", png(6, 6, 8, 2, extra=chunk(b"iCCP", b"icc\0\0" + zlib.compress(b"not a profile" * 4))))
    write("png-unknown-chunks.png", png(6, 4, 8, 0, extra=chunk(b"abCd", b"safe to copy") + chunk(b"eXIf", b"MM\0*\0\0\0\x08\0\0")))
    # A large, flat image in few bytes: the decoder's and the check's big-buffer paths.
    write("png-grey1-512x512-flat.png", png(512, 512, 1, 0, raw=bytes((512 // 8 + 1) * 512)))

    # Broken PNG files.
    good = png(8, 8, 8, 2)
    write("bad-png-magic-only.png", PNG_MAGIC)
    write("bad-png-truncated-idat.png", good[: good.index(b"IDAT") + 20])
    write("bad-png-truncated-ihdr.png", good[:20])
    write("bad-png-no-iend.png", good[:-12])
    write("bad-png-ihdr-crc.png", PNG_MAGIC + chunk(b"IHDR", struct.pack(">IIBBBBB", 8, 8, 8, 2, 0, 0, 0), crc=0) + good[33:])
    write("bad-png-text-crc.png", png(4, 4, 8, 2, extra=chunk(b"tEXt", b"Key\0value", crc=1)))
    write("bad-png-no-idat.png", PNG_MAGIC + ihdr(4, 4, 8, 2) + chunk(b"IEND", b""))
    write("bad-png-too-wide.png", png(40000, 1, 1, 0, raw=bytes(40000 // 8 + 1)))
    write("bad-png-too-many-pixels.png", png(20000, 20000, 1, 0, raw=b""))
    write("bad-png-zero-width.png", PNG_MAGIC + ihdr(0, 4, 8, 0) + chunk(b"IEND", b""))
    write("bad-png-depth3.png", PNG_MAGIC + ihdr(4, 4, 3, 0) + chunk(b"IEND", b""))
    write("bad-png-colour5.png", PNG_MAGIC + ihdr(4, 4, 8, 5) + chunk(b"IEND", b""))
    write("bad-png-rows-missing.png", png(8, 8, 8, 2, raw=raw_rows(8, 5, 8, 2)))
    write("bad-png-rows-extra.png", png(8, 8, 8, 2, raw=raw_rows(8, 12, 8, 2)))
    write("bad-png-filter5.png", png(4, 4, 8, 0, filters=(0, 5)))
    write("bad-png-no-plte.png", png(4, 4, 8, 3))
    write("bad-png-palette-short.png", png(8, 8, 8, 3, plte=palette(3)))
    body = zlib.compress(raw_rows(8, 8, 8, 2))
    broken = body[:10] + bytes(b ^ 0x5a for b in body[10:20]) + body[20:]
    write("bad-png-deflate-corrupt.png", PNG_MAGIC + ihdr(8, 8, 8, 2) + chunk(b"IDAT", broken) + chunk(b"IEND", b""))
    write("bad-png-adler.png", PNG_MAGIC + ihdr(8, 8, 8, 2) + chunk(b"IDAT", body[:-4] + b"\0\0\0\0") + chunk(b"IEND", b""))


# ---------------------------------------------------------------- JPEG

def ppm(w, h):
    px = bytearray()
    for y in range(h):
        for x in range(w):
            px += bytes([x * 255 // (w - 1), y * 255 // (h - 1), x * y * 7 % 256])
    return b"P6\n%d %d\n255\n" % (w, h) + bytes(px)


def pgm(w, h):
    return b"P5\n%d %d\n255\n" % (w, h) + bytes((x * 16 + y * 9) % 256 for y in range(h) for x in range(w))


def run(tool, args, data):
    return subprocess.run([tool] + args, input=data, stdout=subprocess.PIPE, check=True).stdout


def segments(jpeg):
    """Offsets of the markers before the first SOS, as (offset, marker)."""
    at, out = 2, []
    while at + 4 <= len(jpeg) and jpeg[at] == 0xFF:
        marker = jpeg[at + 1]
        out.append((at, marker))
        if marker == 0xDA:
            break
        at += 2 + struct.unpack(">H", jpeg[at + 2:at + 4])[0]
    return out


def find(jpeg, marker):
    return next(at for at, m in segments(jpeg) if m == marker)


def with_size(jpeg, w, h):
    sof = next(at for at, m in segments(jpeg) if m in (0xC0, 0xC1, 0xC2, 0xC9, 0xCA))
    return jpeg[:sof + 5] + struct.pack(">HH", h, w) + jpeg[sof + 9:]


def insert(jpeg, at, data):
    return jpeg[:at] + data + jpeg[at:]


def segment(marker, body):
    return bytes([0xFF, marker]) + struct.pack(">H", len(body) + 2) + body


def many_scans_jpeg(scans):
    """An 8 x 8 progressive JPEG, all zero, in `scans` scans (at most 2660):
    every coefficient of each component sent in 14 steps of one bit, and
    then the end. Each scan is its header and one byte, so a file of
    over 1000 scans stays under 12 KB."""
    out = b"\xff\xd8" + segment(0xDB, b"\x00" + b"\x01" * 64)
    out += segment(0xC2, b"\x08\x00\x08\x00\x08\x03" + b"\x01\x11\x00\x02\x11\x00\x03\x11\x00")
    one_code = b"\x01" + b"\x00" * 15 + b"\x00"  # one symbol, 0, of code 0
    out += segment(0xC4, b"\x00" + one_code) + segment(0xC4, b"\x10" + one_code)
    todo = [((1, 2, 3), 0, 0, 0, 13)]
    todo += [((1, 2, 3), 0, 0, al + 1, al) for al in range(12, -1, -1)]
    for comp in (1, 2, 3):
        for k in range(1, 64):
            todo += [((comp,), k, k, 0, 13)] + [((comp,), k, k, al + 1, al) for al in range(12, -1, -1)]
    for comps, ss, se, ah, al in todo[:scans]:
        header = bytes([len(comps)]) + b"".join(bytes([c, 0x00]) for c in comps) + bytes([ss, se, ah << 4 | al])
        out += segment(0xDA, header) + b"\x1f"  # three bits of 0, the rest padding
    return out + b"\xff\xd9"


def jpeg_seeds():
    img, small, odd = ppm(16, 16), ppm(8, 8), ppm(13, 11)
    cj = lambda args, data=img: run("cjpeg", ["-quality", "75"] + args, data)
    base = cj([])
    write("jpeg-baseline-420.jpg", base)
    write("jpeg-baseline-444.jpg", cj(["-sample", "1x1"]))
    write("jpeg-baseline-422.jpg", cj(["-sample", "2x1"]))
    write("jpeg-baseline-440.jpg", cj(["-sample", "1x2"]))
    write("jpeg-odd-size-420.jpg", cj([], odd))
    write("jpeg-tiny-8x8.jpg", cj(["-quality", "30"], small))
    write("jpeg-optimized.jpg", cj(["-optimize"]))
    write("jpeg-restart.jpg", cj(["-restart", "1B"]))
    write("jpeg-progressive.jpg", cj(["-progressive"]))
    write("jpeg-progressive-odd.jpg", cj(["-progressive", "-sample", "1x1"], odd))
    write("jpeg-grey.jpg", cj(["-grayscale"]))
    write("jpeg-grey-pgm.jpg", cj([], pgm(12, 9)))
    write("jpeg-grey-progressive.jpg", cj(["-grayscale", "-progressive"]))
    write("jpeg-arithmetic.jpg", cj(["-arithmetic"]))
    write("jpeg-arithmetic-progressive.jpg", cj(["-arithmetic", "-progressive"]))
    write("jpeg-rgb-colourspace.jpg", cj(["-rgb"]))
    write("jpeg-quality-100.jpg", cj(["-quality", "100"], small))
    write("jpeg-64x48-quality-90.jpg", cj(["-quality", "90"], ppm(64, 48)))
    write("jpeg-64x48-progressive.jpg", cj(["-quality", "90", "-progressive", "-restart", "2"], ppm(64, 48)))
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write("0;\n1;\n2;\n")  # one scan per component: sequential, not interleaved
        scans = f.name
    try:
        write("jpeg-separate-scans.jpg", run("jpegtran", ["-scans", scans], base))
    finally:
        os.unlink(scans)

    # Markers the decoder must step over or only warn about.
    app0 = find(base, 0xE0)
    after_app0 = app0 + 2 + struct.unpack(">H", base[app0 + 2:app0 + 4])[0]
    write("jpeg-comment-exif-icc.jpg", insert(base, after_app0, segment(0xFE, b"a comment")
                                              + segment(0xE1, b"Exif\0\0MM\0*\0\0\0\x08\0\0")
                                              + segment(0xE2, b"ICC_PROFILE\0\x01\x01" + b"\0" * 40)))
    write("jpeg-jfif-version-2.jpg", base[:app0 + 9] + b"\x02" + base[app0 + 10:])
    write("jpeg-extraneous-bytes.jpg", insert(base, find(base, 0xDB), b"\x12\x34\x56"))
    write("jpeg-after-eoi.jpg", base + b"trailing bytes after the end")
    rgb = cj(["-rgb"])
    adobe = find(rgb, 0xEE)
    write("jpeg-adobe-transform-5.jpg", rgb[:adobe + 15] + b"\x05" + rgb[adobe + 16:])

    # Broken JPEG files.
    write("bad-jpeg-magic-only.jpg", b"\xff\xd8\xff")
    write("bad-jpeg-soi-eoi.jpg", b"\xff\xd8\xff\xd9")
    sos = find(base, 0xDA)
    write("bad-jpeg-header-only.jpg", base[:sos + 14])
    write("bad-jpeg-truncated.jpg", base[: (sos + len(base)) // 2])
    write("bad-jpeg-no-eoi.jpg", base[:-2])
    prog = cj(["-progressive"])
    write("bad-jpeg-progressive-truncated.jpg", prog[: len(prog) * 2 // 3])
    data = bytearray(base)
    for i in range(sos + 20, len(data) - 2, 7):
        if data[i] != 0xFF and data[i - 1] != 0xFF:
            data[i] ^= 0x3C
    write("bad-jpeg-entropy-corrupt.jpg", bytes(data))
    write("bad-jpeg-too-wide.jpg", with_size(base, 40000, 16))
    write("bad-jpeg-too-many-pixels.jpg", with_size(base, 32768, 16384))
    write("bad-jpeg-zero-height.jpg", with_size(base, 16, 0))
    write("bad-jpeg-larger-than-data.jpg", with_size(base, 4096, 4096))
    dqt = find(base, 0xDB)
    dqt_len = struct.unpack(">H", base[dqt + 2:dqt + 4])[0]
    write("bad-jpeg-no-dqt.jpg", base[:dqt] + base[dqt + 2 + dqt_len:])
    dht = find(base, 0xC4)
    write("bad-jpeg-dht-corrupt.jpg", base[:dht + 5] + b"\xff" * 16 + base[dht + 21:])
    # Four components and an Adobe marker saying YCCK: refused as CMYK
    # after the header, before any pixel is decoded.
    sof = find(base, 0xC0)
    sof_len = struct.unpack(">H", base[sof + 2:sof + 4])[0]
    sof4 = segment(0xC0, base[sof + 4:sof + 9] + b"\x04" + b"\x01\x11\x00\x02\x11\x01\x03\x11\x01\x04\x11\x00")
    cmyk = base[:sof] + segment(0xEE, b"Adobe\0\x64\0\0\0\0\x02") + sof4 + base[sof + 2 + sof_len:]
    write("bad-jpeg-ycck.jpg", cmyk)
    write("jpeg-progressive-1000-scans.jpg", many_scans_jpeg(1000))
    write("bad-jpeg-progressive-1001-scans.jpg", many_scans_jpeg(1001))


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    png_seeds()
    jpeg_seeds()
