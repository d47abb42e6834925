#!/usr/bin/env python3
"""Every figure of a report directory is a valid file: each .svg parses as XML with an <svg>
root that has a viewBox or width and height; each .png decodes (signature, chunk CRCs, IHDR,
zlib stream of IDAT, the decompressed size that width, height, colour type and bit depth demand,
and the filter byte of every row). Usage: check_files.py REPORT_DIR. Prints one line per file."""
import os
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}


def check_svg(path):
    root = ET.parse(path).getroot()
    if root.tag.split("}")[-1] != "svg":
        raise ValueError(f"root element is <{root.tag}>, not <svg>")
    if "viewBox" not in root.attrib and not ("width" in root.attrib and "height" in root.attrib):
        raise ValueError("<svg> has neither a viewBox nor a width and a height")
    return f"{len(list(root.iter()))} elements"


def check_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG signature")
    pos, idat, ihdr, end = 8, b"", None, False
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        if len(body) != length or zlib.crc32(kind + body) != crc:
            raise ValueError(f"chunk {kind!r} at byte {pos} is truncated or fails its CRC")
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            end = True
            break
        pos += 12 + length
    if ihdr is None or not end:
        raise ValueError("no IHDR or no IEND")
    width, height, depth, colour, _, _, interlace = ihdr
    if interlace:
        return f"{width}x{height} (interlaced, stream not sized)"
    raw = zlib.decompress(idat)
    row = 1 + (width * CHANNELS[colour] * depth + 7) // 8
    if len(raw) != row * height:
        raise ValueError(f"image data is {len(raw)} bytes, {width}x{height} needs {row * height}")
    if any(raw[r * row] > 4 for r in range(height)):
        raise ValueError("a row has an unknown filter type")
    return f"{width}x{height}"


def main():
    folder = sys.argv[1]
    bad, seen = 0, 0
    for name in sorted(os.listdir(folder)):
        kind = os.path.splitext(name)[1]
        if kind not in (".svg", ".png"):
            continue
        seen += 1
        try:
            what = (check_svg if kind == ".svg" else check_png)(os.path.join(folder, name))
            print(f"ok    {name}: {what}")
        except Exception as e:  # noqa: BLE001 - every failure is a finding
            bad += 1
            print(f"FAIL  {name}: {e}")
    if seen == 0:
        print("FAIL  no figure files")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
