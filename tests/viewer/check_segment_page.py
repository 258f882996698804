#!/usr/bin/env python3
"""Loads kvd view pages of segment scenes in headless Chromium (as
check_page.py does) and checks them against kvd's own output:

  * the page logs no console error;
  * the timeline lists the start and exactly the batches of kvd simulate
    --list, in order, by exact time;
  * clicking the first, middle and last batch shows its exact time, its
    events by kind and each failing certificate, marks in the picture the
    segments they name, and draws a tree whose nodes and height are those of
    kvd build at the instant the page says it drew;
  * the picture the page draws from the tree is the one kvd render draws at
    that instant: every cell, segment, cut, endpoint and crossing, in the
    same order and class, at the same place (the page's pixels mapped to
    render's by the scale and shift that take its endpoints to render's,
    within a hundredth of a pixel);
  * the left arrow key selects the interval before.

check_page.py runs these checks on the segment scenes it is given.
"""
import json
import os
import re
import subprocess

from check_page import console_errors, fail, load_page, page_data


def listed_batches(kvd, scene, events):
    out = subprocess.run([kvd, "simulate", scene, "--events", str(events), "--list", "--json"], check=True,
                         stdout=subprocess.PIPE, text=True).stdout
    return json.loads(out)["batch_list"]


def built(kvd, scene, time):
    out = subprocess.run([kvd, "build", scene, "--time", time, "--json"], check=True, stdout=subprocess.PIPE,
                         text=True).stdout
    return json.loads(out)


def numbers(attributes):
    """The numbers in the attributes' values, in order."""
    values = " ".join(re.findall(r'="([^"]*)"', attributes))
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", values)]


def shapes(svg_elements):
    """The drawn elements of a picture, by kind: (class, [numbers]) of every
    cell polygon, line (the legend's and the marked segments' left out),
    endpoint circle and crossing mark, the crossings apart (the page lists
    them by name, render in preorder)."""
    out = []
    for m in re.finditer(r'<(polygon|line|circle|path) class="([^"]+)"([^>]*)/?>', svg_elements):
        tag, cls, attributes = m.groups()
        if cls.startswith("legend") or cls == "marked":  # the marked segments are checked on their own
            continue
        attributes = re.sub(r'data-segment="\d+"', "", attributes)
        if tag == "circle":
            attributes = re.sub(r'r="[^"]+"', "", attributes)
        out.append((cls.split()[0], numbers(attributes)))
    crossings = [v for c, v in out if c == "crossing"]
    return [x for x in out if x[0] != "crossing"], crossings


def frame(svg_elements):
    """The view box's sides in pixels: (left, right), (top, bottom)."""
    m = re.search(r'<rect class="view-box"([^>]*)>', svg_elements)
    x, y, w, h = (float(re.search(f'{k}="([^"]+)"', m.group(1)).group(1)) for k in ("x", "y", "width", "height"))
    return (x, x + w), (y, y + h)


def check_drawn_as_render(d, kvd, scene, instant, outdir, name):
    page_svg = d.execute_script("return document.getElementById('picture').innerHTML")
    rendered = os.path.join(outdir, "render.svg")
    subprocess.run([kvd, "render", scene, "--time", instant, "--out", rendered], check=True)
    page, page_crossings = shapes(page_svg)
    ref, ref_crossings = shapes(open(rendered).read())
    if [c for c, _ in page] != [c for c, _ in ref] or len(page_crossings) != len(ref_crossings):
        fail(f"{name}: t = {instant}: the page draws other elements than kvd render")
    ends = [(v, w) for (c, v), (_, w) in zip(page, ref) if c == "endpoint"]
    # Pixel x' = a x + b, y' = a y + c, from the two endpoints farthest apart.
    (p0, r0), (p1, r1) = min(ends, key=lambda e: e[0][0] + e[0][1]), max(ends, key=lambda e: e[0][0] + e[0][1])
    a = (r1[0] - r0[0]) / (p1[0] - p0[0]) if p1[0] != p0[0] else (r1[1] - r0[1]) / (p1[1] - p0[1])
    b, c = r0[0] - a * p0[0], r0[1] - a * p0[1]
    tolerance = 0.01 * max(1.0, a)
    # The two draw different regions (the page the hull of its instants'):
    # a side a cell or cut lacks is drawn on the view box's frame, which is
    # then the other's frame too.
    page_frame, ref_frame = frame(page_svg), frame(open(rendered).read())
    def agree(k, x, y):
        for p_side, r_side in zip(page_frame[k % 2], ref_frame[k % 2]):
            if abs(x - p_side) <= 0.01:
                return abs(y - r_side) <= 0.01
        return abs(a * x + (b if k % 2 == 0 else c) - y) <= tolerance
    for (cls, v), (_, w) in zip(page, ref):
        if len(v) != len(w) or not all(agree(k, x, y) for k, (x, y) in enumerate(zip(v, w))):
            fail(f"{name}: t = {instant}: a {cls} the page draws at {v}, kvd render at {w} (scale {a}, "
                 f"shift {b}, {c})")
    def mapped(v):
        return [a * x + (b if k % 2 == 0 else c) for k, x in enumerate(v)]
    # A crossing's mark is a cross 8 pixels wide in both: its centre is compared.
    def centre(v):
        return [v[0] + 4, v[1] + 4]
    for v, w in zip(sorted(mapped(centre(v)) for v in page_crossings), sorted(centre(w) for w in ref_crossings)):
        if any(abs(x - y) > tolerance for x, y in zip(v, w)):
            fail(f"{name}: t = {instant}: a crossing the page marks at {v}, kvd render at {w}")
    return len(page)


