#!/usr/bin/env python3
"""Writes the stiff and extreme scenes of data/stiff/ (README.md there).

Every number is written as an exact decimal or fraction string, so the files
are the scenes described, not roundings of them. Run from anywhere:
    python3 data/stiff/make_scenes.py
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def tri(name, vertices, motion=None):
    o = {"name": name, "vertices": [[str(c) for c in v] for v in vertices], "triangles": [[0, 1, 2]]}
    if motion is not None:
        o["motion"] = motion
    return o


def translation(dx="0", dy="0", dz="0"):
    return {"translation": [dx, dy, dz]}


def scene(name, objects, end, decomposition=None):
    doc = {"format": "kvd-scene/1", "name": name, "time": {"start": "0", "end": end}}
    if decomposition:
        doc["decomposition"] = decomposition
    doc["priority"] = {"seed": 1}
    doc["objects"] = objects
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


# A static triangle whose top vertex is at y = 0: movers cross its P-cut.
def floor(y_top="0", z="0"):
    return tri("floor", [["-10", "-10", z], ["10", "-10", z], ["0", y_top, z]])


# Two movers cross y = 0 at t = 1 and t = 1 + 10^-31.
scene("close-events", [
    floor(),
    tri("a", [["-8", "-1", "1"], ["-6", "-3", "1"], ["-7", "-3", "2"]], translation(dy=["0", "1"])),
    tri("b", [["6", "-1.0000000000000000000000000000001", "3"], ["8", "-3", "3"], ["7", "-3", "4"]],
        translation(dy=["0", "1"])),
], "3")

# Eight movers in lockstep, each with a vertex at y = -1: all cross the
# floor's P-cut at t = 1 exactly, and never move against each other.
scene("simultaneous", [floor()] + [
    tri("m%d" % i, [[str(-9 + 2 * i), "-1", str(1 + i)], [str(-8 + 2 * i), "-3", str(1 + i)],
                    [str(-9 + 2 * i), "-3", str(2 + i)]], translation(dy=["0", "1"]))
    for i in range(8)
], "3")

# Tangential events: vertex y = (t-1)^2 touches the P-cut y = 0 at t = 1
# (double root, no event); vertex y = (t-2)^3 crosses it at t = 2 (triple
# root, one event); vertex y = (t-3)^4 touches it at t = 3 (quadruple root).
scene("tangential", [
    floor(),
    tri("touch2", [["-8", "0", "1"], ["-6", "2", "1"], ["-7", "2", "2"]], translation(dy=["1", "-2", "1"])),
    tri("cross3", [["-2", "0", "3"], ["0", "-2", "3"], ["-1", "-2", "4"]], translation(dy=["-8", "12", "-6", "1"])),
    tri("touch4", [["4", "0", "5"], ["6", "2", "5"], ["5", "2", "6"]], translation(dy=["81", "-108", "54", "-12", "1"])),
], "4")

# Coordinates from 1e-9 to 1e9 in one scene: a huge static triangle, a tiny
# mover near its P-cut, a far mover.
scene("wide-range", [
    tri("huge", [["-1e9", "-1e9", "0"], ["1e9", "-1e9", "0"], ["0", "0", "0"]]),
    tri("tiny", [["1e-9", "-1e-9", "1"], ["2e-9", "-2e-9", "1"], ["1e-9", "-2e-9", "1.000000001"]],
        translation(dy=["0", "1e-9"])),
    tri("far", [["5e8", "-3e8", "1e9"], ["6e8", "-4e8", "1e9"], ["5e8", "-4e8", "1.1e9"]],
        translation(dx=["0", "1e8"], dy=["0", "1e8"])),
], "5")

# A very slow and a very fast object: speeds 1e-12 and 1e12.
scene("slow-fast", [
    floor(),
    tri("slow", [["-8", "-1e-12", "1"], ["-6", "-3", "1"], ["-7", "-3", "2"]], translation(dy=["0", "1e-12"])),
    tri("fast", [["6", "-1e12", "3"], ["8", "-1.0000000001e12", "3"], ["7", "-1.0000000001e12", "4"]],
        translation(dy=["0", "1e12"])),
], "3")

# High-degree motions: a cubic and a quartic translation.
scene("high-degree", [
    floor(),
    tri("cubic", [["-8", "-1", "1"], ["-6", "-3", "1"], ["-7", "-3", "2"]],
        translation(dx=["0", "1", "-1/2", "1/6"], dy=["0", "0", "3", "-1"])),
    tri("quartic", [["4", "-2", "3"], ["6", "-4", "3"], ["5", "-4", "4"]],
        translation(dx=["0", "0", "-1", "0", "1/4"], dy=["0", "1", "0", "0", "1/10"])),
], "3")

# Exact rational rotations (angle 2 atan(t)) about the z axis through the
# origin and, with a different speed, about a vertical axis at x = 5.
rot = [[["1", "0", "-1"], ["0", "-2"], "0", "0"], [["0", "2"], ["1", "0", "-1"], "0", "0"],
       ["0", "0", ["1", "0", "1"], "0"], ["0", "0", "0", ["1", "0", "1"]]]
rot2 = [[["1", "0", "-4"], ["0", "-4"], "0", ["0", "20", "0", "0"]], [["0", "4"], ["1", "0", "-4"], "0", ["0", "-20"]],
        ["0", "0", ["1", "0", "4"], "0"], ["0", "0", "0", ["1", "0", "4"]]]
scene("rational-rotation", [
    tri("floor", [["-20", "-20", "0"], ["20", "-20", "0"], ["0", "20", "0"]]),
    tri("blade", [["1", "0", "1"], ["4", "0", "1"], ["2", "1", "2"]], {"matrix": rot}),
    tri("blade2", [["6", "0", "3"], ["8", "0", "3"], ["7", "1", "4"]], {"matrix": rot2}),
], "3")

# Near-parallel edges (slopes differing by 1e-20) and a near-vertical
# triangle (normal within 1e-15 of horizontal), moving past each other.
scene("near-degenerate", [
    tri("sliver", [["-5", "0", "0"], ["5", "1", "0"], ["0", "-3", "0"]]),
    tri("parallel", [["-5", "0.00000000000000000001", "1"], ["5", "1.00000000000000000002", "1"], ["0", "4", "1"]],
        translation(dx=["0", "1"], dz=["0", "0"])),
    tri("vertical", [["-2", "-6", "2"], ["2", "-6", "2.000000000000001"], ["0", "-6.000000000000001", "6"]],
        translation(dy=["0", "2"])),
], "4")

# A Euclidean decomposition point (a viewpoint) 1e-25 above a triangle's
# plane: the plate's E-planes are nearly its own plane, and a mover beside
# the plate rises through them.
scene("z-near-plane", [
    tri("plate", [["-10", "-10", "0"], ["10", "-10", "0"], ["0", "10", "0"]]),
    tri("mover", [["12", "-2", "-5"], ["18", "-2", "-5"], ["15", "1", "-4"]], translation(dz=["0", "3"])),
], "4", {"x": ["1", "0", "0", "0"], "z": ["0", "0", "0.0000000000000000000000001", "1"]})
