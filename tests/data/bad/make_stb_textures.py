#!/usr/bin/env python3
"""Writes the crafted textures of tests/data/bad/ that reach known faults of
the system stb_image (Debian 12's libstb: stb_image 2.27 with upstream fixes
to September 2022), and a scene naming each (texture_stb_*.babylon).

Every byte is made here, for mote; none comes from a published proof of
concept. src/io/stb_guard*.c refuses (or pads) each before stb_image
sees it; EXPECTED.txt says what each must give, and tests/valgrind.sh runs
mote-render on every scene under memcheck against the real library.

    python3 tests/data/bad/make_stb_textures.py     (from the repository root)
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    with open(os.path.join(HERE, name), 'wb') as f:
        f.write(data)
    scene = ('{"materials":[{"id":"t","diffuseTexture":{"name":"%s"}}],"meshes":[{"id":"m",'
             '"positions":[0,0,0, 1,0,0, 0,1,0],"uvs":[0,0, 1,0, 0,1],"indices":[0,1,2],'
             '"materialId":"t"}]}\n' % name)
    base = name.replace('.', '_')
    with open(os.path.join(HERE, 'texture_%s.babylon' % base), 'w') as f:
        f.write(scene)


# ---- JPEG: segments, and entropy-coded bits (most significant first, 0xff stuffed)

def seg(marker, body):
    return bytes([0xff, marker]) + struct.pack('>H', len(body) + 2) + body


SOI, EOI = b'\xff\xd8', b'\xff\xd9'


def dqt(table=0, first=1, sixteen=False):
    if sixteen:
        return seg(0xdb, bytes([0x10 | table]) + struct.pack('>64H', first, *[1] * 63))
    return seg(0xdb, bytes([table, first] + [1] * 63))


def sof(marker, w, h, comps):  # comps: (id, sampling, quantisation table)
    body = bytes([8]) + struct.pack('>HH', h, w) + bytes([len(comps)])
    for cid, hv, tq in comps:
        body += bytes([cid, hv, tq])
    return seg(marker, body)


def dht(tc, th, counts, values):
    return seg(0xc4, bytes([tc << 4 | th]) + bytes(counts) + bytes(values))


def sos(comps, ss=0, se=63, ah=0, al=0):  # comps: (id, DC table, AC table)
    body = bytes([len(comps)])
    for cid, td, ta in comps:
        body += bytes([cid, td << 4 | ta])
    return seg(0xda, body + bytes([ss, se, ah << 4 | al]))


def bits(pairs):
    s = ''.join(format(v, '0%db' % n) for v, n in pairs)
    s += '1' * (-len(s) % 8)
    out = bytearray()
    for i in range(0, len(s), 8):
        out.append(int(s[i:i + 8], 2))
        if out[-1] == 0xff:
            out.append(0)
    return bytes(out)


ONE = [1] + [0] * 15  # a table of one code, '0'
GREY = [(1, 0x11, 0)]

# a Huffman table of 765 codes: stb_image sizes its arrays for 256 and
# writes past them; the 0x40 symbols land on its decoding limits
# (CVE-2022-28042: with them it reads 1 GiB off its table)
write('stb_huffman_765.jpg',
      SOI + dqt() + sof(0xc0, 8, 8, GREY) + dht(0, 0, ONE, [0]) +
      dht(1, 0, [0] * 13 + [255, 255, 255], [0x40] * 765) + sos([(1, 0, 0)]) + b'\0' * 4 + EOI)
# a scan naming AC table 1, which no DHT defines: stb_image does not clear
# its tables, so it decodes with whatever malloc returned
write('stb_no_huffman_table.jpg',
      SOI + dqt() + sof(0xc0, 8, 8, GREY) + dht(0, 0, ONE, [0]) + dht(1, 0, ONE, [0]) +
      sos([(1, 0, 1)]) + b'\0' * 4 + EOI)
# a component whose quantisation table no DQT defines
write('stb_no_quant_table.jpg',
      SOI + dqt() + sof(0xc0, 8, 8, [(1, 0x11, 1)]) + dht(0, 0, ONE, [8]) + dht(1, 0, ONE, [0]) +
      sos([(1, 0, 0)]) + bits([(0, 1), (0xff, 8), (0, 1)]) + EOI)
# three components, one scan: stb_image converts the two never decoded
write('stb_unscanned_component.jpg',
      SOI + dqt() + sof(0xc0, 8, 8, [(1, 0x11, 0), (2, 0x11, 0), (3, 0x11, 0)]) +
      dht(0, 0, ONE, [0]) + dht(1, 0, ONE, [0]) + sos([(1, 0, 0)]) + b'\0' * 2 + EOI)
# a restart interval of one block and no restart marker: stb_image stops
# the scan after the first block and shows the other seven unwritten
write('stb_restart_cut.jpg',
      SOI + dqt() + seg(0xdd, struct.pack('>H', 1)) + sof(0xc0, 64, 8, GREY) +
      dht(0, 0, ONE, [0]) + dht(1, 0, ONE, [0]) + sos([(1, 0, 0)]) + b'\0' * 8 + EOI)
# progressive, with an AC scan and no first DC scan: the coefficients
# stb_image transforms were never set
write('stb_progressive_no_dc.jpg',
      SOI + dqt() + sof(0xc2, 8, 8, GREY) + dht(1, 0, ONE, [0]) + sos([(1, 0, 0)], 1, 63) +
      b'\0' * 2 + EOI)
# DC differences of +32767 summed in an int and multiplied by a 16-bit
# quantisation step of 65535: signed overflow (nothings/stb#1533)
write('stb_dc_overflow.jpg',
      SOI + dqt(0, 65535, True) + sof(0xc0, 8, 32, GREY) + dht(0, 0, ONE, [15]) +
      dht(1, 0, ONE, [0]) + sos([(1, 0, 0)]) + bits([(0, 1), (0x7fff, 15), (0, 1)] * 4) + EOI)
# the same in a progressive first DC scan, scaled by 2^13 (CVE-2022-28041)
write('stb_progressive_dc_overflow.jpg',
      SOI + dqt() + sof(0xc2, 8, 128, GREY) + dht(0, 0, ONE, [15]) +
      sos([(1, 0, 0)], 0, 0, 0, 13) + bits([(0, 1), (0x7fff, 15)] * 16) + EOI)


# ---- PNG

def chunk(kind, body):
    return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body))


def png(w, h, depth, ctype, zdata, extra=b''):
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, depth, ctype, 0, 0, 0)) +
            extra + chunk(b'IDAT', zdata) + chunk(b'IEND', b''))


class Deflate:
    """Bits of a DEFLATE stream: fields lowest bit first, Huffman codes highest first."""

    def __init__(self):
        self.value, self.count = 0, 0

    def put(self, v, n):
        self.value |= v << self.count
        self.count += n

    def code(self, c, n):
        self.put(int(format(c, '0%db' % n)[::-1], 2), n)

    def fixed(self, symbol):  # the fixed literal/length code of DEFLATE
        if symbol < 144:
            self.code(0x30 + symbol, 8)
        elif symbol < 256:
            self.code(0x190 + symbol - 144, 9)
        elif symbol < 280:
            self.code(symbol - 256, 7)
        else:
            self.code(0xc0 + symbol - 280, 8)

    def zlib(self):  # header, stream, and the four bytes an Adler-32 takes
        return b'\x78\x01' + self.value.to_bytes((self.count + 7) // 8, 'little') + b'\0' * 4


def copies(length_symbol, distance_code):
    """A 16 x 16 grey image whose rows are a filter byte and one copy."""
    z = Deflate()
    z.put(1, 1)  # final block
    z.put(1, 2)  # fixed codes
    for _ in range(16):
        z.fixed(0)
        z.fixed(length_symbol)
        if length_symbol == 267:
            z.put(1, 1)  # 15 + 1: a length of 16
        z.code(distance_code, 5)
    z.fixed(256)
    return png(16, 16, 8, 0, z.zlib())


# distance code 30, which DEFLATE forbids: stb_image 2.27 takes a distance
# of 0 and copies each output byte onto itself, bytes malloc left
write('stb_deflate_distance_30.png', copies(267, 30))
# length code 286, forbidden too (stb_image reads a length of 0)
write('stb_deflate_length_286.png', copies(286, 0))
# an IDAT chunk claiming 2 GiB: stb_image reallocates its buffer to that
# before it finds the file ends
idat = struct.pack('>I', 0x7ffffff0) + b'IDAT' + zlib.compress(b'\0' * 17)
write('stb_idat_2gib.png',
      b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', 4, 4, 8, 0, 0, 0, 0)) + idat)
# a palette of 2 entries and indices 0..15: stb_image looks 2..15 up in an
# uninitialised stack array (nothings/stb#1861); mote pads the palette with black
write('stb_short_palette.png',
      png(16, 1, 8, 3, zlib.compress(b'\0' + bytes(range(16))),
          chunk(b'PLTE', bytes([255, 0, 0, 0, 255, 0]))))


# ---- BMP, TGA, PNM, PIC

def bmp8(w, rows, palette, offset=None):
    off = 14 + 40 + 4 * len(palette) if offset is None else offset
    stride = (w + 3) & ~3
    data = b''.join(bytes(r) + b'\0' * (stride - w) for r in rows)
    head = b'BM' + struct.pack('<IHHI', off + len(data), 0, 0, off)
    info = struct.pack('<IiiHHIIiiII', 40, w, len(rows), 1, 8, 0, len(data), 0, 0, len(palette), 0)
    body = head + info + b''.join(bytes([b, g, r, 0]) for r, g, b in palette)
    return body + b'\0' * max(0, off - len(body)) + data


# 2 palette entries, indices 0..15 (nothings/stb#1929): padded with black too
write('stb_short_palette.bmp', bmp8(16, [range(16)], [(255, 0, 0), (0, 255, 0)]))
# pixels at byte 10, inside the header: stb_image counts -11 palette
# entries, fills none, and looks every index up
write('stb_palette_in_header.bmp', bmp8(16, [range(16)], [], offset=10))
# an uncompressed 16 x 16 TGA with no pixels: stb_image does not check its
# reads and returns the buffer as malloc gave it (CVE-2023-45663)
write('stb_truncated.tga', struct.pack('<BBBHHBHHHHBB', 0, 0, 2, 0, 0, 0, 0, 0, 16, 16, 24, 0x20))
# the same for PNM
write('stb_truncated.ppm', b'P6\n16 16\n255\n')
# a width stb_image adds up in an int past INT_MAX (oss-fuzz 22620)
write('stb_huge_number.ppm', b'P6\n99999999999 1\n255\n' + b'\0' * 3)
# a PIC whose packets are well formed and whose pixels are cut short: its
# loader fails and hands NULL to stbi__convert_format, which dereferences
# it when asked for 3 channels (CVE-2023-43898); with mote's 4 it returns
write('stb_pic_cut_short.pic',
      b'\x53\x80\xf6\x34' + b'\0' * 84 + b'PICT' + struct.pack('>HH', 4, 4) + b'\0' * 8 +
      bytes([0, 8, 0, 0xe0]) + b'\1\2\3')
