#!/usr/bin/env python3
"""Loads kvd view pages in headless Chromium (Debian's chromium and
chromium-driver, through Selenium) and checks them against kvd's own trace:

  * the page logs no console error and draws the scene (WebGL pixels);
  * a batch changes the tree in the page's data exactly when the run says so;
  * the timeline lists exactly the trace's batches, in order, by exact time,
    and the page made from the trace (kvd view TRACE --scene) lists the same;
  * clicking the k-th batch (first, middle, last) shows its exact time and
    every failing certificate's type and features;
  * a diff page lists every exact event of the report and marks the first
    divergence;
  * a segment scene's page, as check_segment_page.py says.

usage: check_page.py KVD OUTDIR SCENE [SCENE ...] [--diff SCENE=KERNEL] [--events N]
Screenshots go to OUTDIR. Exit 0 when every check passes, 1 otherwise, 77
(skipped) when Chromium or Selenium is missing.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def browser():
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        print("skipped: python3-selenium is not installed")
        sys.exit(77)
    driver_path = shutil.which("chromedriver")
    if not driver_path or not (shutil.which("chromium") or shutil.which("chromium-browser")):
        print("skipped: chromium and chromium-driver are not installed")
        sys.exit(77)
    options = webdriver.ChromeOptions()
    for a in ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--use-angle=swiftshader",
              "--enable-unsafe-swiftshader", "--window-size=1600,1000", "--allow-file-access-from-files"]:
        options.add_argument(a)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(driver_path), options=options)


def trace_batches(kvd, scene, events, workdir):
    """The batches of kvd simulate --trace: (exact time, [(type, features)])."""
    trace = os.path.join(workdir, os.path.basename(scene) + ".trace")
    subprocess.run([kvd, "simulate", scene, "--events", str(events), "--validate", "none", "--trace", trace],
                   check=True, stdout=subprocess.DEVNULL)
    batches = []
    for line in open(trace):
        e = json.loads(line)
        if "batch" not in e:
            continue
        if len(batches) <= e["batch"]:
            batches.append((e["time"], []))
        batches[e["batch"]][1].append(e["certificate"] + " " + e["nodes"])
    return batches


def page_data(page):
    """The kvd-view/1 data a page embeds."""
    text = open(page, encoding="utf-8").read()
    start = text.index('id="kvd-data">') + len('id="kvd-data">')
    return json.loads(text[start:text.index("</script>", start)])


def console_errors(d):
    return [e["message"] for e in d.get_log("browser") if e["level"] == "SEVERE"]


def drawn_pixels(d):
    """Pixels of the 3D view that are not the white background."""
    return d.execute_script("""
      const c = document.querySelector('#canvas-holder canvas');
      const k = document.createElement('canvas'); k.width = 200; k.height = 200;
      const g = k.getContext('2d'); g.drawImage(c, 0, 0, 200, 200);
      const px = g.getImageData(0, 0, 200, 200).data; let n = 0;
      for (let i = 0; i < px.length; i += 4) if (px[i] < 250 || px[i + 1] < 250 || px[i + 2] < 250) ++n;
      return n;""")


def load_page(d, kvd, scene, events, outdir):
    """Writes the kvd view page of the scene's first `events` failures into
    outdir and loads it, failing on a console error: (name, page path)."""
    name = os.path.splitext(os.path.basename(scene))[0]
    page = os.path.join(outdir, name + ".html")
    subprocess.run([kvd, "view", scene, "--events", str(events), "--out", page], check=True,
                   stdout=subprocess.DEVNULL)
    d.get("file://" + os.path.abspath(page))
    errors = console_errors(d)
    if errors:
        fail(name + ": console errors: " + "; ".join(errors))
    return name, page


def check_scene_page(d, kvd, scene, events, outdir):
    from selenium.webdriver.common.by import By
    name, page = load_page(d, kvd, scene, events, outdir)
    d.execute_script("return window.kvdViewer !== undefined") or fail(name + ": the viewer did not start")
    if drawn_pixels(d) < 100:
        fail(name + ": the 3D view drew nothing")
    expected = trace_batches(kvd, scene, events, outdir)
    data = page_data(page)
    for k, b in enumerate(data["batches"]):
        if b["tree_changed"] != bool(data["frames"][b["frame"]]["changed"]):
            fail(f"{name}: batch {k}: the run says the tree {'did' if b['tree_changed'] else 'did not'} change, "
                 f"the page's trees say otherwise")
    items = d.find_elements(By.CSS_SELECTOR, "#timeline li.batch")
    times = [li.get_attribute("data-time") for li in items]
    if times != [t for t, _ in expected]:
        fail(f"{name}: the timeline lists {len(times)} batches, the trace {len(expected)}, or their times differ")
    if not expected:
        fail(name + ": the run has no batch to click")
    for k in sorted({0, len(expected) // 2, len(expected) - 1}):
        items[k].click()
        info = d.find_element(By.ID, "event-info").text
        time, failing = expected[k]
        if time not in info:
            fail(f"{name}: batch {k}: the time {time} is not shown")
        for f in failing:
            if f not in info:
                fail(f"{name}: batch {k}: the failing certificate {f} is not shown")
        selected = d.find_elements(By.CSS_SELECTOR, "#timeline li.selected")
        if len(selected) != 1 or selected[0].get_attribute("data-time") != time:
            fail(f"{name}: batch {k} is not the selected one")
    errors = console_errors(d)
    if errors:
        fail(name + ": console errors after clicking: " + "; ".join(errors))
    for k in ("P", "E"):  # the screenshot shows the cells' walls
        d.find_element(By.ID, "show-" + k).click()
    d.save_screenshot(os.path.join(outdir, "viewer-" + name + ".png"))
    # The same page from the run's trace.
    traced = os.path.join(outdir, name + "-traced.html")
    subprocess.run([kvd, "view", os.path.join(outdir, os.path.basename(scene) + ".trace"), "--scene", scene,
                    "--out", traced], check=True, stdout=subprocess.DEVNULL)
    listed = lambda p: [(b["time"], [(c["type"], c["features"]) for c in b["failing"]]) for b in page_data(p)["batches"]]
    if listed(traced) != listed(page):
        fail(name + ": the page made from the trace lists other batches than the page made from the scene")
    print(f"{name}: {len(expected)} batches listed as in the trace, 3 clicks checked, "
          f"{os.path.getsize(page) // 1024} KiB")


def check_diff_page(d, kvd, scene, kernel, events, outdir):
    from selenium.webdriver.common.by import By
    name = os.path.splitext(os.path.basename(scene))[0] + "-diff"
    report = os.path.join(outdir, name + ".json")
    with open(report, "w") as f:
        subprocess.run([kvd, "diff", scene, "--kernel", kernel, "--events", str(events), "--json"], check=True, stdout=f)
    page = os.path.join(outdir, name + ".html")
    subprocess.run([kvd, "view", report, "--out", page], check=True, stdout=subprocess.DEVNULL)
    d.get("file://" + os.path.abspath(page))
    errors = console_errors(d)
    if errors:
        fail(name + ": console errors: " + "; ".join(errors))
    r = json.load(open(report))
    rows = d.find_elements(By.CSS_SELECTOR, "#diff-table tbody tr")
    if len(rows) != len(r["events"]):
        fail(f"{name}: {len(rows)} rows for {len(r['events'])} exact events")
    marked = d.find_elements(By.CSS_SELECTOR, "#diff-table tr.divergence")
    first = r["first_divergence_event"]
    if first is not None and first < len(rows):
        if len(marked) != 1 or marked[0].find_elements(By.TAG_NAME, "td")[0].text != str(first):
            fail(f"{name}: the first divergence, event {first}, is not the one marked")
    elif marked:
        fail(name + ": a divergence is marked where the report has none")
    d.save_screenshot(os.path.join(outdir, "viewer-" + name + ".png"))
    print(f"{name}: {len(rows)} exact events, first divergence {first}, marked")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("kvd")
    p.add_argument("outdir")
    p.add_argument("scenes", nargs="+")
    p.add_argument("--diff", action="append", default=[])
    p.add_argument("--events", type=int, default=40)
    a = p.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    d = browser()
    try:
        for s in a.scenes:
            if json.load(open(s)).get("format") == "kvd-segments/1":
                from check_segment_page import check_segment_page
                check_segment_page(d, a.kvd, s, a.events, a.outdir)
            else:
                check_scene_page(d, a.kvd, s, a.events, a.outdir)
        for sk in a.diff:
            scene, kernel = sk.split("=", 1)
            check_diff_page(d, a.kvd, scene, kernel, a.events, a.outdir)
    finally:
        d.quit()
    print("viewer: every page checked")


if __name__ == "__main__":
    main()
