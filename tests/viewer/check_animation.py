#!/usr/bin/env python3
"""Checks kvd animate against kvd simulate's trace:

  * the SVG film has one picture per sampled frame and one per batch, shown in
    turn (each picture's time window follows the previous one's), and the
    picture held after batch k names every certificate the trace lists as
    failing in batch k, with its exact time: every event appears;
  * with ffmpeg, the MP4 and the GIF hold as many frames as the SVG shows.

usage: check_animation.py KVD OUTDIR SCENE VIEW [EVENTS]
Exit 0 when every check passes, 1 otherwise.
"""
import os
import re
import shutil
import subprocess
import sys

from check_page import fail, trace_batches  # the trace's batches, as the viewer test reads them


def main():
    kvd, outdir, scene, view = sys.argv[1:5]
    events = sys.argv[5] if len(sys.argv) > 5 else "20"
    os.makedirs(outdir, exist_ok=True)
    name = os.path.splitext(os.path.basename(scene))[0]
    batches = trace_batches(kvd, scene, events, outdir)
    svg = os.path.join(outdir, name + ".svg")
    frames, hold = 30, 4
    subprocess.run([kvd, "animate", scene, "--view", view, "--events", events, "--frames", str(frames), "--hold",
                    str(hold), "--out", svg], check=True, stdout=subprocess.DEVNULL)
    text = open(svg).read()
    groups = re.split(r'(?=<g class="frame")', text)[1:]
    if len(groups) != frames + len(batches):
        fail(f"{len(groups)} pictures, expected {frames} sampled and {len(batches)} batches")
    windows = []
    for g in groups:
        m = re.search(r'keyTimes="([^"]*)"', g)
        times = [float(x) for x in m.group(1).split(";")]
        values = re.search(r'values="([^"]*)"', g).group(1).split(";")
        start = times[values.index("inline")]
        end = times[values.index("inline") + 1] if values.index("inline") + 1 < len(times) else 1.0
        windows.append((start, end))
    for (a0, a1), (b0, b1) in zip(windows, windows[1:]):
        if abs(a1 - b0) > 1e-5 or not a0 < a1:
            fail(f"pictures are not shown in turn: {a0, a1} then {b0, b1}")
    held = {}
    for g in groups:
        m = re.search(r'data-batch="(\d+)"', g)
        if m:
            held[int(m.group(1))] = g
    for k, (time, failing) in enumerate(batches):
        if k not in held:
            fail(f"batch {k} has no picture")
        captions = "\n".join(re.findall(r"<text[^>]*>([^<]*)</text>", held[k]))
        if "t = " + time not in captions and len(time) < 80:
            fail(f"batch {k}: its time {time} is not in the caption")
        for f in failing[:6]:
            if f not in captions:
                fail(f"batch {k}: {f} is not named")
    shown = frames + hold * len(batches)
    print(f"{name}: {len(groups)} pictures, {shown} frames, every batch held and named")
    if not shutil.which("ffmpeg") or not shutil.which("ffprobe"):
        print("ffmpeg not installed: the MP4 and GIF are not checked")
        return
    for ext in ("mp4", "gif"):
        film = os.path.join(outdir, name + "." + ext)
        subprocess.run([kvd, "animate", scene, "--view", view, "--events", events, "--frames", str(frames), "--hold",
                        str(hold), "--out", film], check=True, stdout=subprocess.DEVNULL)
        count = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                "stream=nb_read_frames", "-of", "csv=p=0", film], check=True, capture_output=True,
                               text=True).stdout.strip()
        if int(count) != shown:
            fail(f"{film}: {count} frames, expected {shown}")
        print(f"{name}.{ext}: {count} frames")


if __name__ == "__main__":
    main()
