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

