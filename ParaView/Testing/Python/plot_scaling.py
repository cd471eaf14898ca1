# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""prefix image.png: plots what distributed_scene.py measured with chunks on 1, 2 and 4 ranks
(prefix-N-<rank>.txt): frame times and memory per rank (Documentation/paraview.md)."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(prefix, ranks):
    found = []
    for rank in range(ranks):
        values = {}
        with open("%s-%d-%d.txt" % (prefix, ranks, rank)) as stats:
            for line in stats:
                words = line.split()
                if len(words) == 2:
                    values[words[0]] = float(words[1])
                elif len(words) == 3:  # timer: name count seconds
                    values[words[0]] = float(words[2])
        found.append(values)
    return found


prefix, image = sys.argv[1], sys.argv[2]
runs = {n: load(prefix, n) for n in (1, 2, 4)}
figure, (times, memory) = plt.subplots(1, 2, figsize=(10, 4))
ranks = list(runs)
slowest = lambda key: [max(r.get(key, 0.0) for r in runs[n]) for n in ranks]  # noqa: E731
times.plot(ranks, slowest("frame_s"), "o-", label="frame, camera moved, cube map kept")
times.plot(ranks, slowest("frame_cubemap_s"), "s-", label="frame, camera still, cube map re-rendered")
times.plot(ranks, slowest("first_frame_s"), "^-", label="first frame (incl. data)")
# Under IceT (2 ranks and more): its draw callback (each rank's rendering, cube map included) and
# its compositing, for the frame after a camera move.
parallel = [n for n in ranks if n > 1]
times.plot(parallel, [max(r["frame_s_icet_render"] for r in runs[n]) for n in parallel], "v--",
           label="  of which local rendering (IceT draw)")
times.plot(parallel, [max(r["frame_s_icet_composite"] for r in runs[n]) for n in parallel], "x--",
           label="  of which IceT compositing")
times.set_xlabel("MPI ranks (2 cores, oversubscribed)")
times.set_ylabel("seconds (slowest rank)")
times.set_xticks(ranks)
times.legend(fontsize=8)
times.set_title("500 ice chunks + terrain, llvmpipe")
for n in ranks:
    memory.scatter([n] * n, [r["max_rss_mib"] for r in runs[n]], color="tab:blue")
memory.set_xlabel("MPI ranks")
memory.set_ylabel("peak resident memory per rank (MiB)")
memory.set_xticks(ranks)
memory.set_title("memory per rank")
figure.tight_layout()
figure.savefig(image, dpi=80)
