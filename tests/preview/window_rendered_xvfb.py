#!/usr/bin/env python3
"""The window's Rendered mode on the default scene, driven under Xvfb as a user drives it
(issue 47):

- R switches the view to the path tracer, whose passes arrive until it is converged (the Render
  button's spp, here 24 at 160x120 so that the test is short), denoised;
- a slider dragged starts the view again: its restart count rises and its sample count drops, and
  once converged again it shows the new material (another mean colour);
- R again goes back to the GLSL view, and the path tracer stops.

Nothing here is timed: every wait is for a state the widget map reports.

Usage: window_rendered_xvfb.py WOVEN_BINARY ASSETS_DIR
"""
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from window_click_xvfb import check, run, window_under_xvfb  # noqa: E402
from window_truth_xvfb import scroll_to  # noqa: E402

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


def converged(m):
    r = m['state']['rendered']
    return r['converged'] and r['samples'] == SPP and r['denoised_at'] == SPP and r['mean'] is not None


def main(woven, assets):
    with tempfile.TemporaryDirectory(prefix='woven-rendered-') as tmp, \
            window_under_xvfb(woven, tmp, ('--integrator', 'path', small_scene(tmp, assets))) as window:
        m = window.wait('the first widget map', lambda m: m['state']['frame'] >= 2, 60)
        check(not m['state']['rendered']['on'], 'the view started rendered without --viewport rendered')

        # R: the path tracer's view, refined to the Render button's spp and denoised.
        window.key('r')
        m = window.wait('the rendered view on', lambda m: m['state']['rendered']['on'], 30)
        m = window.wait('the rendered view converged', converged, 240)
        before = m['state']['rendered']
        check(before['size'] == list(SIZE) and before['image'] == list(SIZE), f'the view rendered {before}')
        check('converged' in before['status'] and f'{SPP}/{SPP} spp' in before['status'],
              f'status line "{before["status"]}"')
        print(f'rendered: {before["status"]}, mean {before["mean"]}')

        # A slider dragged: the view starts again, and shows the new cloth once converged.
        scroll_to(window, 'weft e_x (along yarn)', 'drag')
        x0, y0, x1, y1 = window.item('weft e_x (along yarn)', 'drag')['frame']
        wx, wy = window.map['state']['window']['pos']
        window.xdotool('mousemove', str(int(wx + (x0 + x1) / 2)), str(int(wy + (y0 + y1) / 2)))
        window.frames()
        window.xdotool('mousedown', '1')
        window.frames()
        for _ in range(4):
            window.xdotool('mousemove_relative', '--', '40', '0')
            window.frames()
        window.xdotool('mouseup', '1')
        m = window.wait('the view restarted', lambda m: m['state']['rendered']['restarts'] > before['restarts'] and
                        m['state']['rendered']['samples'] < SPP, 60)
        print(f'restarted: {m["state"]["rendered"]["status"]}')
        m = window.wait('the view converged again', converged, 240)
        after = m['state']['rendered']
        check(after['mean'] != before['mean'], f'the view still shows the old cloth: mean {after["mean"]}')
        print(f'converged again: {after["status"]}, mean {after["mean"]}')

        # R again: back to the GLSL view; the path tracer stops.
        window.key('r')
        m = window.wait('the GLSL view back', lambda m: not m['state']['rendered']['on'], 30)
        check(m['state']['rendered']['samples'] == 0, f'the path tracer kept its frame: {m["state"]["rendered"]}')
        print('R: back to the GLSL view')


if __name__ == '__main__':
    run(main, sys.argv[1], sys.argv[2])
