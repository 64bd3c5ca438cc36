#!/usr/bin/env python3
"""Compares two RGB(A) PNGs of the same size as the Phong-demo test does: covered = not black;
prints the IoU of the covered pixels, both counts and the mean absolute difference per
channel over the pixels both cover. Usage: compare_png.py OURS.png THEIRS.png (needs numpy)."""
import struct, sys, zlib

import numpy as np


def read_png(path):
    data = open(path, "rb").read()
    pos, idat, w, h, ct = 8, b"", 0, 0, 0
    while pos < len(data):
        n = struct.unpack(">I", data[pos:pos + 4])[0]
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, _, ct = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    ch = {2: 3, 6: 4}[ct]
    raw, stride = zlib.decompress(idat), w * ch
    out, prev = np.zeros((h, stride), np.int32), np.zeros(stride, np.int32)
    for y in range(h):
        f, row = raw[y * (stride + 1)], np.frombuffer(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)], np.uint8).astype(np.int32)
        cur = row.copy()
        for x in range(stride):
            a = cur[x - ch] if x >= ch else 0
            b, c = prev[x], (prev[x - ch] if x >= ch else 0)
            pred = {0: 0, 1: a, 2: b, 3: (a + b) // 2}.get(f)
            if pred is None:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (row[x] + pred) & 255
        out[y], prev = cur, cur
    return out.reshape(h, w, ch)[:, :, :3]


a, b = read_png(sys.argv[1]), read_png(sys.argv[2])
ca, cb = a.any(2), b.any(2)
both = ca & cb
iou = both.sum() / max((ca | cb).sum(), 1)
mad = np.abs(a[both] - b[both]).mean(0) if both.any() else np.zeros(3)
print("iou %.4f covered %d %d mad %s" % (iou, ca.sum(), cb.sum(), " ".join("%.3f" % m for m in mad)))
