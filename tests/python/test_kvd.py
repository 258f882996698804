"""The Python module `kvd` against the kvd command line, which it must agree
with exactly: counts, structure hashes, the painter's order with exact
coordinates, and the batches of a kinetic run. Run by CTest python_module
(environment: PYTHONPATH holds the module, KVD_EXECUTABLE and KVD_SOURCE_DIR)."""
import hashlib
import json
import os
import pathlib
import subprocess
from fractions import Fraction

import pytest

import kvd

KVD = os.environ["KVD_EXECUTABLE"]
DATA = os.path.join(os.environ["KVD_SOURCE_DIR"], "data")


def cli(*args):
    return subprocess.run([KVD, *args], check=True, capture_output=True, text=True).stdout


def scene_file(name):
    return os.path.join(DATA, name)


@pytest.mark.parametrize("name", ["two-triangles.json", "boxes.json", "cycle3.json", "uniform-scale-25.json"])
def test_build_agrees_with_kvd_build(name):
    s = kvd.load_scene(scene_file(name))
    ours = kvd.build(s, Fraction(1, 3))
    theirs = json.loads(cli("build", scene_file(name), "--time", "1/3", "--json"))
    assert ours["structure_hash"] == theirs["structure_hash"]
    assert ours["nodes"] == theirs["nodes"]
    assert ours["height"] == theirs["height"]


def test_back_to_front_order_is_kvd_orders_in_fractions():
    name = scene_file("cycle3.json")
    ours = kvd.build(kvd.load_scene(name), 0, view=(1, 2, 30))["order"]
    theirs = json.loads(cli("order", name, "--view", "1,2,30", "--json"))["fragments"]
    assert [f["triangle"] for f in ours] == [f["triangle"] for f in theirs]
    for a, b in zip(ours, theirs):
        assert all(isinstance(x, Fraction) for v in a["vertices"] for x in v)
        assert [tuple(v) for v in a["vertices"]] == [tuple(Fraction(x) for x in v) for v in b["vertices"]]


def test_the_order_at_an_instant_where_a_cut_degenerates_is_kvd_orders(tmp_path):
    # The mover's vertex (0, 0, 1) is on the line x ∨ z at 0: its P-cut and
    # the corners on it vanish there, and the corners were divided by a W of
    # zero (the interpreter died of SIGFPE). Both give their limits from after 0.
    name = tmp_path / "on-axis.json"
    name.write_text(json.dumps({
        "format": "kvd-scene/1", "time": {"start": "0", "end": "10"},
        "decomposition": {"x": ["0", "0", "0", "1"], "z": ["0", "0", "1", "0"]},
        "objects": [
            {"vertices": [["-4", "-4", "0"], ["4", "-4", "0"], ["0", "4", "0"]], "triangles": [[0, 1, 2]]},
            {"vertices": [["0", "0", "1"], ["1", "0", "1"], ["0", "1", "2"]], "triangles": [[0, 1, 2]],
             "motion": {"translation": [["0", "1/2"], "0", "0"]}}]}))
    ours = kvd.build(kvd.load_scene(name), 0, view=(10, 10, 10))["order"]
    theirs = json.loads(cli("order", str(name), "--view", "10,10,10", "--json"))["fragments"]
    assert [[tuple(v) for v in f["vertices"]] for f in ours] == \
        [[tuple(Fraction(x) for x in v) for v in f["vertices"]] for f in theirs]
    assert (0, 0, 1) in [tuple(v) for f in ours for v in f["vertices"]]


