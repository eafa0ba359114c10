#!/usr/bin/env python3
"""The previewer's window driven as a user drives it, under Xvfb: real X input events (XTest,
through xdotool) on the widgets whose places the window writes each frame (--widget-map).

It checks, at the default 1280x800 window: no two widgets share an ImGui ID, with every section
open (the Lights header is clicked open); no label runs past the panel's edge; the Render button
is on screen without scrolling; the render size fields take "160 Tab 120 Enter" as 160x120 and say
so in the status line when a value is clamped; the Render button renders (the final frame arrives
at 160x120); Save PNG writes that frame; the Fabrics menu lists the library and denim chosen in
it becomes the edited material at its thread counts, measured in the panel; SIGTERM closes the
window. While a text field has the focus, the view is drawn at full resolution.

Usage: window_click_xvfb.py WOVEN_BINARY
"""
import contextlib
import json
import os
import select
import signal
import struct
import subprocess
import sys
import tempfile
import time
import zlib

WINDOW = (1280, 800)
# The Render button's settings come from the command line but for the size, which the test types.
DEFAULT_ARGS = ('--spp', '4', '--integrator', 'path')


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def png_pixels(path):
    """(width, height, rows of RGB bytes) of an 8-bit RGB or RGBA PNG."""
    data = open(path, 'rb').read()
    check(data[:8] == b'\x89PNG\r\n\x1a\n', f'{path} is not a PNG')
    pos, idat, header = 8, b'', None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            header = struct.unpack('>IIBBBBB', body)
        if kind == b'IDAT':
            idat += body
        pos += 12 + length
    width, height, depth, colour_type = header[:4]
    check(depth == 8 and colour_type in (2, 6), f'unexpected PNG format {depth} {colour_type}')
    channels = 3 if colour_type == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
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
        rows.append(bytes(b for x in range(width) for b in line[x * channels:x * channels + 3]))
        prev = line
    return width, height, rows


