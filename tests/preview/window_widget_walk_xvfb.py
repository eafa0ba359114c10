#!/usr/bin/env python3
"""Every control of the material panel acts, or is drawn disabled (issue: "every control acts, or
says why it cannot"). Under Xvfb, on three kinds of cloth: the procedural cloth (a plain weave
of the panel's own parameters), the default scene's denim (from a draft) and the library's tartan
(per-thread colours), the walk nudges each slider, drag, colour and checkbox of the Material
section as a user would (a drag of 40 pixels, a click) and waits for the view to change (the first
frame of the view's refinement, a function of what it shows: the walk need not wait for the rest);
then it presses Render and checks that the final frame changed too, and the same way: where both
mean colours moved by more than MOVED of their size, the two moves point the same way (a positive
dot product). The Undo button must then bring back every parameter as it was (Ctrl+Z is the truth
test's). A control that changes nothing, in the view or the frame, and is not drawn disabled fails.

The Render button renders 1 sample a pixel with the path tracer, not denoised: a frame is a pure
function of the scene and the seed, so any change of it is the material's.

Usage: window_widget_walk_xvfb.py WOVEN_BINARY ASSETS_DIR procedural|denim|tartan
"""
import os
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from window_click_xvfb import Failure, check, run, window_under_xvfb  # noqa: E402
from window_truth_xvfb import drag, scene_in, scroll_to  # noqa: E402

VALUE_KINDS = ('slider', 'drag', 'colour', 'checkbox')
SIZE = ('--width', '640', '--height', '480', '--spp', '1', '--noise-threshold', '0', '--integrator', 'path',
        '--no-denoise')
# A mean colour "moved" by more than this share of its length. The preview may differ from the
# render by a median 5 % a block (the fidelity harness's bound), and how much differs varies with
# the parameter, so smaller moves may go different ways and are not compared (the tartan's c_y
# moved the view's mean up and the frame's down, both by over 1 %, not both by 5 %).
MOVED = 0.05


def view_since(window, frame, timeout=60):
    """The view begun after `frame` (its first full-size frame: checksum and mean), once there is one."""
    m = window.wait(f'a view begun after frame {frame}', lambda m: m['state']['view']['since'] > frame, timeout)
    return m['state']['view']


def material_controls(m):
    """The labels of the Material section's value controls, in the panel's order."""
    items = [i for i in m['items'] if i['window'] == 'woven']
    start = next(n for n, i in enumerate(items) if i['label'] == 'Material' and i['kind'] == 'header')
    return [(i['label'], i['kind'], i['disabled']) for i in items[start + 1:] if i['kind'] in VALUE_KINDS]


def nudge(window, label, kind):
    """A checkbox clicked; a colour's first field (red), a pair's first value, a single slider or
    drag from its middle, dragged 40 pixels."""
    if kind == 'checkbox':
        scroll_to(window, label, kind)
        window.click(label, kind)
        return
    pair = label.endswith('(1/n, 1/m)') or label == 'ends, picks per cm'
    at = 0.15 if kind == 'colour' else 0.25 if pair else 0.5
    drag(window, label, kind, 40, at)


def final_mean(window):
    """The Render button's frame: its mean linear colour. The frame is then hidden again, so that
    the view shows (and refines) the preview."""
    scroll_to(window, 'Render', 'button')
    window.click('Render', 'button')
    m = window.wait('the final frame', lambda m: m['state']['final']['done'] and m['state']['final']['shown'], 180)
    scroll_to(window, 'show the rendered frame', 'checkbox')
    window.click('show the rendered frame', 'checkbox')
    window.wait('the preview shown again', lambda m: not m['state']['final']['shown'], 30)
    return m['state']['final']['mean']


def moved(before, after):
    """The move from one mean colour to another, None where it is under MOVED of the colour's size."""
    d = [a - b for a, b in zip(after, before)]
    size = sum(b * b for b in before) ** 0.5
    return d if sum(x * x for x in d) ** 0.5 > MOVED * size else None


def walk(window, cloth):
    m = window.read()
    controls = material_controls(m)
    check(len(controls) >= 15, f'{cloth}: only {len(controls)} material controls: {controls}')
    view_since(window, -1)
    frame_before = final_mean(window)
    view = window.read()['state']['view']
    view_before = view['mean']
    silent, unrendered, opposite, disabled, unrestored = [], [], [], [], []
    for label, kind, off in controls:
        if off:
            disabled.append(label)
            continue
        m = window.read()
        frame, params = m['state']['frame'], m['state']['material']['params']
        nudge(window, label, kind)
        try:
            changed = window.wait(f'{label} to change the view', lambda m: m['state']['view']['since'] > frame and
                                  m['state']['view']['checksum'] != view['checksum'], 15)['state']['view']
        except Failure:
            changed = None
        print(f'{cloth}: {label}', flush=True)
        if changed is None:
            silent.append(label)
            continue
        view_after = changed['mean']
        frame_after = final_mean(window)
        view_move, frame_move = moved(view_before, view_after), moved(frame_before, frame_after)
        if frame_after == frame_before:
            unrendered.append(label)
        elif view_move and frame_move and sum(a * b for a, b in zip(view_move, frame_move)) <= 0:
            opposite.append(f'{label}: view {view_move}, frame {frame_move}')
        frame = window.read()['state']['frame']
        scroll_to(window, 'Undo', 'button')
        window.click('Undo', 'button')
        # The edit was committed once the control was let go (nothing to redo); the undo makes one.
        m = window.wait('the undo', lambda m: m['state']['history']['redo'], 30)
        if m['state']['material']['params'] != params:
            unrestored.append(label)
        view = view_since(window, frame)
    acted = len(controls) - len(silent) - len(disabled)
    print(f'{cloth}: {acted} controls act, disabled: {disabled}')
    check(not silent, f'{cloth}: controls that change nothing and are not disabled: {silent}')
    check(not unrendered, f'{cloth}: controls that change the view but not the Render button\'s frame: {unrendered}')
    check(not opposite, f'{cloth}: controls that move the view and the frame different ways: {opposite}')
    check(not unrestored, f'{cloth}: Undo did not bring back the parameters after: {unrestored}')


def procedural(tmp, assets):
    return SIZE


def denim(tmp, assets):
    return SIZE + (scene_in(tmp, assets),)


def tartan(tmp, assets):
    return denim(tmp, assets) + ('--woven', 'Cloth={"preset": "tartan"}')


# The three kinds of cloth, each a test of its own (CTest runs them side by side): the window's
# arguments for it.
CLOTHS = {'procedural': ('the procedural cloth', procedural), 'denim': ('the denim draft', denim),
          'tartan': ('the tartan', tartan)}


def main(woven, assets, cloth):
    name, args = CLOTHS[cloth]
    with tempfile.TemporaryDirectory(prefix='woven-walk-') as tmp:
        with window_under_xvfb(woven, tmp, args(tmp, assets)) as window:
            m = window.wait('the first widget map', lambda m: m['state']['frame'] >= 2, 60)
            if cloth == 'tartan':
                check(m['state']['material']['tile_rows'] > 0, f'the tartan did not open: {m["state"]["material"]}')
            walk(window, name)


if __name__ == '__main__':
    run(main, *sys.argv[1:4])