def check_segment_page(d, kvd, scene, events, outdir):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    name, page = load_page(d, kvd, scene, events, outdir)
    expected = listed_batches(kvd, scene, events)
    data = page_data(page)
    items = d.find_elements(By.CSS_SELECTOR, "#timeline li")
    times = [li.get_attribute("data-time") for li in items[1:]]
    if len(items) != len(expected) + 1 or times != [b["time"] for b in expected]:
        fail(f"{name}: the timeline lists {len(items) - 1} batches, kvd simulate {len(expected)}, or their times differ")
    if not expected:
        fail(name + ": the run has no batch to click")
    for k in sorted({0, len(expected) // 2, len(expected) - 1}):
        items[k + 1].click()
        info = d.find_element(By.ID, "event-info").text
        b = expected[k]
        if b["time"] not in info:
            fail(f"{name}: batch {k}: the time {b['time']} is not shown")
        for kind, n in b["events"].items():
            if f"{n} {kind}" not in info:
                fail(f"{name}: batch {k}: '{n} {kind}' is not shown")
        failing = d.find_elements(By.CSS_SELECTOR, "#failing li")
        shown = [li.text for li in failing]
        page_failing = [f["kind"] + " " + f["features"] for f in data["batches"][k]["failing"]]
        if len(failing) != b["failing"] or shown != page_failing:
            fail(f"{name}: batch {k}: {len(failing)} failing certificates shown, kvd simulate lists {b['failing']}")
        named = {s for f in data["batches"][k]["failing"] for s in f["segments"]}
        marked = d.find_elements(By.CSS_SELECTOR, "#picture line.marked")
        drawn = sorted(int(line.get_attribute("data-segment")) for line in marked)
        if drawn != sorted(named) or not named:
            fail(f"{name}: batch {k}: segments {drawn} marked, the failing certificates name {sorted(named)}")
        m = re.search(r"Drawn at t = (\S+): (\d+) nodes, height (\d+)\.", info)
        if not m:
            fail(f"{name}: batch {k}: the instant drawn is not shown")
        fresh = built(kvd, scene, m.group(1))
        if (fresh["nodes"], fresh["height"]) != (int(m.group(2)), int(m.group(3))):
            fail(f"{name}: batch {k}: the page drew {m.group(2)} nodes, height {m.group(3)}; kvd build at "
                 f"t = {m.group(1)} makes {fresh['nodes']}, height {fresh['height']}")
        leaves = len(d.find_elements(By.CSS_SELECTOR, "#picture polygon.cell"))
        if leaves != fresh["leaves"]:
            fail(f"{name}: batch {k}: {leaves} cells drawn, kvd build has {fresh['leaves']} leaves")
        check_drawn_as_render(d, kvd, scene, m.group(1), outdir, name)
    d.find_element(By.TAG_NAME, "body").send_keys(Keys.ARROW_LEFT)
    selected = d.find_elements(By.CSS_SELECTOR, "#timeline li.selected")
    if len(selected) != 1 or selected[0].get_attribute("data-interval") != str(len(expected) - 1):
        fail(f"{name}: the left arrow did not select interval {len(expected) - 1}")
    errors = console_errors(d)
    if errors:
        fail(name + ": console errors after clicking: " + "; ".join(errors))
    d.save_screenshot(os.path.join(outdir, "segment-viewer-" + name + ".png"))
    print(f"{name}: {len(expected)} batches listed as kvd simulate lists them, 3 clicks checked against kvd build, "
          f"{os.path.getsize(page) // 1024} KiB")

