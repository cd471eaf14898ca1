# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""ice-render as a tool: every look option changes the picture, the ice's own settings only where
the ice is; values outside the library's range are refused with that range in the message;
presets (shipped and written by --print-preset) round-trip to the same picture; a turntable
writes its frames (and a video when ffmpeg is installed); a photographed HDR panorama, found by
name in Debian's blender-data, is clipped to white without a tone curve and not with one.

usage: TestIceRenderLook.py ICE_RENDER WORK_DIR   (Debian's /usr/bin/python3, for vtk)
"""
import os
import shutil
import subprocess
import sys

from ice_render_tool import Checks, read_png, render as render_tool, run as run_tool

ICE_RENDER, WORK = sys.argv[1], sys.argv[2]
SIZE = "96x72"
# The library's defaults (the paper preset): each option changes that look.
# The built-in sky: the default environment, a photographed panorama, would be tone mapped.
BASE = ["--model", "sphere", "--env", "sky", "--static", "--size", SIZE, "--preset", "paper"]
check = Checks()


def run(*args):
    return run_tool(ICE_RENDER, *args)


def render(name, *args):
    """Renders to NAME.png; returns its pixels (a list of RGB tuples) or None."""
    pixels, error = render_tool(ICE_RENDER, WORK, name, *args)
    if error is not None:
        print("     ice-render %s: %s" % (" ".join(args), error))
    return pixels


def differing(a, b, threshold=2):
    return {i for i, (p, q) in enumerate(zip(a, b)) if max(abs(x - y) for x, y in zip(p, q)) > threshold}


def dilate(pixels, width, height, radius):
    grown = set()
    for i in pixels:
        x, y = i % width, i // width
        for dy in range(-radius, radius + 1):
            for dx in range(-radius, radius + 1):
                if 0 <= x + dx < width and 0 <= y + dy < height:
                    grown.add((y + dy) * width + x + dx)
    return grown


def options_change_the_picture():
    default = render("default", *BASE)
    # Where the ice is: what its front-depth debug view changes, a few pixels wider.
    depth = render("ice-mask", *BASE, "--debug-view", "front-depth")
    ice = dilate(differing(default, depth, 0), 96, 72, 3)
    check("the ice's silhouette found", 800 < len(ice) < 96 * 72 - 500, "%d pixels" % len(ice))
    # (what the option needs to show, the option, whether only the ice may change)
    cases = [
        ([], ["--eta", "0.9"], True),
        ([], ["--ior", "1.5"], True),
        ([], ["--attenuation-distance", "0.5", "--attenuation-color", "0.4,0.7,0.9"], True),
        ([], ["--fresnel-power", "1"], True),
        ([], ["--fresnel", "dielectric"], True),
        ([], ["--color", "0.6,0.8,1"], True),
        ([], ["--no-two-sided"], True),
        ([], ["--two-sided-method", "exit-point"], True),
        (["--two-sided-method", "exit-point"], ["--bounces", "4"], True),
        ([], ["--back-normal-weight", "0.8"], True),
        ([], ["--cracks", "0"], True),
        ([], ["--interior", "paper-passes"], True),
        (["--cracks", "6"], ["--crack-seed", "9"], True),
        (["--cracks", "6"], ["--crack-intensity", "4"], True),
        (["--cracks", "6"], ["--cracks-in-refraction"], True),
        ([], ["--air", "0"], True),
        ([], ["--air-seed", "5"], True),
        ([], ["--milkiness", "1"], True),
        ([], ["--milky-core", "1"], True),
        ([], ["--bumps", "0"], True),
        ([], ["--bump-scale", "0.02"], True),
        ([], ["--glistening"], True),
        (["--glistening"], ["--snow", "0.8"], True),
        (["--glistening"], ["--glistening-scale", "0.2"], True),
        # Glints are few and small: seen in a larger picture.
        (["--glistening", "--size", "320x240"], ["--glistening-intensity", "3"], True),
        (["--glistening", "--size", "320x240"], ["--glistening-alignment", "8"], True),
        ([], ["--debug-view", "air"], True),
        ([], ["--debug-view", "cracks-unclipped"], False),  # red cracks over everything
        # A tone curve and exposure act on the whole picture.
        ([], ["--tone-mapping", "filmic"], False),
        (["--tone-mapping", "filmic"], ["--exposure", "-1"], False),
        ([], ["--camera-position", "0,0,5"], False),
        ([], ["--focal-point", "0.5,0,0"], False),
        ([], ["--view-up", "1,1,0"], False),
        ([], ["--view-angle", "60"], False),
        ([], ["--fit"], False),
    ]
    large = BASE + ["--size", "320x240"]
    large_ice = dilate(differing(render("large", *large),
                                 render("large-mask", *large, "--debug-view", "front-depth"), 0),
                       320, 240, 3)
    for needs, args, ice_only in cases:
        before = render("needs", *BASE, *needs) if needs else default
        mask = large_ice if "320x240" in needs else ice
        compare(before, mask, needs + args, ice_only, render("option", *BASE, *needs, *args))
    # The dynamic cube map shows the landscape around the ice: its settings, in that scene.
    landscape = ["--model", "sphere", "--env", "sky", "--size", SIZE]
    default = render("landscape", *landscape)
    depth = render("landscape-mask", *landscape, "--debug-view", "front-depth")
    ice = dilate(differing(default, depth, 0), 96, 72, 3)
    for args in (["--no-cube-map"], ["--cube-map-size", "8"], ["--cube-map-faces", "1"]):
        compare(default, ice, args, True, render("option", *landscape, *args))
    # Culling only skips work: the same picture.
    unculled = render("option", *landscape, "--no-cube-map-culling")
    check("--no-cube-map-culling gives the same picture",
          unculled is not None and not differing(default, unculled, 0))


def compare(default, ice, args, ice_only, picture):
    if picture is None:
        check(" ".join(args) + " renders", False)
        return
    changed = differing(default, picture)
    outside = changed - ice
    ok = len(changed) > 10 and (not ice_only or not outside)
    check(" ".join(args) + " changes the picture" + (" only where the ice is" if ice_only else ""),
          ok, "%d pixels changed, %d outside the ice" % (len(changed), len(outside)))


def bad_values_are_refused():
    cases = [
        (["--milkiness", "2"], "[0, 1]"),
        (["--eta", "0"], "[0.05, 1]"),
        (["--eta", "1.31"], "for an index of refraction of 1.31 set ior (--ior 1.31)"),
        (["--ior", "0"], "[0.05, 20]"),
        (["--attenuation-distance", "0"], "[1e-06, inf]"),
        (["--cracks", "5000"], "[0, 1000]"),
        (["--cracks", "2.5"], "a whole number in [0, 1000]"),
        (["--cube-map-size", "4"], "[8, 4096]"),
        (["--cube-map-faces", "7"], "[1, 6]"),
        (["--bounces", "0"], "[1, 16]"),
        (["--fresnel-power", "nan"], "a number in"),
        (["--debug-view", "xray"], "one of off, front-depth"),
        (["--two-sided-method", "exact"], "one of blended-normals, exit-point"),
        (["--fresnel", "schlick"], "one of paper, dielectric"),
        (["--color", "1,2"], "three numbers"),
        (["--color", "1,2,0"], "each in [0, 1]"),
        (["--view-up", "0,0,0"], "not 0,0,0"),
        (["--view-angle", "180"], "[1, 179]"),
        (["--exposure", "11"], "[-10, 10]"),
        (["--tone-mapping", "hable"], "one of none, reinhard, exponential, filmic, aces"),
        (["--turntable", "0"], "[1, 3600]"),
        (["--preset", "no-such-look"], "shipped clear, ice-cube, lake, glacier, frosted, snow, paper"),
        (["--no-eta"], "unknown argument '--no-eta'"),
    ]
    for args, expected in cases:
        result = run(*BASE, *args, "--out", os.path.join(WORK, "never.png"))
        lines = result.stderr.strip().splitlines()
        ok = result.returncode == 2 and len(lines) == 1 and lines[0].startswith("ice-render: ") \
            and expected in lines[0] and not os.path.exists(os.path.join(WORK, "never.png"))
        check("refused: " + " ".join(args), ok, result.stderr.strip())
    bad = os.path.join(WORK, "bad.ice")
    for text, expected in (("cracks = 8\nsparkle = 3\n", "bad.ice:2: unknown setting 'sparkle'"),
                           ("milkiness = 3\n", "bad.ice:1: bad milkiness '3' (a number in [0, 1])"),
                           ("milkiness 0.3\n", "bad.ice:1: expected NAME = VALUE")):
        with open(bad, "w") as f:
            f.write(text)
        result = run(*BASE, "--preset", bad, "--out", os.path.join(WORK, "never.png"))
        check("refused preset line: " + text.strip().splitlines()[-1],
              result.returncode == 2 and expected in result.stderr, result.stderr.strip())


def presets_round_trip():
    for name in ("clear", "ice-cube", "lake", "glacier", "frosted", "snow", "paper"):
        shipped = render("preset-" + name, *BASE, "--preset", name)
        printed = run(*BASE, "--preset", name, "--print-preset")
        path = os.path.join(WORK, name + "-printed.ice")
        with open(path, "w") as f:
            f.write(printed.stdout)
        again = render("again-" + name, *BASE, "--preset", path)
        ok = shipped is not None and again is not None and printed.returncode == 0 and \
            not differing(shipped, again, 0)
        check("preset %s: --print-preset fed back gives the same picture" % name, ok)
    default = render("default", *BASE)
    glacier = render("preset-glacier", *BASE, "--preset", "glacier")
    check("a shipped preset changes the look", len(differing(default, glacier)) > 100)
    overridden = run(*BASE, "--preset", "glacier", "--milkiness", "0.2", "--camera-position",
                     "0,1,5", "--print-preset").stdout
    check("options override the preset, camera settings given are printed",
          "milkiness = 0.2\n" in overridden and "cracks = 5\n" in overridden and
          "camera-position = 0,1,5\n" in overridden and "view-angle" not in overridden,
          overridden.replace("\n", "; "))


def turntable():
    out = os.path.join(WORK, "turn.png")
    result = run(*BASE, "--turntable", "3", "--out", out)
    frames = [os.path.join(WORK, "turn-%04d.png" % i) for i in range(1, 5)]
    present = [os.path.exists(f) for f in frames]
    check("--turntable 3 writes turn-0001.png .. turn-0003.png and no more",
          result.returncode == 0 and present == [True, True, True, False],
          result.stdout.strip() + result.stderr.strip())
    pictures = [read_png(f) for f in frames[:2]]
    check("the turntable's frames differ", len(differing(*pictures)) > 100)
    video = os.path.join(WORK, "turn.mp4")
    if shutil.which("ffmpeg"):
        probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-show_entries",
                                "stream=nb_read_frames,width,height", "-of", "csv=p=0", video],
                               capture_output=True, text=True)
        check("with ffmpeg, the turntable's video: 3 frames of 96x72", probe.stdout.strip() ==
              "96,72,3" and "and " + video in result.stdout, probe.stdout.strip() + probe.stderr)
    else:
        check("without ffmpeg, frames only, said so",
              not os.path.exists(video) and "no video: ffmpeg is not installed" in result.stdout)


PANORAMAS = "/usr/share/blender/datafiles/studiolights/world"  # Debian's blender-data


def clipped(pixels):
    """The fraction of pixels at white."""
    return sum(1 for p in pixels if min(p) >= 254) / len(pixels)


def named_panoramas():
    path = os.path.join(PANORAMAS, "courtyard.exr")
    if not os.path.exists(path):
        result = run(*BASE, "--env", "courtyard", "--out", os.path.join(WORK, "never.png"))
        check("--env courtyard without blender-data: refused, naming the package",
              result.returncode == 1 and "apt-get install blender-data" in result.stderr,
              result.stderr.strip())
        return
    by_name = render("courtyard", *BASE, "--env", "courtyard", "--tone-mapping", "none")
    by_path = render("courtyard-path", *BASE, "--env", path, "--tone-mapping", "none")
    check("--env courtyard is blender-data's panorama", by_name is not None and
          by_path is not None and not differing(by_name, by_path, 0))
    filmic = render("courtyard-filmic", *BASE, "--env", "courtyard", "--tone-mapping", "filmic",
                    "--exposure", "-1")
    default = render("courtyard-default", *BASE, "--env", "courtyard", "--exposure", "-1")
    check("a photographed panorama is tone mapped with filmic unless the look names a curve",
          default is not None and filmic is not None and not differing(default, filmic, 0))
    check("the sunlit courtyard (HDR) is clipped to white without a tone curve, not with filmic",
          by_name is not None and filmic is not None and clipped(by_name) > 0.2 and
          clipped(filmic) < clipped(by_name) / 4,
          "%.1f %% and %.1f %% of the pixels white" % (100 * clipped(by_name or [(0, 0, 0)]),
                                                       100 * clipped(filmic or [(0, 0, 0)])))
    result = run(*BASE, "--exposure", "1", "--out", os.path.join(WORK, "exposure.png"))
    check("--exposure without a curve that applies it: rendered, and said so",
          result.returncode == 0 and "exposure has no effect with tone-mapping none" in
          result.stderr, result.stderr.strip())


def main():
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    options_change_the_picture()
    bad_values_are_refused()
    presets_round_trip()
    turntable()
    named_panoramas()
    print("%d failed" % check.failures)
    return 1 if check.failures else 0


if __name__ == "__main__":
    sys.exit(main())
