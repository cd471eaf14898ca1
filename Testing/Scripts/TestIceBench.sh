#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# ice-bench --quick runs and writes a well-formed table, CSV, Markdown and plot; bad arguments give
# one line and exit 2. No timing is checked: speed is measured by ice-bench, never by a test.
# usage: TestIceBench.sh ICE_BENCH WORK_DIR
set -u
ice_bench=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0

if "$ice_bench" --quick --csv bench.csv --plot bench.png --markdown bench.md >out.txt 2>err.txt; then
  echo "ok   ice-bench --quick exits 0"
else
  echo "FAIL ice-bench --quick: exit $?, stderr: $(tail -5 err.txt)"; failures=$((failures + 1))
fi
if grep -q "^== Targets" out.txt && grep -q "wrote bench.csv" out.txt; then
  echo "ok   the table and the targets are printed"
else
  echo "FAIL no table or targets on stdout"; failures=$((failures + 1))
fi

/usr/bin/python3 - <<'PY' || failures=$((failures + 1))
import csv, math, sys

expected = ("group,object,triangles,scene,coverage,configuration,material,cracks,air_planes,interior,"
            "cube_map,update_mode,face_size,faces_per_frame,culling,moving,frames,median_ms,p25_ms,"
            "p75_ms,min_ms,max_ms,mean_ms,fps,baseline_median_ms,ratio,cpu_median_ms,cpu_ratio,"
            "cube_faces_per_frame,gpu_cube_map_ms,gpu_depth_interval_ms,gpu_back_faces_ms,"
            "gpu_scene_ms,gpu_interior_ms,"
            "renderer,multisamples").split(",")
problems = []
with open("bench.csv", newline="") as f:
    rows = list(csv.reader(f))
if not rows or rows[0] != expected:
    problems.append("header is %r" % (rows[0] if rows else None))
data = [dict(zip(expected, r)) for r in rows[1:]]
for i, r in enumerate(rows[1:], 2):
    if len(r) != len(expected):
        problems.append("line %d has %d fields" % (i, len(r)))
groups = {}
for r in data:
    groups.setdefault(r["group"], []).append(r)
for wanted in ("objects-teapot", "dynamic-teapot", "cracks-teapot", "triangles-1k", "triangles-10k"):
    if wanted not in groups:
        problems.append("group %s missing" % wanted)
for name, members in groups.items():
    if members[0]["material"] != "plain" or abs(float(members[0]["ratio"]) - 1.0) > 1e-9:
        problems.append("%s: the first row is not the plain VTK baseline" % name)
    if len(members) < 2:
        problems.append("%s: no ice configuration" % name)
    if len({m["coverage"] for m in members}) != 1 or len({m["triangles"] for m in members}) != 1:
        problems.append("%s: configurations of one group differ in object or coverage" % name)
