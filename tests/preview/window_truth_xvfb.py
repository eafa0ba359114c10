#!/usr/bin/env python3
"""The previewer's window on the default scene (denim from a draft), driven under Xvfb as a user
drives it (issue: "what you tune is what you get"):

- left alone, the window rests: under 2 % of a core over 3 s once its view has settled;
- a weave chosen in the panel replaces the draft's weave (the draft view closes and the status
  line says so; that the Render button's frame follows is held by test_draft's layering test,
  through the same materialFromJson());
- a slider moved after a render hides the stale final frame;
- Ctrl+Z and Ctrl+Shift+Z undo and redo a material edit;
- Save, twice, writes a scene file that `woven render` renders bit for bit as the Render button;
  Save As writes the file typed into "scene file" (Save then writes there), which renders the same,
  and refuses the scene's own file and a name that is no woven scene file;
- Export's warnings are listed in the window's Messages.

Usage: window_truth_xvfb.py WOVEN_BINARY ASSETS_DIR
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from window_click_xvfb import Failure, check, png_pixels, run, window_under_xvfb  # noqa: E402

IDLE_CPU_LIMIT = 0.02  # of one core


def cpu_seconds(pid):
    """User + system CPU time of the process, from /proc (clock ticks)."""
    with open(f'/proc/{pid}/stat') as f:
        fields = f.read().rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')


def rested(window, quiet=1.5, timeout=90):
    """Waits until no frame was drawn for `quiet` seconds."""
    deadline = time.monotonic() + timeout
    last, since = window.frame(), time.monotonic()
    while time.monotonic() < deadline:
        time.sleep(0.1)
        frame = window.frame()
        if frame != last:
            last, since = frame, time.monotonic()
        elif time.monotonic() - since >= quiet:
            return
    raise Failure(f'the window kept drawing for {timeout} s with nothing to do')


def scroll_to(window, label, kind):
    """Scrolls the panel (the mouse wheel over it) until the widget is on screen: as many wheel
    clicks at once as its distance needs at the step the clicks before moved it (one to start),
    as a hand spins the wheel, so that a long way costs the window a few frames, not one a click."""
    step = None
    for _ in range(40):
        item = window.item(label, kind)
        clip = window.map['windows']['woven']['clip']
        top, bottom = item['frame'][1], item['frame'][3]
        if item['visible'] and clip[1] <= top and bottom <= clip[3]:
            return
        down = top > clip[1]
        distance = bottom - clip[3] if down else clip[1] - top
        clicks = max(1, min(20, math.ceil(distance / step))) if step else 1
        wx, wy = window.map['state']['window']['pos']
        window.xdotool('mousemove', str(int(wx + (clip[0] + clip[2]) / 2)), str(int(wy + (clip[1] + clip[3]) / 2)))
        window.xdotool('click', '--repeat', str(clicks), '--delay', '1', '5' if down else '4')
        window.frames()
        moved = abs(window.item(label, kind)['frame'][1] - top)
        if moved > 0:
            step = moved / clicks
    raise Failure(f'"{label}" could not be scrolled into view')


def drag(window, label, kind, dx, at=0.5):
    """Drags the widget's frame `dx` pixels to the right from `at` of its width, in four steps, as a
    hand does."""
    scroll_to(window, label, kind)
    x0, y0, x1, y1 = window.item(label, kind)['frame']
    wx, wy = window.map['state']['window']['pos']
    window.move_to(int(wx + x0 + (x1 - x0) * at), int(wy + (y0 + y1) / 2))
    window.xdotool('mousedown', '1')
    window.frames()
    for _ in range(4):
        window.xdotool('mousemove_relative', '--', str(dx // 4), '0')
        window.frames()
    window.xdotool('mouseup', '1')
    window.frames()


def render_and_save(window, tmp):
    """The Render button's frame, saved by Save PNG to its default path beside the scene: its pixels."""
    scroll_to(window, 'Render', 'button')
    window.click('Render', 'button')
    window.wait('the final frame', lambda m: m['state']['final']['done'] and m['state']['final']['shown'], 180)
    scroll_to(window, 'Save PNG', 'button')
    window.click('Save PNG', 'button')
    path = os.path.join(tmp, 'denim-render.png')
    window.wait('"saved denim-render.png"', lambda m: m['state']['status'] == f'saved {path}', 30)
    return png_pixels(path)[2]