def test_a_scene_from_lists_is_the_scene_from_its_file():
    # data/two-triangles.json written as Python lists with exact numbers.
    text = json.load(open(scene_file("two-triangles.json")))
    objects = []
    for o in text["objects"]:
        obj = {"vertices": [[Fraction(x) for x in v] for v in o["vertices"]], "triangles": o["triangles"]}
        if "motion" in o:
            obj["translation"] = [[Fraction(c) for c in (p if isinstance(p, list) else [p])]
                                  for p in o["motion"]["translation"]]
        objects.append(obj)
    ours = kvd.scene(objects, start=Fraction(text["time"]["start"]), end=text["time"].get("end"),
                     seed=text.get("priority", {}).get("seed", 0))
    file = kvd.load_scene(scene_file("two-triangles.json"))
    assert (ours.triangles, ours.vertices, ours.objects) == (file.triangles, file.vertices, file.objects)
    for t in (0, Fraction(1, 2), 1):
        assert kvd.build(ours, t)["structure_hash"] == kvd.build(file, t)["structure_hash"]


def test_bad_input_raises_value_errors_that_name_the_place():
    with pytest.raises(ValueError, match="/objects/0/triangles/0/2"):
        kvd.scene([{"vertices": [[0, 0, 0], [1, 0, 0]], "triangles": [[0, 1, 2]]}])
    with pytest.raises(ValueError, match="kernel"):
        kvd.Kinetic(kvd.load_scene(scene_file("boxes.json")), kernel="quad")
    with pytest.raises(ValueError):
        kvd.load_scene(os.path.join(DATA, "README.md"))


TRIANGLE = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]


def test_lists_take_tuples_and_refuse_other_types_with_type_errors():
    # Tuples are lists here; a string, None, a float index or a mapping that
    # is not a dict are refused, not read as something else (or crash).
    assert kvd.scene([{"vertices": [tuple(v) for v in TRIANGLE], "triangles": [(0, 1, 2)]}]).triangles == 1
    for bad in ({"vertices": TRIANGLE, "triangles": ["abc"]},
                {"vertices": TRIANGLE, "triangles": [[0, 1, 2]], "translation": None},
                {"vertices": TRIANGLE, "triangles": [[0, 1, 2.0]]},
                [("vertices", TRIANGLE), ("triangles", [[0, 1, 2]])]):
        with pytest.raises(TypeError):
            kvd.scene([bad])
    with pytest.raises(ValueError, match="vertex index"):
        kvd.scene([{"vertices": TRIANGLE, "triangles": [[0, 1, -1]]}])
    run = kvd.Kinetic(kvd.load_scene(scene_file("two-triangles.json")))
    with pytest.raises(TypeError):
        run.set_motion(1, [None, None, None], 1)


def test_builds_are_refused_outside_the_time_span_as_on_the_command_line():
    s = kvd.load_scene(scene_file("two-triangles.json"))
    segments = kvd.load_segments(os.path.join(DATA, "segments", "two-crossing.json"))
    for t in (100, -5):
        with pytest.raises(ValueError, match="outside the scene's time span"):
            kvd.build(s, t)
        with pytest.raises(ValueError, match="outside the scene's time span"):
            kvd.build_segments(segments, t)
    assert kvd.build_segments(segments, 10)["nodes"] > 0


def test_seeds_and_kernel_names_are_checked_as_on_the_command_line():
    for seed, error in ((-1, ValueError), (2**64, ValueError), (1.5, TypeError), ("3", TypeError)):
        with pytest.raises(error, match="seed"):
            kvd.load_scene(scene_file("two-triangles.json"), seed=seed)
        with pytest.raises(error, match="seed"):
            kvd.load_segments(os.path.join(DATA, "segments", "two-crossing.json"), seed=seed)
    s = kvd.load_scene(scene_file("two-triangles.json"))
    for kernel in ("mpfr:64abc", "mpfr: 64", "mpfr:+64", "mpfr:-18446744073709551614", "mpfr:"):
        with pytest.raises(ValueError, match="mpfr:BITS"):
            kvd.Kinetic(s, kernel=kernel)
    assert kvd.Kinetic(s, kernel="mpfr:64").next_event_time is not None


def test_paths_are_any_os_pathlike_and_a_nul_in_one_is_refused(tmp_path):
    assert kvd.load_scene(pathlib.Path(scene_file("two-triangles.json"))).triangles == 2
    assert kvd.load_segments(pathlib.Path(segment_file("two-crossing.json"))).segments == 2
    # A name that is not UTF-8, as os.listdir gives it (os.fsdecode).
    odd = tmp_path / os.fsdecode(b"\xff.json")
    odd.write_bytes(open(segment_file("two-crossing.json"), "rb").read())
    assert kvd.load_segments(str(odd)).segments == 2
    for load, name in ((kvd.load_scene, scene_file("two-triangles.json")),
                       (kvd.load_segments, segment_file("two-crossing.json"))):
        # The C++ file functions would end the path at the NUL and read another file.
        with pytest.raises(ValueError, match="NUL"):
            load(name + "\0.bak")
        with pytest.raises(ValueError, match="NUL"):
            load(name.encode() + b"\0.bak")
        assert load(os.fsencode(name)) is not None
        for bad in (3, None):
            with pytest.raises(TypeError, match="path"):
                load(bad)


def test_scenes_are_made_by_the_module_only():
    for cls in (kvd.Scene, kvd.SegmentScene):
        with pytest.raises(TypeError, match="made by the module"):
            cls.__new__(cls)


def test_runs_not_initialised_refuse_to_be_read():
    # Class.__new__(Class) makes an object __init__ never filled.
    for cls in (kvd.Kinetic, kvd.KineticSegments, kvd.PaperSegments):
        empty = cls.__new__(cls)
        for name in ("advance", "now", "summary", "events"):
            with pytest.raises(TypeError, match="not initialised"):
                getattr(empty, name)
        assert isinstance(repr(empty), str)
    s = kvd.load_segments(segment_file("two-crossing.json"))
    assert kvd.PaperSegments(s).now["time"] == "0"


def test_numbers_of_thousands_of_digits_cross_both_ways(tmp_path):
    # Python converts at most 4,300 decimal digits to or from text.
    big = 10**5000
    s = kvd.scene([{"vertices": [[big, 0, 0], [big + 1, 0, 0], [big, 1, 0]], "triangles": [[0, 1, 2]]}],
                  start=Fraction(1, big), end=1)
    assert s.start == Fraction(1, big)
    assert kvd.build(s)["nodes"] > 0


def test_an_error_quoting_bytes_that_are_not_utf8_keeps_its_message(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_bytes(b"\xff\xfe{}")
    with pytest.raises(kvd.SceneError, match="malformed JSON"):
        kvd.load_segments(str(bad))


@pytest.mark.parametrize("name", ["uniform-scale-25.json", "collisions.json"])
def test_stepping_gives_the_batches_of_kvd_simulate(name, tmp_path):
    trace = tmp_path / "trace"
    summary = json.loads(cli("simulate", scene_file(name), "--events", "30", "--trace", str(trace), "--json"))
    k = kvd.Kinetic(kvd.load_scene(scene_file(name)), events=30)
    batches = []
    while (b := k.advance()) is not None:
        batches.append(b)
        lo, hi = b["time_interval"]
        assert lo <= Fraction(b["time_approx"]) <= hi or abs(b["time_approx"] - float(lo)) < 1e-12
        assert b["structure_hash"] == k.structure_hash  # the tree in force is the batch's
    traced = {}
    for line in open(trace):
        e = json.loads(line)
        if "batch" in e:
            traced.setdefault(e["batch"], (e["time"], []))[1].append((e["certificate"], e["nodes"]))
    assert [(b["time"], b["failing"]) for b in batches] == [traced[i] for i in range(len(traced))]
    assert [(b["scope"], b["nodes_touched"]) for b in batches] == [
        (t["scope"], t["nodes_touched"]) for t in summary["batch_list"]]
    assert k.summary["structure_hash"] == summary["structure_hash"]
    assert k.summary["valid"] and k.summary["stopped"] == summary["stopped"]
    assert k.events == batches


def test_floating_point_kernels_step_and_report_their_times():
    s = kvd.load_scene(scene_file("uniform-scale-25.json"))
    for kernel in ("double", "mpfr:113"):
        k = kvd.Kinetic(s, kernel=kernel, events=20)
        times = []
        while (b := k.advance()) is not None:
            times.append(b["time_approx"])
            assert "time_interval" not in b
        assert times == sorted(times) and len(times) > 5


def standing(name, obj, at):
    # Object `obj` of scene `name` stopped where it is at `at`: a constant
    # translation, its value then.
    motion = json.load(open(scene_file(name)))["objects"][obj]["motion"]["translation"]
    return [[sum(Fraction(c) * at ** i for i, c in enumerate(p if isinstance(p, list) else [p]))] for p in motion]


def test_set_motion_turns_an_object_back():
    s = kvd.load_scene(scene_file("uniform-scale-25.json"))
    k = kvd.Kinetic(s, events=40)
    k.advance_to(Fraction(1, 5))
    at = Fraction(1, 5)
    before = len(k.events)
    still = standing("uniform-scale-25.json", 3, at)
    k.set_motion(3, still, at)
    while k.advance() is not None:
        pass
    assert k.summary["valid"] and k.summary["motion_changes"] == 1 and len(k.events) > before
    with pytest.raises(ValueError):
        k.set_motion(99, still, at)


def segment_file(name):
    return os.path.join(DATA, "segments", name)


@pytest.mark.parametrize("name", ["two-crossing.json", "concurrent-three.json", "rotating-10.json", "random-100.json"])
def test_segment_build_agrees_with_kvd_build(name):
    ours = kvd.build_segments(kvd.load_segments(segment_file(name)), Fraction(1, 3))
    theirs = json.loads(cli("build", segment_file(name), "--time", "1/3", "--json"))
    for key in ("segments", "crossings", "vertex_cuts", "intersection_cuts", "edge_cuts", "nodes", "leaves", "height"):
        assert ours[key] == theirs[key], key
    assert ours["tree"] == cli("build", segment_file(name), "--time", "1/3", "--tree").strip()
    assert ours["augmented"] == cli("build", segment_file(name), "--time", "1/3", "--augmented").strip()
    assert ours["structure_hash"] == hashlib.sha256(ours["tree"].encode()).hexdigest()


@pytest.mark.parametrize("name", ["rotating-10.json", "random-100.json"])
def test_segment_stepping_gives_the_batches_of_kvd_simulate(name):
    theirs = json.loads(cli("simulate", segment_file(name), "--events", "30", "--list", "--json"))
    k = kvd.KineticSegments(kvd.load_segments(segment_file(name)), events=30)
    batches = []
    while (b := k.advance()) is not None:
        batches.append(b)
        assert b["structure_hash"] == k.tree["structure_hash"]  # the tree in force is the batch's
        assert all(event in ("vertex", "edge", "intersection", "flip") for _, _, event in b["failing"])
    assert [(b["time"], len(b["failing"]), b["changed"], b["certificates"], b["nodes_rebuilt"], b["frontier_replays"],
             b["subtree_replays"], b["signs"], b["held"]) for b in batches] == [
        (t["time"], t["failing"], t["changed"], t["certificates"], t["nodes_rebuilt"], t["frontier_replays"],
         t["subtree_replays"], t["signs"], t["held"]) for t in theirs["batch_list"]]
    # The kept set's update reads the signs of the certificates in force.
    assert sum(b["held"] for b in batches) > 0
    assert k.summary["failures"] == theirs["failures"]
    assert k.summary["validations"] == theirs["validations"] and k.summary["validation_failures"] == []
    assert k.tree["nodes"] == theirs["nodes"] and k.summary["certificates"] == theirs["certificates"]
    assert k.events == batches


@pytest.mark.parametrize("name", ["over-endpoint.json", "rotating-10.json"])
def test_paper_segments_give_the_batches_of_kvd_simulate_certificates_paper(name):
    theirs = json.loads(cli("simulate", segment_file(name), "--certificates", "paper", "--events", "30", "--list",
                            "--json"))
    p = kvd.PaperSegments(kvd.load_segments(segment_file(name)), events=30)
    batches = list(iter(p.advance, None))
    assert [(b["time"], [{"kind": kind, "of": of} for kind, of in b["failing"]], b["changed"], b["certificates"],
             b["replays"], b["frontier_replays"], b["nodes_rebuilt"], b["flipped_in_place"], b["nodes_edited"], b["signs"],
             b["held"], b["repeated"], b["signs_by"]) for b in batches] == [
        (t["time"], t["failing"], t["changed"], t["certificates"], t["replays"], t["frontier_replays"], t["nodes_rebuilt"],
         t["flipped_in_place"], t["nodes_edited"], t["signs"], t["held"], t["repeated"], t["signs_by"])
        for t in theirs["batch_list"]]
    # The paper's set holds no sign of the construction: every one asked is
    # decided, once a batch (a key asked again is repeated).
    assert all(b["held"] == 0 for b in batches) and sum(b["signs"] for b in batches) > 0
    assert sum(b["repeated"] for b in batches) > 0
    assert batches[-1]["structure_hash"] == p.tree["structure_hash"] and p.tree["nodes"] == theirs["nodes"]
    assert p.summary["validations"] == theirs["validations"] > 0 and p.summary["validation_failures"] == []


def test_paper_segments_change_the_tree_where_the_kept_run_does():
    # Every batch of the run on the paper's certificates is an instant where
    # the run keeping every sign changes the tree, to the same tree, and the
    # other way round (tests/test_aeg_kinetic.cpp does it on 17 scenes).
    s = kvd.load_segments(segment_file("random-100.json"))
    paper = kvd.PaperSegments(s, events=10**6, validate=False, until=Fraction(1, 8))
    kept = kvd.KineticSegments(s, events=10**6, validate=False, until=Fraction(1, 8))
    ours = [(b["time"], b["structure_hash"]) for b in iter(paper.advance, None)]
    theirs = [(b["time"], b["structure_hash"]) for b in iter(kept.advance, None) if b["changed"]]
    assert ours == theirs and len(ours) > 20
    assert paper.summary["certificates"] < kept.summary["certificates"]


def test_segment_local_subtree_and_rebuild_steps_agree_on_every_kernel():
    s = kvd.load_segments(segment_file("random-100.json"))
    for kernel in ("exact", "double", "mpfr:113"):
        local = kvd.KineticSegments(s, kernel=kernel, events=40)
        subtree = kvd.KineticSegments(s, kernel=kernel, events=40, update="subtree")
        rebuild = kvd.KineticSegments(s, kernel=kernel, events=40, update="rebuild")
        steps = list(iter(local.advance, None))
        a = [(b["time"], b["structure_hash"]) for b in steps]
        assert a == [(b["time"], b["structure_hash"]) for b in iter(subtree.advance, None)] and len(a) > 10
        assert a == [(b["time"], b["structure_hash"]) for b in iter(rebuild.advance, None)]
        assert local.summary["recovery"]["unrepaired"] == 0
        # Most failures take the frontier replay; the subtree update never does.
        assert sum(b["frontier_replays"] for b in steps) > sum(b["subtree_replays"] for b in steps)
        assert all(b["frontier_replays"] == 0 for b in subtree.events)


def test_segment_bad_input_raises_value_errors():
    with pytest.raises(ValueError, match="format"):
        kvd.load_segments(scene_file("two-triangles.json"))
    s = kvd.load_segments(segment_file("two-crossing.json"))
    with pytest.raises(ValueError, match="kernel"):
        kvd.KineticSegments(s, kernel="quad")
    with pytest.raises(ValueError, match="update"):
        kvd.KineticSegments(s, update="reinsert")


def changed(result):
    # KineticSegments.set_motion says whether the tree changed; PaperSegments
    # returns the batch of the certificates it failed at once.
    return result if isinstance(result, bool) else result["changed"]


@pytest.mark.parametrize("run", [kvd.KineticSegments, kvd.PaperSegments])
def test_segment_set_motion_stops_the_sinker(run):
    # over-endpoint.json: the sinker, from (3, 4) to (6, 1), moves down by t
    # and passes over the floor's endpoint (4, 0) at t = 3 (an edge event).
    # Stopped at 1/2 (a constant translation, where it is then), nothing fails
    # any more and the tree stays the one at 1/2.
    s = kvd.load_segments(segment_file("over-endpoint.json"))
    moving = run(s)
    assert [b["time"] for b in iter(moving.advance, None)] == ["3"]
    k = run(s)
    at = Fraction(1, 2)
    assert not changed(k.set_motion(1, {"translation": [0, Fraction(-1, 2)]}, at))
    assert k.now["time"] == "1/2"
    assert k.advance() is None
    assert k.tree["tree"] == kvd.build_segments(s, at)["tree"]
    assert k.summary["motion_changes"] == 1 and k.summary["validation_failures"] == []
    # Moving down again from 3/4 (by 1/4 - t), it meets the endpoint a
    # quarter later than it would have.
    assert not changed(k.set_motion(1, {"translation": ["0", ["1/4", "-1"]]}, Fraction(3, 4)))
    assert [b["time"] for b in iter(k.advance, None)] == ["13/4"]
    assert k.summary["motion_changes"] == 2 and k.summary["validation_failures"] == []


@pytest.mark.parametrize("run", [kvd.KineticSegments, kvd.PaperSegments])
def test_segment_set_motion_rejects_bad_motions(run):
    s = kvd.load_segments(segment_file("over-endpoint.json"))
    k = run(s)
    with pytest.raises(ValueError, match="no segment 5"):
        k.set_motion(5, None, Fraction(1, 2))
    with pytest.raises(ValueError, match="set_motion: /translation: "):
        k.set_motion(1, {"translation": [0]}, Fraction(1, 2))
    with pytest.raises(ValueError, match="set_motion: /: expected exactly one of"):
        k.set_motion(1, {}, Fraction(1, 2))
    # Back to its rest position at 1/2: a jump.
    with pytest.raises(ValueError, match="away from where it is now"):
        k.set_motion(1, None, Fraction(1, 2))
    # Endpoints that meet at t = 1, inside the span: a file with this motion
    # is refused too.
    with pytest.raises(ValueError, match="endpoints coincide at t = 1"):
        k.set_motion(1, {"endpoints": [[[3, 1], [4, -1], 1], [[6, -2], [1, 2], 1]]}, 0)
    # A change refused leaves the run where it was.
    assert k.now["time"] == "0" and k.summary["motion_changes"] == 0
    k.advance_to(Fraction(1, 2))
    with pytest.raises(ValueError, match="before the run's now"):
        k.set_motion(1, {"translation": [0, Fraction(-1, 4)]}, Fraction(1, 4))
    assert k.summary["motion_changes"] == 0


def test_set_motion_refuses_an_instant_past_the_span_and_leaves_the_run():
    # The scenes end at 7/2 and 10. The segment runs moved to the end and took
    # the change there; the triangle run refused it.
    s = kvd.load_segments(segment_file("over-endpoint.json"))
    sinking = {"translation": [0, [0, -1]]}  # its own motion: where it is at any instant
    for run in (kvd.KineticSegments, kvd.PaperSegments):
        k = run(s)
        for at in (4, 100):
            with pytest.raises(ValueError, match="outside the scene's time span"):
                k.set_motion(1, sinking, at)
        assert k.now["time"] == "0" and k.events == [] and k.summary["motion_changes"] == 0
        k.set_motion(1, sinking, Fraction(7, 2))  # the end is in the span
        assert k.now["time"] == "7/2" and k.summary["motion_changes"] == 1
    k = kvd.Kinetic(kvd.load_scene(scene_file("two-triangles.json")))
    with pytest.raises(ValueError, match="not in"):
        k.set_motion(1, [[0], [0], [0]], 11)
    assert k.now["time"] == "0" and k.events == [] and k.summary["motion_changes"] == 0


def test_advance_to_refuses_an_instant_before_now_and_leaves_the_run():
    # It returned 0 as though nothing were due.
    s = kvd.load_segments(segment_file("over-endpoint.json"))
    triangles = kvd.load_scene(scene_file("uniform-scale-25.json"))
    for k in (kvd.KineticSegments(s), kvd.PaperSegments(s), kvd.Kinetic(triangles, events=40)):
        k.advance_to(Fraction(1, 5))
        now, events = k.now, k.events
        assert now["time"] != "0"
        with pytest.raises(ValueError, match="before the run's now"):
            k.advance_to(0)
        assert k.now == now and k.events == events
        assert k.advance_to(Fraction(1, 5)) == 0  # now, or later


@pytest.mark.parametrize("run", [kvd.KineticSegments, kvd.PaperSegments])
def test_segment_runs_keep_their_bounds_in_advance_to_and_set_motion_as_in_advance(run):
    # advance_to and set_motion went past `events` and `until`, which only
    # advance() kept (Kinetic keeps them in all three).
    s = kvd.load_segments(segment_file("random-100.json"))

    def untimed(batches):
        return [{k: v for k, v in b.items() if k != "update_seconds"} for b in batches]

    stepped = run(s, events=7, validate=False)
    batches = list(iter(stepped.advance, None))
    assert batches and stepped.summary["failures"] >= 7
    bounded = run(s, events=7, validate=False)
    assert bounded.advance_to(s.end) == len(batches)
    assert untimed(bounded.events) == untimed(batches) and bounded.now["time"] == batches[-1]["time"]
    # Stopped by its events before `at`, the change is refused.
    with pytest.raises(ValueError, match="after its 7 events"):
        bounded.set_motion(1, None, s.end)  # segment 1 is static
    assert bounded.summary["motion_changes"] == 0
    # `until`: batches up to it, then the run moves there and no further.
    until = Fraction(1, 100)
    capped = run(s, events=10**6, validate=False, until=until)
    capped.advance_to(s.end)
    assert capped.now["time"] == str(until)
    assert untimed(capped.events) == untimed(iter(run(s, events=10**6, validate=False, until=until).advance, None))
    with pytest.raises(ValueError, match="after the run's until"):
        capped.set_motion(1, None, 2 * until)
    assert capped.now["time"] == str(until) and capped.summary["motion_changes"] == 0


@pytest.mark.parametrize("run", [kvd.KineticSegments, kvd.PaperSegments])
def test_a_float_is_its_exact_binary_value_in_motions_as_everywhere(run):
    # The module's one rule: a float is Fraction(float). A segment's motion
    # read 1.1 as the decimal 11/10 (json.dumps wrote its shortest text), and
    # refused an int of more than 4,300 digits (Python's text limit).
    s = kvd.load_segments(segment_file("over-endpoint.json"))
    k = run(s)
    k.set_motion(1, {"translation": [0, [0, -1.1]]}, 0)
    # The sinker meets the floor's endpoint when it has sunk by 3.
    assert [b["time"] for b in iter(k.advance, None)] == [str(3 / Fraction(1.1))]
    assert kvd.scene([{"vertices": TRIANGLE, "triangles": [[0, 1, 2]]}], start=0.1).start == Fraction(0.1)
    run(s).set_motion(1, {"translation": [0, [0, Fraction(-1, 10**5000)]]}, 0)
    # inf and nan have no exact value: ValueError (inf was an OverflowError).
    for bad in (float("inf"), float("nan")):
        with pytest.raises(ValueError):
            kvd.scene([{"vertices": TRIANGLE, "triangles": [[0, 1, 2]]}], end=bad)
        with pytest.raises(ValueError):
            run(s).set_motion(1, {"translation": [0, [0, bad]]}, 0)


@pytest.mark.parametrize("run", [kvd.KineticSegments, kvd.PaperSegments])
def test_a_bool_is_no_number_anywhere(run):
    # True counted as 1 in a triangle's coordinates and instants (Fraction
    # takes it) but was refused in a segment's motion (the format has no
    # bool number).
    with pytest.raises(TypeError, match="not a bool"):
        kvd.scene([{"vertices": [[True, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]}])
    with pytest.raises(TypeError, match="not a bool"):
        kvd.scene([{"vertices": TRIANGLE, "triangles": [[0, 1, 2]]}], end=True)
    s = kvd.load_segments(segment_file("over-endpoint.json"))
    with pytest.raises(TypeError, match="not a bool"):
        run(s).advance_to(True)
    with pytest.raises(kvd.SceneError):
        run(s).set_motion(1, {"translation": [0, [0, True]]}, 0)
    assert kvd.scene([{"vertices": [[1, 0, 0], [2, 0, 0], [1, 1, 0]], "triangles": [[0, 1, 2]]}]).start == 0


@pytest.mark.parametrize("run", [kvd.KineticSegments, kvd.PaperSegments])
def test_a_number_as_text_follows_the_file_format_everywhere(run):
    # A str went through Fraction's grammar in coordinates and instants
    # (" 1", "1_000", "+1" and ".5" were numbers) but through the file
    # format's in a motion (they were not). Now the format's everywhere.
    assert kvd.scene([{"vertices": TRIANGLE, "triangles": [[0, 1, 2]]}], end="1e-3").end == Fraction(1, 1000)
    s = kvd.load_segments(segment_file("over-endpoint.json"))
    for text in (" 1", "1_000", "+1", ".5", "1/0"):
        with pytest.raises(ValueError, match="is .*(not a number|zero denominator)"):
            kvd.scene([{"vertices": TRIANGLE, "triangles": [[0, 1, 2]]}], end=text)
        with pytest.raises(ValueError):
            run(s).advance_to(text)
        with pytest.raises(kvd.SceneError):
            run(s).set_motion(1, {"translation": [0, [0, text]]}, 0)
    k = run(s)
    k.set_motion(1, {"translation": [0, [0, "-11/10"]]}, "0")
    assert [b["time"] for b in iter(k.advance, None)] == [str(Fraction(30, 11))]


def test_summary_says_why_the_run_stopped_once_it_has():
    # It named the record's default, "exhausted", as soon as no batch was due
    # before the limit or the event count, while set_motion could still give
    # the run batches; the reason came with the stop.
    s = kvd.load_scene(scene_file("uniform-scale-25.json"))
    at = Fraction(1, 5)
    k = kvd.Kinetic(s, until=at)
    assert k.advance_to(at) > 0 and k.next_event_time is None
    assert k.summary["stopped"] is None
    k.set_motion(3, standing("uniform-scale-25.json", 3, at), at)
    assert k.summary["stopped"] is None
    assert k.advance() is None and k.summary["stopped"] == "limit"
    with pytest.raises(ValueError, match="has stopped"):
        k.set_motion(3, standing("uniform-scale-25.json", 3, at), at)
    k = kvd.Kinetic(s, events=3)
    assert k.advance_to(1) == 3 and k.summary["stopped"] is None
    assert k.advance() is None and k.summary["stopped"] == "events"
