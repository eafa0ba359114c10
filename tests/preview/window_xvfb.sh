#!/bin/sh
# The interactive previewer's window path under Xvfb: GLFW window, OpenGL core context through
# GLX (llvmpipe), the preview frame and the ImGui panel drawn. Usage: window_xvfb.sh WOVEN_BINARY
set -eu
woven="$1"
tmp=$(mktemp -d)
xvfb_pid=
cleanup() {
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null || true
    rm -rf "$tmp"
}
trap cleanup EXIT

# A display that Xvfb chose free itself (-displayfd): other tests may start servers at once.
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$tmp/display" >"$tmp/xvfb.log" 2>&1 &
xvfb_pid=$!
for _ in $(seq 100); do [ -s "$tmp/display" ] && break; sleep 0.1; done
display=$(head -n 1 "$tmp/display")
[ -n "$display" ] || { echo "Xvfb did not start within 10 s"; cat "$tmp/xvfb.log"; exit 1; }

DISPLAY=":$display" LIBGL_ALWAYS_SOFTWARE=1 "$woven" preview --frames 5 --width 800 --height 600 \
    --window-screenshot "$tmp/shot.png"
# The draft view: a draft opened on the cloth draws its threads' colours (houndstooth.wif's
# dark and light, sRGB 32,30,36 and 236,228,210) in its colour bars and drawdown.
assets="$(cd "$(dirname "$0")/../../assets" && pwd)"
DISPLAY=":$display" LIBGL_ALWAYS_SOFTWARE=1 "$woven" preview --frames 5 --width 800 --height 600 \
    --wif "$assets/drafts/houndstooth.wif" --window-screenshot "$tmp/draft.png"

# The screenshot must be an 800x600 PNG with both the cloth and the panel in it: many distinct
# colours (a blank or failed frame is one or two), and the ImGui panel's title bar colour present.
python3 - "$tmp/shot.png" "$tmp/draft.png" <<'PY'
import struct, sys, zlib

def pixels(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
    pos, idat, header = 8, b'', None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR': header = struct.unpack('>IIBBBBB', body)
        if kind == b'IDAT': idat += body
        pos += 12 + length
    width, height, depth, colour_type = header[:4]
    assert (width, height) == (800, 600), f'size {width}x{height}, expected 800x600'
    assert depth == 8 and colour_type in (2, 6), f'unexpected PNG format {depth} {colour_type}'
    channels = 3 if colour_type == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line)); prev = line
    return width, height, channels, stride, rows

width, height, channels, stride, rows = pixels(sys.argv[1])
colours = {row[i:i + 3] for row in rows for i in range(0, stride, channels)}
print(f'{width}x{height}, {len(colours)} distinct colours')
assert len(colours) > 200, 'the frame is (nearly) one colour: nothing was drawn'
# The cloth is drawn where the panel is not: the right quarter of the frame must itself vary.
right = {row[x * channels:x * channels + 3] for row in rows for x in range(width * 3 // 4, width)}
assert len(right) > 50, f'the preview area (right quarter) is blank: {len(right)} colours'
_, _, channels, stride, rows = pixels(sys.argv[2])
draft = {row[i:i + 3] for row in rows for i in range(0, stride, channels)}
for colour in (bytes([32, 30, 36]), bytes([236, 228, 210])):
    assert colour in draft, f'the draft view does not show thread colour {tuple(colour)}'
print('draft view: both thread colours shown')
PY
