"""The pixel rows of an 8-bit RGB or RGBA PNG, as io/PngFile writes them: standard library only.

Shared by scripts/size-pictures.py (which tiles figment-view's pictures) and the service's tests
(tests/serve/scenarios/ServeSupport.py, which counts colours in figment-serve's answers); a
script beside it imports it as `pngrows`, a test puts this folder on sys.path first."""
import struct
import zlib

SIGNATURE = b"\x89PNG\r\n\x1a\n"


def unfiltered_rows(data):
    """(width, height, channels, rows): `data`, a whole PNG file, decoded; each row a bytearray
    of width * channels values (3: RGB, 4: RGBA), the scanline filters undone."""
    assert data[:8] == SIGNATURE, "not a PNG"
    position, idat, header = 8, b"", None
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position:position + 8])
        chunk = data[position + 8:position + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        position += 12 + length
    width, height, depth, colour = header[:4]
    assert depth == 8 and colour in (2, 6), "only 8-bit RGB(A)"
    channels = 3 if colour == 2 else 4
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = previous[x], previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows
