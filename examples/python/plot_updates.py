"""Runs the exact kinetic KVD on a bundled scene from Python and plots the
cost of each update against the event number (matplotlib).
usage: python3 plot_updates.py SCENE OUT.png"""
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt

import kvd

k = kvd.Kinetic(kvd.load_scene(sys.argv[1]), events=200, validate="none")
times, costs, touched = [], [], []
while (batch := k.advance()) is not None:
    times.append(batch["time_approx"])
    costs.append(batch["update_seconds"] * 1000)
    touched.append(batch["nodes_touched"])
fig, ax = plt.subplots(figsize=(7, 3.5))
ax.plot(range(1, len(costs) + 1), costs, ".", label="update (ms)")
ax.plot(range(1, len(touched) + 1), touched, "x", label="nodes touched")
ax.set_xlabel("batch")
ax.set_yscale("log")
ax.legend()
ax.set_title(f"{len(costs)} batches, {k.summary['events']} events, exact kernel")
fig.tight_layout()
fig.savefig(sys.argv[2])
print(f"{len(costs)} batches; median update {sorted(costs)[len(costs) // 2]:.2f} ms; wrote {sys.argv[2]}")
