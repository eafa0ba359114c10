#!/usr/bin/env python3
"""Every control of the material panel acts, or is drawn disabled (issue: "every control acts, or
says why it cannot"). Under Xvfb, on three kinds of cloth: the procedural cloth (a plain weave
of the panel's own parameters), the default scene's denim (from a draft) and the library's tartan
(per-thread colours), the walk nudges each slider, drag, colour and checkbox of the Material
section as a user would (a drag of 40 pixels, a click) and waits for the settled view to change;
the Undo button must then bring back every parameter as it was (Ctrl+Z is the truth test's). A control that changes nothing and is not
drawn disabled fails the test.

Usage: window_widget_walk_xvfb.py WOVEN_BINARY ASSETS_DIR
"""
import os
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from window_click_xvfb import Failure, check, run, window_under_xvfb  # noqa: E402
from window_truth_xvfb import drag, scene_in, scroll_to  # noqa: E402

VALUE_KINDS = ('slider', 'drag', 'colour', 'checkbox')
SIZE = ('--width', '640', '--height', '480')


def settled(window, timeout=60):
    """The checksum of the view once its refinement is complete and a frame has passed."""
    m = window.wait('the settled view', lambda m: m['state']['refinement'] == 9 and m['state']['view_checksum'], timeout)
    return m['state']['view_checksum']


def material_controls(m):
    """The labels of the Material section's value controls, in the panel's order."""
    items = [i for i in m['items'] if i['window'] == 'woven']
    start = next(n for n, i in enumerate(items) if i['label'] == 'Material' and i['kind'] == 'header')
    return [(i['label'], i['kind'], i['disabled']) for i in items[start + 1:] if i['kind'] in VALUE_KINDS]


def nudge(window, label, kind):
    """A checkbox clicked; a colour's first field (red), a pair's first value, a single slider or
    drag from its middle, dragged 40 pixels."""
    if kind == 'checkbox':
        window.click(label, kind)
        return
    at = 0.15 if kind == 'colour' else 0.25 if label.endswith('(1/n, 1/m)') else 0.5
    drag(window, label, kind, 40, at)


def walk(window, cloth):
    m = window.read()
    controls = material_controls(m)
    check(len(controls) >= 15, f'{cloth}: only {len(controls)} material controls: {controls}')
    silent, disabled, unrestored = [], [], []
    for label, kind, off in controls:
        if off:
            disabled.append(label)
            continue
        before = settled(window)
        params = window.read()['state']['material']['params']
        nudge(window, label, kind)
        deadline = time.monotonic() + 15
        after = before
        while after == before and time.monotonic() < deadline:
            after = settled(window)
        if after == before:
            silent.append(label)
            continue
        scroll_to(window, 'Undo', 'button')
        window.click('Undo', 'button')
        # The edit was committed once the control was let go (nothing to redo); the undo makes one.
        m = window.wait('the undo', lambda m: m['state']['history']['redo'], 30)
        if m['state']['material']['params'] != params:
            unrestored.append(label)
    acted = len(controls) - len(silent) - len(disabled)
    print(f'{cloth}: {acted} controls act, disabled: {disabled}')
    check(not silent, f'{cloth}: controls that change nothing and are not disabled: {silent}')
    check(not unrestored, f'{cloth}: Undo did not bring back the parameters after: {unrestored}')


def main(woven, assets):
    with tempfile.TemporaryDirectory(prefix='woven-walk-') as tmp:
        with window_under_xvfb(woven, tmp, SIZE) as window:
            window.wait('the first widget map', lambda m: m['state']['frame'] >= 2, 60)
            walk(window, 'the procedural cloth')
        with window_under_xvfb(woven, tmp, SIZE + (scene_in(tmp, assets),)) as window:
            window.wait('the first widget map', lambda m: m['state']['frame'] >= 2, 60)
            walk(window, 'the denim draft')
        tartan = ('--woven', 'Cloth={"preset": "tartan"}')
        with window_under_xvfb(woven, tmp, SIZE + (scene_in(tmp, assets),) + tartan) as window:
            m = window.wait('the first widget map', lambda m: m['state']['frame'] >= 2, 60)
            check(m['state']['material']['tile_rows'] > 0, f'the tartan did not open: {m["state"]["material"]}')
            walk(window, 'the tartan')

if __name__ == '__main__':
    run(main, sys.argv[1], sys.argv[2])
