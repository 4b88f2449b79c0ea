#!/usr/bin/env python3
"""Count the frames of a GIF by walking its blocks (GIF89a spec): each image descriptor
(0x2C) is one frame; prints "frames graphic_control_extensions", exits 1 on a GIF that
is not whole (a block past the end, no trailer 0x3B)."""
import sys

d = open(sys.argv[1], 'rb').read()
if d[:6] not in (b'GIF87a', b'GIF89a'):
    sys.exit('not a GIF: header %r' % d[:6])
flags, i = d[10], 13
if flags & 0x80:  # a global colour table of 2^(n+1) RGB entries
    i += 3 * (2 << (flags & 7))


def sub_blocks(i):
    while d[i]:
        i += d[i] + 1
    return i + 1


frames = gce = 0
try:
    while True:
        b = d[i]
        i += 1
        if b == 0x3B:
            break
        if b == 0x21:
            gce += d[i] == 0xF9
            i = sub_blocks(i + 1)
        elif b == 0x2C:
            frames += 1
            lf = d[i + 8]
            i += 9
            if lf & 0x80:
                i += 3 * (2 << (lf & 7))
            i = sub_blocks(i + 1)  # past the LZW minimum code size
        else:
            sys.exit('bad block 0x%02x at byte %d' % (b, i - 1))
except IndexError:
    sys.exit('the GIF ends inside a block (no trailer)')
print(frames, gce)
