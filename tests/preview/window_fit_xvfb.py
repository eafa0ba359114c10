#!/usr/bin/env python3
"""The previewer's Fit section driven as a user drives it, under Xvfb (window_click_xvfb.py's
harness): a capture-rig shot of a 3/1 twill of 8 x 6 threads per cm opened in the window with
its swatch made woven, the Fit header opened, a shot that does not exist refused naming it, then
the rig's shot typed in with a short budget and Fit clicked: the fit runs in the background, its
result becomes the edited material, and the panel's repeat is the cloth's thread counts within
3 % (the round trips' bound: the counts are the fit's first stage).

Usage: window_fit_xvfb.py WOVEN_BINARY WRITE_CAPTURE_SHOT_BINARY
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from window_click_xvfb import check, check_panel, run, window_under_xvfb  # noqa: E402


def main(woven, writer):
    with tempfile.TemporaryDirectory(prefix='woven-fit-') as tmp:
        rig = json.loads(subprocess.run([writer, tmp], check=True, capture_output=True, text=True, timeout=120).stdout)
        with window_under_xvfb(woven, tmp, (rig['shot'], '--woven', 'Swatch={}')) as window:
            fit_in_window(window, rig)


def fit_in_window(window, rig):
    m = window.wait('the swatch as the edited material',
                    lambda m: (m['state']['material'] or {}).get('target') == 'Swatch', 60)
    window.click('Fit', 'header')
    m = window.wait('the Fit section open', lambda m: any(i['label'] == 'shot files' for i in m['items']), 30)
    check_panel(m, 'with Fit open')

    # A shot file that is not there: refused, naming it, and nothing applied.
    window.click('shot files', 'input')
    window.type('missing.json')
    window.key('Return')
    window.click('Fit', 'button')
    m = window.wait('the missing shot refused', lambda m: not m['state']['fit']['running']
                    and 'missing.json' in m['state']['fit']['error'], 30)
    check(not m['state']['fit']['applied'], 'a failed fit was applied')
    check('missing.json' in m['state']['status'], f'status "{m["state"]["status"]}" does not name the file')
    print(f'missing shot: {m["state"]["fit"]["error"]}')

    # The rig's shot, 6 s: the fit runs in the background and its material becomes the edited one.
    window.click('shot files', 'input')
    window.key('ctrl+a')
    window.type(rig['shot'])
    window.key('Return')
    window.click('fit seconds', 'input')
    window.key('ctrl+a')
    window.type('6')
    window.key('Return')
    before = window.read()['state']['material']['repeat']
    window.click('Fit', 'button')
    window.wait('the fit to start', lambda m: m['state']['fit']['running'] or m['state']['fit']['applied'], 30)
    m = window.wait('the fit applied', lambda m: m['state']['fit']['applied'], 120)
    state = m['state']
    check(not state['fit']['error'], f'the fit failed: {state["fit"]["error"]}')
    check(state['fit']['loss_points'] >= 2, f'the loss plot has {state["fit"]["loss_points"]} points to draw')
    repeat = state['material']['repeat']
    # One UV unit of the rig's swatch is a metre: threads per cm x 100.
    expected = [100 * n for n in rig['threads_per_cm']]
    check(all(abs(r / e - 1) <= 0.03 for r, e in zip(repeat, expected)),
          f'the fitted repeat {repeat} is not the cloth\'s {expected} within 3 % (it was {before})')
    check(state['status'].startswith('fit: ') and 'applied to Swatch' in state['status'],
          f'status "{state["status"]}"')
    print(f'fitted: repeat {repeat[0]:.0f} x {repeat[1]:.0f} (cloth {expected}); {state["status"]}')


if __name__ == '__main__':
    run(main, sys.argv[1], sys.argv[2])
