# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""ice-render and ice-bench against broken files, hostile headers, bad options, full disks and
signals.

Every case runs the program with a time limit (a hang fails) and asserts: no crash (no death by
SIGSEGV, SIGABRT, ...), for bad input a non-zero exit and exactly one printable line on stderr
naming the problem, and the output file, which holds a sentinel before the run, byte for byte
unchanged with no temporary file left beside it.
usage: TestIceHostileInput.py ICE_RENDER ICE_BENCH WORK_DIR   (Debian's /usr/bin/python3)
"""
import os
import re
import shutil
import signal
import stat
import struct
import subprocess
import sys
import time
import zlib

ICE_RENDER, ICE_BENCH, WORK = sys.argv[1:4]
TIME_LIMIT = 60
SENTINEL = b"sentinel: the user's previous picture\n"
failures = []
passed = 0


def write(name, data):
    with open(name, "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)
    return name


def leftovers(path):
    folder, name = os.path.split(os.path.abspath(path))
    return [f for f in os.listdir(folder) if f.startswith("." + name + ".")]


def run(argv, env=None, out="sentinel.png"):
    """Runs a program with a fresh sentinel at `out`; returns (code, stdout, stderr lines)."""
    write(out, SENTINEL)
    try:
        result = subprocess.run(argv, capture_output=True, timeout=TIME_LIMIT, env=env,
                                stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return None, b"", [b"(hung for %d s)" % TIME_LIMIT]
    return result.returncode, result.stdout, result.stderr.splitlines()


def check(name, ok, detail):
    global passed
    if ok:
        passed += 1
        print("ok   %s" % name)
    else:
        failures.append(name)
        print("FAIL %s: %s" % (name, detail))


def printable(line):
    return all(32 <= b < 127 or b >= 0x80 for b in line) and b"\x1b" not in line


def expect_error(name, pattern, args, program=None, env=None, out="sentinel.png"):
    program = program or ICE_RENDER
    tool = os.path.basename(program)
    code, _, err = run([program] + args, env=env, out=out)
    with open(out, "rb") as f:
        kept = f.read() == SENTINEL
    problems = []
    if code is None:
        problems.append("hung")
    elif code < 0:
        problems.append("died of signal %d" % -code)
    elif code == 0:
        problems.append("exit 0")
    if len(err) != 1 or not err[0].startswith(tool.encode() + b": "):
        problems.append("%d stderr lines" % len(err))
    elif not re.search(pattern.encode(), err[0]):
        problems.append("message lacks %r" % pattern)
    if err and not all(printable(line) for line in err):
        problems.append("unprintable bytes on stderr")
    if not kept:
        problems.append("the output file changed")
    if leftovers(out):
        problems.append("temporary files left: %s" % leftovers(out))
    shown = err[0].decode("utf-8", "replace") if err else ""
    check(name, not problems, "; ".join(problems) + " | " + shown[:300])


def expect_ok(name, args, out, magic):
    code, _, err = run([ICE_RENDER] + args + ["--out", out], out=out)
    with open(out, "rb") as f:
        data = f.read()
    check(name, code == 0 and not err and data.startswith(magic) and not leftovers(out),
          "exit %s, stderr %r, starts %r" % (code, b"".join(err)[:200], data[:8]))


def expect_warning(name, pattern, args, out, magic):
    """Exit 0 with the picture written and, when anything was left out, one stderr line naming
    it."""
    code, _, err = run([ICE_RENDER] + args + ["--out", out], out=out)
    with open(out, "rb") as f:
        data = f.read()
    said = not err or (len(err) == 1 and err[0].startswith(b"ice-render: ")
                       and re.search(pattern.encode(), err[0]))
    check(name, code == 0 and said and data.startswith(magic) and not leftovers(out),
          "exit %s, stderr %r, starts %r" % (code, b"".join(err)[:300], data[:8]))


def png_header(width, height):
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(b"\0" * 64)) + chunk(b"IEND", b""))


def legacy_vtk(points, polygons):
    size = sum(len(p) + 1 for p in polygons)
    return ("# vtk DataFile Version 3.0\nhostile\nASCII\nDATASET POLYDATA\nPOINTS %d float\n%s\n"
            "POLYGONS %d %d\n%s\n" % (len(points), " ".join("%g %g %g" % p for p in points),
                                      len(polygons), size,
                                      "\n".join(" ".join(map(str, [len(p)] + list(p))) for p in polygons)))


TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def ply(fmt, faces, vertices=TETRA, declared_vertices=None):
    header = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
              "property float z\nelement face %d\nproperty list uchar int vertex_indices\n"
              "end_header\n" % (fmt, declared_vertices or len(vertices), len(faces))).encode()
    if fmt == "ascii":
        body = "".join("%g %g %g\n" % v for v in vertices)
        body += "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)
        return header + body.encode()
    body = b"".join(struct.pack("<fff", *v) for v in vertices)
    body += b"".join(struct.pack("<B", len(f)) + struct.pack("<%di" % len(f), *f) for f in faces)
    return header + body


def binary_stl(triangles, declared=None):
    body = b"".join(struct.pack("<12fH", *([0.0, 0.0, 1.0] + [c for p in t for c in p]), 0)
                    for t in triangles)
    return b"\0" * 80 + struct.pack("<I", len(triangles) if declared is None else declared) + body


def model_cases():
    tris = [[TETRA[i] for i in f] for f in TETRA_FACES]
    cases = [
        ("OBJ: vertex index out of range", "does not exist",
         write("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")),
        ("OBJ: negative index out of range", "model",
         write("negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -9\n")),
        ("OBJ: polygon of two points", "model", write("two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n")),
        ("OBJ: no faces", "no polygons", write("nofaces.obj", "v 0 0 0\nv 1 0 0\n")),
        ("OBJ: empty file", "model", write("empty.obj", "")),
        ("OBJ: binary garbage", "model", write("garbage.obj", bytes(range(256)) * 8)),
        ("VTK: point index out of range", "does not exist",
         write("index.vtk", legacy_vtk(TETRA, [(0, 1, 7)]))),
        ("VTK: polygon of two points", "2 points", write("two.vtk", legacy_vtk(TETRA, [(0, 1, 2), (0, 3)]))),
        ("VTK: negative point index", "does not exist",
         write("negative.vtk", legacy_vtk(TETRA, [(0, 1, -3)]))),
        ("VTK: all points coincide", "no extent", write("point.vtk", legacy_vtk([(1, 1, 1)] * 4, TETRA_FACES))),
        # VTK 9.1 reads the NaN and the mapper names it; VTK 9.7's STL reader refuses it itself
        # ("vertex 2 non-finite").
        ("STL: NaN coordinates", "NaN|non-finite",
         write("nan.stl", binary_stl([[(0, 0, 0), (1, float("nan"), 0), (0, 1, 0)]] + tris[1:]))),
        ("VTK: cut off", "model", write("cut.vtk", legacy_vtk(TETRA, TETRA_FACES)[:130])),
        ("VTK: binary garbage after the header", "model",
         write("garbage.vtk", b"# vtk DataFile Version 3.0\nx\nBINARY\n" + bytes(range(256)) * 4)),
        ("STL: half a binary file", "does not match its header",
         write("half.stl", binary_stl(tris)[:84 + 50 * 2 + 17])),
        ("STL: header claims a billion triangles", "announces 1000000000",
         write("billion.stl", binary_stl(tris, declared=10 ** 9))),
        ("STL: garbage claiming a billion triangles", "does not match",
         write("garbage.stl", b"\x01\xfe" * 40 + struct.pack("<I", 10 ** 9) + bytes(range(256)) * 3)),
        ("STL: shorter than its header", "fewer than its 84-byte header", write("tiny.stl", b"\x00\xff" * 20)),
        ("STL: ASCII cut between facets", "endsolid",
         write("cut_ascii.stl", "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
               "   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\n")),
        ("STL: empty file", "model", write("empty.stl", "")),
        ("PLY: binary cut off", "cut off", write("cut.ply", ply("binary_little_endian", TETRA_FACES)[:-20])),
        ("PLY: ASCII cut off", "cut off", write("cut_ascii.ply", ply("ascii", TETRA_FACES)[:-12])),
        ("PLY: face names a missing vertex", "names vertex 9",
         write("index.ply", ply("binary_little_endian", TETRA_FACES[:3] + [(1, 2, 9)]))),
        ("PLY: ASCII face names a negative vertex", "names vertex -1",
         write("negative_ascii.ply", ply("ascii", TETRA_FACES[:3] + [(1, 2, -1)]))),
        ("PLY: header declares a billion vertices", "cut off",
         write("billion.ply", ply("binary_little_endian", TETRA_FACES, declared_vertices=10 ** 9))),
        ("PLY: no header end", "bad header", write("header.ply", b"ply\nformat ascii 1.0\n" + b"\xff" * 100)),
        ("PLY: not a PLY file", "bad header", write("garbage.ply", bytes(range(256)))),
        ("VTP: corrupt XML", "model", write("garbage.vtp", "<VTKFile broken")),
        ("VTP: connectivity out of range", "does not exist", write("index.vtp", """<?xml version="1.0"?>
<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
<PolyData><Piece NumberOfPoints="4" NumberOfPolys="1">
<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>
<Polys><DataArray type="Int64" Name="connectivity" format="ascii">0 1 42</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">3</DataArray></Polys>
</Piece></PolyData></VTKFile>
""")),
        ("model is a folder", "not a regular file", "folder.stl"),
        ("model is /dev/zero (a link named .stl)", "not a regular file", "zero.stl"),
        ("model is a pipe", "not a regular file", "pipe.obj"),
        ("missing model file", "cannot open", "no-such-file.ply"),
        ("model name with terminal escapes", "unknown model", write("\x1b[31mred\x07.txt", "x")),
    ]
    os.makedirs("folder.stl", exist_ok=True)
    if not os.path.lexists("zero.stl"):
        os.symlink("/dev/zero", "zero.stl")
    if not os.path.exists("pipe.obj"):
        os.mkfifo("pipe.obj")
    for name, pattern, path in cases:
        expect_error("model: " + name, pattern, ["--model", path, "--static", "--size", "64x48",
                                                 "--out", "sentinel.png"])
    # Fewer texture coordinates than vertices: VTK 9.1's vtkOBJReader hands on the short array,
    # which the ice does not use, so it is dropped with a line saying so; VTK 9.6's reader leaves
    # it out itself. Either way the model renders.
    short_vt = "".join("v %g %g %g\n" % p for p in TETRA + [(2, 2, 2)]) + \
        "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n" + \
        "".join("f %d/%d %d/%d %d/%d\n" % (a + 1, a + 1, b + 1, b + 1, c + 1, c + 1)
                for a, b, c in TETRA_FACES)
    expect_warning("model: OBJ with fewer texture coordinates than vertices",
                   r"dropped its point array 'TCoords' \(4 values for 5 points\)",
                   ["--model", write("short-vt.obj", short_vt), "--static", "--size", "64x48"],
                   "short-vt.png", b"\x89PNG")


def environment_cases():
    os.makedirs("huge-faces", exist_ok=True)
    for face in ("px", "nx", "py", "ny", "pz", "nz"):
        write("huge-faces/%s.png" % face, png_header(100000, 100000))
    os.makedirs("zero-faces", exist_ok=True)
    for face in ("px", "nx", "py", "ny", "pz", "nz"):
        if not os.path.lexists("zero-faces/%s.png" % face):
            os.symlink("/dev/zero", "zero-faces/%s.png" % face)
    if not os.path.lexists("zero.hdr"):
        os.symlink("/dev/zero", "zero.hdr")
    if not os.path.exists("pipe.hdr"):
        os.mkfifo("pipe.hdr")
    hdr = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 200000\n" + b"\x80" * 64
    # OpenImageIO 2.5 opens these headers and the reader refuses their size; OpenImageIO 3.1
    # refuses them itself, naming the size or the header as corrupt (Debian sid).
    oiio_refuses = "|exceeds the .* limit|may not exceed|corrupt or malicious header"
    cases = [
        ("PNG panorama header of 200000x100000", "pixels the reader accepts" + oiio_refuses,
         write("huge.png", png_header(200000, 100000))),
        ("six face headers of 100000x100000", "accepts" + oiio_refuses, "huge-faces"),
        ("HDR header of 200000x100000", "pixels the reader accepts" + oiio_refuses,
         write("huge.hdr", hdr)),
        ("cross image of 40000x30000 (faces of 10000)", "accepts" + oiio_refuses,
         write("cross.png", png_header(40000, 30000))),
        ("/dev/zero", "neither a folder nor a regular file", "/dev/zero"),
        ("a link to /dev/zero named .hdr", "neither a folder nor a regular file", "zero.hdr"),
        ("a pipe", "neither a folder nor a regular file", "pipe.hdr"),
        ("faces that are links to /dev/zero", "no face image", "zero-faces"),
        ("empty image file", "environment", write("empty.png", b"")),
        ("PNG cut after its header", "environment", write("cut.png", png_header(64, 32)[:40])),
        ("HDR with garbage pixels", "environment",
         write("garbage.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 32 +X 64\n" + b"\x02\x02\xff\xff" * 10)),
    ]
    for name, pattern, path in cases:
        expect_error("environment: " + name, pattern, ["--env", path, "--static", "--size", "64x48",
                                                       "--out", "sentinel.png"])


def option_cases():
    no_display = dict(os.environ)
    no_display.pop("DISPLAY", None)
    bad_backend = dict(os.environ, VTKICE_BACKEND="bogus")
    if not os.path.lexists("full.png"):
        os.symlink("/dev/full", "full.png")
    cases = [
        ("size 0x0", "bad --size", ["--size", "0x0"], None),
        ("size 99999x99999", "bad --size", ["--size", "99999x99999"], None),
        ("size -64x48", "bad --size", ["--size", "-64x48"], None),
        ("size with trailing text", "bad --size", ["--size", "64x48x3"], None),
        ("output of an unknown image type", "must end in .png", ["--out", "picture.bmp"], None),
        ("output without extension", "must end in .png", ["--out", "picture"], None),
        ("output is a folder", "it is a folder", ["--out", "folder.png"], None),
        ("output folder missing", "no folder", ["--out", "missing/ice.png"], None),
        ("unknown back end", "bad --backend", ["--backend", "bogus"], None),
        ("argument with terminal escapes", "unknown argument", ["--\x1b]0;owned\x07"], None),
        ("unknown back end in VTKICE_BACKEND", "VTKICE_BACKEND", [], bad_backend),
        ("x back end without a display", "DISPLAY", ["--backend", "x"], no_display),
        ("interactive without a display", "interactive|DISPLAY", ["--interactive", "--backend", "x"], no_display),
        ("disk full (a link to /dev/full)", "No space left", ["--out", "full.png", "--static"], None),
    ]
    # Standard output on a full disk: the picture is written, the exit says the log was not.
    with open("/dev/full", "w") as full:
        write("stdout.png", SENTINEL)
        result = subprocess.run([ICE_RENDER, "--size", "64x48", "--static", "--out", "stdout.png"],
                                stdout=full, stderr=subprocess.PIPE, timeout=TIME_LIMIT)
    check("option: standard output on a full disk",
          result.returncode == 1 and result.stderr.splitlines() ==
          [b"ice-render: cannot write to standard output"],
          "exit %s, stderr %r" % (result.returncode, result.stderr[:200]))
    os.makedirs("folder.png", exist_ok=True)
    for name, pattern, args, env in cases:
        expect_error("option: " + name, pattern, ["--size", "64x48", "--out", "sentinel.png"] + args,
                     env=env)


def output_cases():
    expect_ok("output: JPEG for .jpg", ["--size", "64x48", "--static"], "picture.jpg", b"\xff\xd8\xff")
    expect_ok("output: PNG for .PNG", ["--size", "64x48", "--static"], "picture.PNG", b"\x89PNG")
    # A link is followed: the link stays, its target gets the new picture.
    write("target.png", SENTINEL)
    if not os.path.lexists("link.png"):
        os.symlink("target.png", "link.png")
    code = subprocess.run([ICE_RENDER, "--size", "64x48", "--static", "--out", "link.png"],
                          capture_output=True, timeout=TIME_LIMIT).returncode
    with open("target.png", "rb") as f:
        check("output: a symbolic link stays a link to the new picture",
              code == 0 and os.path.islink("link.png") and f.read().startswith(b"\x89PNG"),
              "exit %s" % code)
    # Permissions of the replaced file are kept.
    write("mode.png", SENTINEL)
    os.chmod("mode.png", 0o640)
    code = subprocess.run([ICE_RENDER, "--size", "64x48", "--static", "--out", "mode.png"],
                          capture_output=True, timeout=TIME_LIMIT).returncode
    check("output: the replaced file keeps its permissions",
          code == 0 and stat.S_IMODE(os.stat("mode.png").st_mode) == 0o640,
          "exit %s, mode %o" % (code, stat.S_IMODE(os.stat("mode.png").st_mode)))


def signal_cases():
    """SIGINT and SIGTERM at several moments: the file is the sentinel or a whole new picture."""
    for sig in (signal.SIGINT, signal.SIGTERM):
        for delay in (0.2, 0.8, 1.5, 2.5):
            write("signal.png", SENTINEL)
            process = subprocess.Popen([ICE_RENDER, "--size", "640x480", "--out", "signal.png"],
                                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            time.sleep(delay)
            process.send_signal(sig)
            try:
                code = process.wait(timeout=TIME_LIMIT)
            except subprocess.TimeoutExpired:
                process.kill()
                code = "hung"
            with open("signal.png", "rb") as f:
                data = f.read()
            whole = data == SENTINEL or (data.startswith(b"\x89PNG") and data.endswith(b"IEND\xaeB`\x82"))
            check("signal: %s after %.1f s" % (signal.Signals(sig).name, delay),
                  code in (-sig, 0) and whole and not leftovers("signal.png"),
                  "exit %s, whole %s, leftovers %s" % (code, whole, leftovers("signal.png")))


def bench_cases():
    if not os.path.lexists("full.csv"):
        os.symlink("/dev/full", "full.csv")
    quick = ["--quick", "--frames", "1", "--only", "objects-teapot"]
    expect_error("ice-bench: CSV into a missing folder", "no folder",
                 ["--csv", "missing/b.csv"], program=ICE_BENCH, out="sentinel.csv")
    expect_error("ice-bench: plot of an unknown image type", "must end in .png",
                 ["--plot", "plot.gif"], program=ICE_BENCH, out="sentinel.csv")
    expect_error("ice-bench: CSV name with terminal escapes", "no folder",
                 ["--csv", "\x1b[2Jmissing/b.csv"], program=ICE_BENCH, out="sentinel.csv")
    expect_error("ice-bench: CSV on a full disk", "No space left",
                 quick + ["--csv", "full.csv"], program=ICE_BENCH, out="sentinel.csv")
    # Interrupted: no CSV appears where there was none, an existing one stays as it was.
    for existing in (False, True):
        if os.path.exists("interrupted.csv"):
            os.remove("interrupted.csv")
        if existing:
            write("interrupted.csv", SENTINEL)
        process = subprocess.Popen([ICE_BENCH, "--quick", "--csv", "interrupted.csv"],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(2.0)
        process.send_signal(signal.SIGINT)
        code = process.wait(timeout=TIME_LIMIT)
        if existing:
            with open("interrupted.csv", "rb") as f:
                ok = f.read() == SENTINEL
        else:
            ok = not os.path.exists("interrupted.csv")
        check("ice-bench: interrupted, %s CSV" % ("existing" if existing else "no"),
              code == -signal.SIGINT and ok and not leftovers("interrupted.csv"),
              "exit %s, file as before: %s" % (code, ok))


def main():
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    os.chdir(WORK)
    model_cases()
    environment_cases()
    option_cases()
    output_cases()
    signal_cases()
    bench_cases()
    print("%d passed, %d failed" % (passed, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