for r in data:
    where = "%s / %s" % (r["group"], r["configuration"])
    try:
        t = {k: float(r[k]) for k in ("median_ms", "p25_ms", "p75_ms", "min_ms", "max_ms",
                                       "mean_ms", "fps", "baseline_median_ms", "ratio",
                                       "cpu_median_ms", "cpu_ratio",
                                       "coverage", "cube_faces_per_frame")}
        frames, triangles = int(r["frames"]), int(r["triangles"])
        cracks, air = int(r["cracks"]), int(r["air_planes"])
        samples = int(r["multisamples"])
    except ValueError as e:
        problems.append("%s: not a number: %s" % (where, e))
        continue
    if not all(math.isfinite(v) for v in t.values()):
        problems.append("%s: non-finite value" % where)
    if not (0 < t["min_ms"] <= t["p25_ms"] <= t["median_ms"] <= t["p75_ms"] <= t["max_ms"]):
        problems.append("%s: statistics out of order" % where)
    if not (t["min_ms"] <= t["mean_ms"] <= t["max_ms"]):
        problems.append("%s: mean outside min..max" % where)
    if abs(t["ratio"] - t["median_ms"] / t["baseline_median_ms"]) > 1e-3 * t["ratio"] + 1e-4:
        problems.append("%s: ratio is not median / baseline" % where)
    if t["cpu_median_ms"] <= 0 or t["cpu_ratio"] <= 0:
        problems.append("%s: no CPU time" % where)
    if abs(t["fps"] - 1000.0 / t["median_ms"]) > 0.01 + 1e-3 * t["fps"]:
        problems.append("%s: fps is not 1000 / median" % where)
    if frames != 4:
        problems.append("%s: %d frames, --quick times 4" % (where, frames))
    if triangles <= 0 or cracks < 0 or air < 0 or samples < 0:
        problems.append("%s: bad counts" % where)
    if not 0.15 <= t["coverage"] <= 0.25:
        problems.append("%s: coverage %.3f is not about 1/5" % (where, t["coverage"]))
    if r["material"] not in ("plain", "one-sided", "two-sided", "exit-point", "full-look"):
        problems.append("%s: material %r" % (where, r["material"]))
    wanted = "" if r["material"] in ("plain", "one-sided") else ("paper-passes", "screen-space")
    if r["interior"] not in wanted or (not wanted and r["interior"]):
        problems.append("%s: interior %r" % (where, r["interior"]))
    if r["cube_map"] == "1":
        if r["update_mode"] not in ("every-frame", "on-change") or int(r["face_size"]) not in (128, 256, 512):
            problems.append("%s: cube map settings %r %r" % (where, r["update_mode"], r["face_size"]))
        if r["update_mode"] == "every-frame" and abs(t["cube_faces_per_frame"] - float(r["faces_per_frame"])) > 1e-9:
            problems.append("%s: %.2f cube faces per frame" % (where, t["cube_faces_per_frame"]))
        if r["update_mode"] == "on-change" and r["moving"] == "0" and t["cube_faces_per_frame"] != 0:
            problems.append("%s: a still scene re-rendered its cube map" % where)
    elif r["update_mode"] or t["cube_faces_per_frame"] != 0:
        problems.append("%s: cube map fields without a cube map" % where)
    if not r["renderer"]:
        problems.append("%s: no renderer string" % where)
    # GPU times by step (vtkIcePass::MeasureStepTimes): only with the pass, for the steps it runs.
    gpu = {k[4:-3]: r[k] for k in r if k.startswith("gpu_")}
    with_pass = r["material"] not in ("plain", "one-sided")
    timed = {step for step, value in gpu.items() if value}
    wanted = set()
    if with_pass:
        wanted = {"scene"}
        if r["cube_map"] == "1" and t["cube_faces_per_frame"] > 0:
            wanted.add("cube_map")
        if r["interior"] in ("paper-passes", "screen-space") and (cracks or air):
            wanted.add("interior")
    no_interior = not (cracks or air)
    if not wanted <= timed or (not with_pass and timed) or (no_interior and "interior" in timed):
        problems.append("%s: GPU steps timed %s, wanted at least %s" % (where, sorted(timed), sorted(wanted)))
    if any(value and not (float(value) >= 0 and math.isfinite(float(value))) for value in gpu.values()):
        problems.append("%s: a GPU step time is not a finite number >= 0" % where)
crack_counts = [(int(r["cracks"]), r["interior"]) for r in groups.get("cracks-teapot", [])[1:]]
if crack_counts != [(n, m) for m in ("paper-passes", "screen-space") for n in (0, 2, 8)]:
    problems.append("cracks-teapot counts %r" % crack_counts)

markdown = open("bench.md").read()
if "| target | limit | measured |" not in markdown or "| renderer |" not in markdown:
    problems.append("bench.md lacks the target or machine table")
with open("bench.png", "rb") as f:
    head = f.read(24)
if head[:8] != b"\x89PNG\r\n\x1a\n" or int.from_bytes(head[16:20], "big") != 1600:
    problems.append("bench.png is not a 1600 pixel wide PNG")

for p in problems:
    print("FAIL " + p)
if not problems:
    print("ok   bench.csv: %d rows in %d groups, well-formed; bench.md and bench.png written"
          % (len(data), len(groups)))
sys.exit(1 if problems else 0)
PY

expect_usage_error() {
  local name=$1 pattern=$2; shift 2
  "$ice_bench" "$@" >out.txt 2>err.txt
  local code=$?
  if [ "$code" -eq 2 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "^ice-bench: .*$pattern" err.txt; then
    echo "ok   $name: $(cat err.txt)"
  else
    echo "FAIL $name: exit $code, stderr: $(cat err.txt)"; failures=$((failures + 1))
  fi
}
expect_usage_error "unknown argument" "unknown argument" --fast
expect_usage_error "bad frame count" "bad --frames" --frames 0
expect_usage_error "missing value" "needs a value" --csv
expect_usage_error "unknown back end" "bad --backend" --backend vulkan
expect_usage_error "no group matches" "no group matches" --only nothing --csv ''

# The trace's tree alone: one row per object, each with its triangles, build time and size.
if "$ice_bench" --only tree >out.txt 2>err.txt && grep -q "^== The trace's tree" out.txt &&
  [ "$(grep -cE '^   (cube|teapot|sphere-100k|sphere-1M) +[0-9]+ +[0-9.]+ +[0-9]+ +[0-9]+ +[0-9]+ +[0-9.]+$' out.txt)" -eq 4 ]; then
  echo "ok   --only tree prints the tree of four objects"
else
  echo "FAIL --only tree: $(cat out.txt err.txt | tail -6)"; failures=$((failures + 1))
fi

if "$ice_bench" --help | grep -q "^usage: ice-bench"; then
  echo "ok   --help"
else
  echo "FAIL --help"; failures=$((failures + 1))
fi

if [ "$failures" -eq 0 ]; then echo "ice-bench: all checks passed"; fi
exit "$failures"