def settle_layout(window):
    """The frame that took the last press drew the status line above before the press changed it:
    the panel's layout is the next frame's (a resting window draws one on an input)."""
    window.xdotool('mousemove_relative', '1', '0')
    window.frames()


def save_as(window, path):
    """`path` typed into the "scene file" field in place of what it held, then Save As pressed."""
    settle_layout(window)
    scroll_to(window, 'scene file', 'input')
    window.click('scene file', 'input')
    # Ctrl held across frames: a Ctrl+A within one software frame may reach ImGui without its Ctrl.
    window.xdotool('keydown', 'ctrl')
    window.frames()
    window.key('a')
    window.xdotool('keyup', 'ctrl')
    window.frames()
    window.type(path)
    scroll_to(window, 'Save As', 'button')
    window.click('Save As', 'button')


def scene_in(tmp, assets):
    """The default scene as a file of tmp's, naming the assets by their absolute paths: the window's
    outputs go beside the scene."""
    with open(os.path.join(assets, 'default_scene.json')) as f:
        scene = json.load(f)
    scene['gltf'] = os.path.join(assets, scene['gltf'])
    scene['materials']['Cloth']['wif'] = os.path.join(assets, scene['materials']['Cloth']['wif'])
    path = os.path.join(tmp, 'denim.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    return path


def main(woven, assets):
    with tempfile.TemporaryDirectory(prefix='woven-truth-') as tmp, \
            window_under_xvfb(woven, tmp, ('--spp', '2', '--integrator', 'path', scene_in(tmp, assets))) as window:
        m = window.wait('the first widget map', lambda m: m['state']['frame'] >= 2, 60)
        check(m['state']['material']['draft_open'], 'the default denim did not open its draft')

        # A software-rendered frame of this scene may take a second or more: the measurement
        # counts once no frame was drawn during it.
        for attempt in range(10):
            rested(window)
            frame, before = window.frame(), cpu_seconds(window.process.pid)
            time.sleep(3.0)
            used = (cpu_seconds(window.process.pid) - before) / 3.0
            if window.frame() == frame:
                break
        print(f'idle: {used:.1%} of a core, frame {window.frame()}')
        check(used < IDLE_CPU_LIMIT, f'the resting window used {used:.1%} of a core (at most {IDLE_CPU_LIMIT:.0%})')

        render_and_save(window, tmp)

        # A slider moved: the denim's final frame is stale, and hidden.
        drag(window, 'weft e_x (along yarn)', 'drag', 40)
        m = window.wait('the final frame hidden', lambda m: not m['state']['final']['shown'], 30)
        print('a slider moved after Render hides the final frame')

        # A weave chosen over the draft: sateen (1,4,2).
        scroll_to(window, 'weave preset', 'combo')
        window.click('weave preset', 'combo')
        window.wait('the weave presets listed', lambda m: any(i['label'] == 'sateen (1,4,2)' and i['visible']
                                                               for i in m['items']), 30)
        window.frames()
        window.click('sateen (1,4,2)', 'selectable')
        m = window.wait('the sateen chosen', lambda m: m['state']['material']['pattern'] == [1, 4, 2], 30)
        material = m['state']['material']
        check(material['tile_rows'] == 0 and not material['draft_open'],
              f'the draft\'s tile or view stayed: {material}')
        check('replaces the draft' in m['state']['status'], f'status "{m["state"]["status"]}"')
        print('sateen chosen over the denim draft: the draft replaced, and said so')

        # Undo and redo (Ctrl+Z, Ctrl+Shift+Z): the draft's weave, and its view, come back; then the sateen.
        window.key('ctrl+z')
        m = window.wait('the draft back', lambda m: m['state']['material']['tile_rows'] > 0, 30)
        check(m['state']['material']['draft_open'] and m['state']['history']['redo'],
              f'undo did not bring the draft back: {m["state"]["material"]}, {m["state"]["history"]}')
        window.key('ctrl+shift+z')
        m = window.wait('the sateen again', lambda m: m['state']['material']['pattern'] == [1, 4, 2] and
                        m['state']['material']['tile_rows'] == 0, 30)
        print('Ctrl+Z brought the draft back, Ctrl+Shift+Z the sateen')

        # The Render button's frame of the sateen, then Save, twice: a woven scene file beside the
        # scene, naming its glTF, with the sateen and the Render button's settings, that `woven
        # render` renders bit for bit as the button did.
        button = render_and_save(window, tmp)
        saved = os.path.join(tmp, 'denim-tuned.json')
        for time_ in ('first', 'second'):
            scroll_to(window, 'Save', 'button')
            window.click('Save', 'button')
            window.wait(f'the {time_} save', lambda m: m['state']['status'] == f'saved {saved}', 30)
            with open(saved) as f:
                written = json.load(f)
            check(os.path.isabs(written['gltf']) or os.path.exists(os.path.join(tmp, written['gltf'])),
                  f'{saved} names a glTF that is not there: {written["gltf"]}')
            check(written['materials']['Cloth']['pattern'] == [1, 4, 2] and 'tile' not in written['materials']['Cloth'],
                  f'{saved} does not hold the sateen: {written["materials"]["Cloth"]}')
            check(written['render']['spp'] == 2 and written['render']['integrator'] == 'path',
                  f'{saved} does not hold the Render button\'s settings: {written["render"]}')
            window.frames()
        result = subprocess.run([woven, 'render', saved, '-o', os.path.join(tmp, 'saved.png')],
                                capture_output=True, text=True, timeout=300)
        check(result.returncode == 0, f'woven render {saved} failed: {result.stderr}')
        rendered = png_pixels(os.path.join(tmp, 'saved.png'))[2]
        check(rendered == button, f'woven render {os.path.basename(saved)} differs from the Render button\'s frame')
        print(f'saved twice to {os.path.basename(saved)}, which woven render renders as the Render button did')

        # Save As: the path typed into "scene file". Refused over the scene's own file (an input)
        # and into a name that is no woven scene file, each in the status line, the file untouched;
        # then a new file in another folder, which Save writes again and woven render renders as
        # the Render button did.
        scene_file, image = os.path.join(tmp, 'denim.json'), os.path.join(tmp, 'denim-render.png')
        for path, why in ((scene_file, 'the scene reads this file'), (image, 'not a woven scene file name')):
            with open(path, 'rb') as f:
                before = f.read()
            save_as(window, path)
            window.wait(f'Save As over {os.path.basename(path)} refused',
                        lambda m: m['state']['status'].startswith(f'{path}: {why}'), 30)
            with open(path, 'rb') as f:
                check(f.read() == before, f'Save As changed {path}')
        os.makedirs(os.path.join(tmp, 'chosen'))
        chosen = os.path.join(tmp, 'chosen', 'sateen.json')
        save_as(window, chosen)
        window.wait('Save As', lambda m: m['state']['status'] == f'saved {chosen}', 30)
        os.remove(chosen)
        settle_layout(window)
        scroll_to(window, 'Save', 'button')
        window.click('Save', 'button')
        window.wait('Save to the file Save As chose', lambda m: os.path.exists(chosen), 30)
        result = subprocess.run([woven, 'render', chosen, '-o', os.path.join(tmp, 'chosen.png')],
                                capture_output=True, text=True, timeout=300)
        check(result.returncode == 0, f'woven render {chosen} failed: {result.stderr}')
        check(png_pixels(os.path.join(tmp, 'chosen.png'))[2] == button,
              f'woven render of the file Save As wrote differs from the Render button\'s frame')
        print('Save As refused the scene file and a .png, wrote chosen/sateen.json, which renders as the Render button did')

        # Export: what the command line would warn of is in the window's Messages, not only on stderr.
        exported = os.path.join(tmp, 'denim-export.glb')  # the default: beside the scene
        scroll_to(window, 'Export', 'button')
        window.click('Export', 'button')
        m = window.wait('the export', lambda m: m['state']['status'].startswith(f'exported {exported}'), 120)
        check('see Messages' in m['state']['status'] and any(exported in line for line in m['state']['messages']),
              f'the export\'s warnings are not in the window: status "{m["state"]["status"]}", {m["state"]["messages"]}')
        window.wait('the Messages header', lambda m: any(i['label'].startswith('Messages (') for i in m['items']), 30)
        print(f'exported with {len(m["state"]["messages"])} warnings shown under Messages')

if __name__ == '__main__':
    run(main, sys.argv[1], sys.argv[2])
