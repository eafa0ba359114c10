#!/usr/bin/env python3
"""The window's Rendered mode on the default scene, driven under Xvfb as a user drives it
(issue 47):

- R switches the view to the path tracer, whose passes arrive until it is converged (the Render
  button's spp, here 24 at 160x120 so that the test is short), denoised;
- a slider dragged starts the view again: its restart count rises and its sample count drops, and
  once converged again it shows the new material (another mean colour);
- the environment (an image with one bright window) turned by the Lights section's rotation
  slider starts it again too, and lights the cloth from elsewhere;
- R again goes back to the GLSL view, and the path tracer stops.

Nothing here is timed: every wait is for a state the widget map reports.

Usage: window_rendered_xvfb.py WOVEN_BINARY ASSETS_DIR
"""
import json
import os
import struct
import sys
import tempfile
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from window_click_xvfb import check, run, window_under_xvfb  # noqa: E402
from window_truth_xvfb import drag, scroll_to  # noqa: E402

SIZE, SPP = (160, 120), 24


def small_scene(tmp, assets):
    """The default scene as a file of tmp's, its render (and so the view's passes) small."""
    with open(os.path.join(assets, 'default_scene.json')) as f:
        scene = json.load(f)
    scene['gltf'] = os.path.join(assets, scene['gltf'])
    scene['materials']['Cloth']['wif'] = os.path.join(assets, scene['materials']['Cloth']['wif'])
    scene['render'] = {'width': SIZE[0], 'height': SIZE[1], 'spp': SPP}
    path = os.path.join(tmp, 'denim.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    return path


def sky_with_a_window(tmp):
    """An 8-bit equirectangular PNG: a dim sky, one bright window towards +x above the horizon."""
    width, height = 64, 32
    rows = b''
    for y in range(height):
        row = bytes(255 if abs(x / width - 0.25) < 0.06 and abs(y / height - 0.35) < 0.1 else 30
                    for x in range(width) for _ in range(3))
        rows += b'\x00' + row

    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)
    path = os.path.join(tmp, 'sky.png')
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0)) +
                chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b''))
    return path


def restarted_and_converged(window, before, what):
    """Waits for the view to start again (fewer samples than converged) and converge; returns its
    state, which must show another image than `before`."""
    m = window.wait(f'the view restarted after {what}',
                    lambda m: m['state']['rendered']['restarts'] > before['restarts'] and
                    m['state']['rendered']['samples'] < SPP, 60)
    print(f'{what}: restarted, {m["state"]["rendered"]["status"]}')
    m = window.wait(f'the view converged after {what}', converged, 240)
    after = m['state']['rendered']
    check(after['mean'] != before['mean'], f'after {what} the view still shows the old image: mean {after["mean"]}')
    print(f'{what}: converged again, {after["status"]}, mean {after["mean"]}')
    return after


def converged(m):
    r = m['state']['rendered']
    return r['converged'] and r['samples'] == SPP and r['denoised_at'] == SPP and r['mean'] is not None


def main(woven, assets):
    with tempfile.TemporaryDirectory(prefix='woven-rendered-') as tmp, \
            window_under_xvfb(woven, tmp, ('--integrator', 'path', '--environment', sky_with_a_window(tmp),
                                           small_scene(tmp, assets))) as window:
        m = window.wait('the first widget map', lambda m: m['state']['frame'] >= 2, 60)
        check(not m['state']['rendered']['on'], 'the view started rendered without --viewport rendered')

        # R: the path tracer's view, refined to the Render button's spp and denoised.
        window.key('r')
        m = window.wait('the rendered view on', lambda m: m['state']['rendered']['on'], 30)
        m = window.wait('the rendered view converged', converged, 240)
        before = m['state']['rendered']
        check(before['size'] == list(SIZE) and before['image'] == list(SIZE), f'the view rendered {before}')
        check(before["status"].startswith(f"{SPP}/{SPP} spp,") and before["status"].endswith("converged"),
              f'status line "{before["status"]}"')
        print(f'rendered: {before["status"]}, mean {before["mean"]}')

        # A slider dragged: the view starts again, and shows the new cloth once converged.
        drag(window, 'weft e_x (along yarn)', 'drag', 160)
        after = restarted_and_converged(window, before, 'a slider')

        # The environment turned: the window lights the cloth from elsewhere.
        scroll_to(window, 'Lights', 'header')
        window.click('Lights', 'header')
        window.wait('the Lights section open', lambda m: any(i['label'] == 'rotation' for i in m['items']), 30)
        drag(window, 'rotation', 'slider', 80)
        restarted_and_converged(window, after, 'the environment turned')

        # R again: back to the GLSL view; the path tracer stops.
        window.key('r')
        m = window.wait('the GLSL view back', lambda m: not m['state']['rendered']['on'], 30)
        check(m['state']['rendered']['samples'] == 0, f'the path tracer kept its frame: {m["state"]["rendered"]}')
        print('R: back to the GLSL view')


if __name__ == '__main__':
    run(main, sys.argv[1], sys.argv[2])