class Window:
    def __init__(self, woven, tmp, display, args):
        self.tmp = tmp
        self.map_path = os.path.join(tmp, 'map.json')
        # A window before this one in the same folder left its map: not this window's.
        if os.path.exists(self.map_path):
            os.remove(self.map_path)
        self.env = dict(os.environ, DISPLAY=f':{display}', LIBGL_ALWAYS_SOFTWARE='1')
        self.stderr = open(os.path.join(tmp, 'woven.stderr'), 'w+')
        # The window keeps its default 1280x800.
        self.process = subprocess.Popen(
            [woven, 'preview', *args, '--frames', '0', '--widget-map', self.map_path],
            cwd=tmp, env=self.env, stdout=subprocess.DEVNULL, stderr=self.stderr)
        self.map = None

    def read(self):
        check(self.process.poll() is None, f'woven preview exited ({self.process.returncode}): {self.errors()}')
        try:
            with open(self.map_path) as f:
                self.map = json.load(f)
        except (OSError, ValueError):
            pass
        return self.map

    def errors(self):
        self.stderr.flush()
        self.stderr.seek(0)
        return self.stderr.read()

    def wait(self, what, condition, timeout):
        """Waits until condition(map) holds, reading the map each 50 ms, at most timeout seconds."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            m = self.read()
            if m is not None and condition(m):
                return m
            time.sleep(0.05)
        state = self.map['state'] if self.map else None
        raise Failure(f'timed out after {timeout} s waiting for {what}; last state: {state}')

    def frame(self):
        return self.read()['state']['frame']

    def frames(self, n=2, timeout=60):
        """Waits until the window has drawn n more frames, so it saw what was sent before."""
        start = self.frame()
        self.wait(f'{n} frames', lambda m: m['state']['frame'] >= start + n, timeout)

    def item(self, label, kind=None):
        found = [i for i in self.map['items'] if i['label'] == label and (kind is None or i['kind'] == kind)]
        check(len(found) == 1, f'{len(found)} widgets "{label}" ({kind}) in the map, expected one')
        return found[0]

    def xdotool(self, *args):
        subprocess.run(['xdotool', *args], env=self.env, check=True, timeout=10)

    def move_to(self, x, y):
        """The pointer to (x, y), by way of the pixel beside it: a resting window draws on input
        alone, and a move to where the pointer already is sends none."""
        self.xdotool('mousemove', str(x + 1), str(y))
        self.xdotool('mousemove', str(x), str(y))
        self.frames()

    def click(self, label, kind=None, at_frame=True):
        """A left click at the centre of the widget's frame (a field's box, not its label)."""
        x0, y0, x1, y1 = self.item(label, kind)['frame' if at_frame else 'rect']
        wx, wy = self.map['state']['window']['pos']
        self.move_to(int(wx + (x0 + x1) / 2), int(wy + (y0 + y1) / 2))
        self.xdotool('mousedown', '1')
        self.frames()
        self.xdotool('mouseup', '1')
        self.frames()

    def type(self, text):
        self.xdotool('type', '--delay', '20', text)
        self.frames()

    def key(self, name):
        # As a user presses it: down and up again within a few milliseconds, quicker than a
        # software-rendered frame.
        self.xdotool('key', name)
        self.frames()

    def close(self):
        self.process.send_signal(signal.SIGTERM)
        try:
            return self.process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            raise Failure('the window did not close within 30 s of SIGTERM')


def check_panel(m, where):
    """No ID clashes; every label of the panel within its visible width."""
    check(not m['clashes'], f'{where}: ImGui ID clashes: {m["clashes"]}')
    clip = m['windows']['woven']['clip']
    for item in m['items']:
        if item['window'] != 'woven':
            continue
        check(item['rect'][2] <= clip[2] + 0.5,
              f'{where}: "{item["label"]}" is cut at the panel\'s edge: it ends at x = {item["rect"][2]}, '
              f'the panel shows up to {clip[2]}')


def start_xvfb():
    """An X server on a display it chose free itself (-displayfd: tests may start servers at the
    same time), and the display; the caller kills it."""
    read_end, write_end = os.pipe()
    xvfb = subprocess.Popen(['Xvfb', '-displayfd', str(write_end), '-screen', '0', '1600x1000x24', '-nolisten', 'tcp'],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, pass_fds=(write_end,))
    os.close(write_end)
    with os.fdopen(read_end) as announced:
        ready, _, _ = select.select([announced], [], [], 10)
        display = announced.readline().strip() if ready else ''
    if not display.isdigit():
        xvfb.kill()
        xvfb.wait()
        raise Failure('Xvfb did not start within 10 s')
    return xvfb, int(display)


@contextlib.contextmanager
def window_under_xvfb(woven, tmp, args=DEFAULT_ARGS):
    """The window on its own X server; at the end it must close on SIGTERM with status 0. Whatever
    happens, the window and the server are stopped."""
    xvfb, display = start_xvfb()
    window = None
    try:
        window = Window(os.path.abspath(woven), tmp, display, args)
        yield window
        code = window.close()
        check(code == 0, f'woven preview exited with {code} on SIGTERM: {window.errors()}')
        print('closed on SIGTERM')
    finally:
        if window is not None and window.process.poll() is None:
            window.process.kill()
            window.process.wait()
        xvfb.kill()
        xvfb.wait()


def run(main, *args):
    """main(*args) as a test's process: CTest's timeout (SIGTERM) and Ctrl-C still go through its
    cleanup; a Failure is printed and exits 1."""
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(1))
    try:
        main(*args)
    except Failure as e:
        print(f'FAILED: {e}', file=sys.stderr)
        sys.exit(1)


def main(woven):
    with tempfile.TemporaryDirectory(prefix='woven-click-') as tmp, window_under_xvfb(woven, tmp) as window:
        m = window.wait('the first widget map', lambda m: m['state']['frame'] >= 2, 60)
        check(m['state']['window']['size'] == list(WINDOW), f'window size {m["state"]["window"]["size"]}')

        # Every widget, every section open: the Lights header is closed at start.
        check_panel(m, 'at start')
        window.click('Lights', 'header')
        m = window.wait('the Lights section open', lambda m: any(i['label'] == 'environment' for i in m['items']), 30)
        check_panel(m, 'with Lights open')
        print(f'{len(m["items"])} widgets, no ID clash, no label cut')

        # The Render button on screen at 1280x800 without scrolling.
        render = window.item('Render', 'button')
        x0, y0, x1, y1 = render['rect']
        check(render['visible'] and 0 <= x0 and x1 <= WINDOW[0] and 0 <= y0 and y1 <= WINDOW[1],
              f'the Render button at {render["rect"]} is not within the {WINDOW} window')
        clip = m['windows']['woven']['clip']
        check(clip[1] <= y0 and y1 <= clip[3], f'the Render button at {render["rect"]} needs scrolling (panel {clip})')

        # The render size: a width too large is clamped, and the status line says so.
        window.click('##width', 'input')
        window.type('160120')
        window.key('Return')
        m = window.wait('the clamped width', lambda m: m['state']['render']['width'] == 16384, 30)
        check('render width 160120 is out of range' in m['state']['status'],
              f'clamping said nothing: status "{m["state"]["status"]}"')
        # Tab moves from the width to the height.
        window.click('##width', 'input')
        window.type('160')
        # A focused text field is no interaction: the view is drawn at full size while one types.
        window.frames(4)
        state = window.read()['state']
        check(not state['interacting'] and state['resolution_scale'] == 1.0,
              f'with a text field focused the view is drawn at {state["resolution_scale"]:.0%}')
        window.key('Tab')
        window.type('120')
        window.key('Return')
        m = window.wait('the render size 160x120', lambda m: (m['state']['render']['width'],
                                                             m['state']['render']['height']) == (160, 120), 30)
        print(f'render size typed: 160 Tab 120 -> {m["state"]["render"]["width"]}x{m["state"]["render"]["height"]}')

        # The Render button: the final frame arrives.
        window.click('Render', 'button')
        window.wait('the final render to start', lambda m: m['state']['final']['running'] or m['state']['final']['done'], 30)
        m = window.wait('the final frame', lambda m: m['state']['final']['done'], 120)
        final = m['state']['final']
        check(final['image'] == [160, 120], f'final frame {final["image"]}, expected 160x120')
        check(final['shown'], 'the final frame is not shown')
        print(f'final frame arrived: {final["progress"]}')

        # Save PNG writes it.
        window.click('Save PNG', 'button')
        png = os.path.join(tmp, 'render.png')
        m = window.wait('"saved render.png"', lambda m: m['state']['status'] == 'saved render.png', 30)
        check(os.path.exists(png), 'render.png was not written')
        width, height, rows = png_pixels(png)
        check((width, height) == (160, 120), f'render.png is {width}x{height}, expected 160x120')
        brightest = max(max(row) for row in rows)
        colours = {row[i:i + 3] for row in rows for i in range(0, len(row), 3)}
        check(brightest > 40 and len(colours) > 50, f'render.png is (nearly) black: max {brightest}, {len(colours)} colours')
        print(f'render.png: {width}x{height}, {len(colours)} colours')
        check_panel(m, 'after the render')

        # The Fabrics menu: denim chosen in its combo becomes the edited material at denim's thread
        # counts on the 2 m procedural cloth, and the panel measures it as `woven fabrics` does.
        # Scrolled until the whole combo is within the panel's clip, where a click reaches it.
        while not (window.item('fabric', 'combo')['visible'] and
                   m['windows']['woven']['clip'][1] <= window.item('fabric', 'combo')['frame'][1] and
                   window.item('fabric', 'combo')['frame'][3] <= m['windows']['woven']['clip'][3]):
            x0, y0, x1, y1 = m['windows']['woven']['clip']
            wx, wy = m['state']['window']['pos']
            window.xdotool('mousemove', str(int(wx + (x0 + x1) / 2)), str(int(wy + (y0 + y1) / 2)))
            window.xdotool('click', '5')
            m = window.read()
            window.frames()
        window.click('fabric', 'combo')
        # On its first frame a popup is measured, hidden, and then placed within the window.
        m = window.wait('the Fabrics menu open', lambda m: any(i['label'] == 'denim' and i['kind'] == 'selectable'
                                                                and i['visible'] for i in m['items']), 30)
        window.frames()
        names = [i['label'] for i in m['items'] if i['kind'] == 'selectable' and i['window'] != 'woven']
        check(len(names) >= 12, f'the Fabrics menu lists {names}')
        check_panel(m, 'with the Fabrics menu open')
        window.click('denim', 'selectable')
        m = window.wait('denim chosen', lambda m: m['state']['material']['fabric'] == 'denim', 30)
        material = m['state']['material']
        repeat, measures = material['repeat'], material['measures']
        # The cloth spans 2 m of x and z over its UVs, and its waves add a few percent of length.
        check(all(200 * n <= r <= 1.05 * 200 * n for r, n in zip(repeat, (25, 16))),
              f'denim (25 x 16 per cm) on the 2 m cloth has repeat {repeat}')
        check('25 x 16 threads/cm' in measures and '381 g/m2' in measures and 'about' not in measures
              and '0.97 cloth' in measures,
              f'the panel measures denim as "{measures}"')
        check(material['warp_color'][2] > material['warp_color'][0], f'denim\'s warp is not indigo: {material["warp_color"]}')
        check(m['state']['status'].startswith('fabric denim'), f'status "{m["state"]["status"]}"')
        print(f'Fabrics menu: {len(names)} fabrics; denim chosen: repeat {repeat[0]:.0f} x {repeat[1]:.0f}, {measures}')

        check('ID clash' not in window.errors(), f'clash warnings on stderr: {window.errors()}')


if __name__ == '__main__':
    run(main, sys.argv[1])
