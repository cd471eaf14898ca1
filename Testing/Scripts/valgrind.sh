#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# valgrind memcheck on one full-ice run: one cycle of the soak (TestIceSoak --frames 100
# --small: two-sided refraction, a cube map of the scene every frame, cracks, air, bumps, ice
# actors added and removed, a shared mapper, the pass removed and set again, resizes) in a small
# window. About 15 minutes on 2 cores with llvmpipe.
#   Testing/Scripts/valgrind.sh [FRAMES]        (./ice.sh valgrind [FRAMES])
# Needs a build (build/, or $VTKICE_BUILD_DIR). Writes the memcheck log to
# <build>/Testing/Temporary/valgrind/memcheck.log and prints a summary; exit status 1 when a
# definite leak or a memory error belongs to VTK Ice:
# - a definite leak is VTK Ice's when, walking its allocation stack from the allocator
#   upward, a frame of the project's libraries or the test program comes before any
#   frame of the GL driver (Mesa's swrast_dri, libLLVM, libGLX_mesa, libEGL_mesa, libOSMesa):
#   memory that the driver allocates for itself while VTK Ice calls GL is the driver's;
# - a memory error is VTK Ice's when the first of its frames outside libc, the dynamic linker
#   and libstdc++ is in one of those VTK Ice files.
# Mesa's driver is kept loaded until exit (Testing/Sanitizers/IceKeepDriversLoaded.cxx,
# preloaded): unloaded, the blocks its globals still point to would be reported as lost.
set -euo pipefail
cd "$(dirname "$0")/../.."
source_dir=$PWD
build_dir=${VTKICE_BUILD_DIR:-build}
frames=${1:-100}
driver="$build_dir/bin/IceCxxTests"
if [ ! -x "$driver" ]; then
  echo "valgrind: $driver not found: build first (./ice.sh test-vtk, or cmake --build $build_dir)" >&2
  exit 2
fi
command -v valgrind >/dev/null || { echo "valgrind: not installed (apt-get install valgrind)" >&2; exit 2; }
work="$build_dir/Testing/Temporary/valgrind"
mkdir -p "$work"
log="$work/memcheck.log"

keep="$work/keep-drivers-loaded.so"
multiarch=$(gcc -print-multiarch)
g++ -shared -fPIC -O1 -o "$keep" "$source_dir/Testing/Sanitizers/IceKeepDriversLoaded.cxx" \
  "-DVTKICE_KEEP_LOADED=\"/usr/lib/$multiarch/dri/swrast_dri.so\", \"libOSMesa.so.8\""

run=(env LP_NUM_THREADS=0 LD_PRELOAD="$keep"
  valgrind --tool=memcheck --leak-check=full --show-leak-kinds=definite --keep-debuginfo=yes
  --num-callers=40 --log-file="$log"
  "$driver" TestIceSoak --frames "$frames" --small)
echo "valgrind: ${run[*]}"
start=$(date +%s)
if [ -n "${VTKICE_BACKEND:-}" ] || { [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1; }; then
  "${run[@]}" | tail -4
else
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "${run[@]}" | tail -4
fi
echo "valgrind: $(($(date +%s) - start)) s; log $log"

/usr/bin/python3 - "$log" <<'EOF'
import re
import sys

ours = re.compile(r"libRenderingIce|libFiltersIce|libIOIce|libLookIce|libIceHeadless|IceCxxTests")
driver = re.compile(r"swrast_dri|libLLVM|libGLX_mesa|libEGL_mesa|libOSMesa|libgallium")
system = re.compile(r"vgpreload|libc\.so|ld-linux|libstdc\+\+|\(dl-|strcmp|rtld")
records = []
current = None
for line in open(sys.argv[1], errors="replace"):
    text = re.sub(r"^==\d+== ?", "", line.rstrip("\n"))
    if not text or re.match(r"Thread \d+", text):
        current = None
        continue
    if text.strip().startswith(("at ", "by ")):
        if current is not None:
            current["frames"].append(text.strip())
    elif not text.startswith(" ") and current is None:
        current = {"title": text, "frames": []}
        records.append(current)

def leak_is_ours(frames):
    for frame in frames[1:]:
        if driver.search(frame):
            return False
        if ours.search(frame):
            return True
    return False

def error_is_ours(frames):
    for frame in frames:
        if not system.search(frame):
            return bool(ours.search(frame))
    return False

def where(frames):
    for frame in frames[1:]:
        if not system.search(frame):
            return frame.split(": ", 1)[-1]
    return "?"

leaks = [r for r in records if "definitely lost in loss record" in r["title"]]
errors = [r for r in records if r["frames"] and "lost in loss record" not in r["title"]]
bad = 0
for r in leaks:
    mine = leak_is_ours(r["frames"])
    bad += mine
    print(("FAIL " if mine else "     ") + "definite leak: " + r["title"] + ", allocated in "
          + where(r["frames"]) + ("" if mine else " (not VTK Ice's)"))
for r in errors:
    mine = error_is_ours(r["frames"])
    bad += mine
    print(("FAIL " if mine else "     ") + "memory error: " + r["title"] + " at "
          + r["frames"][0].split(": ", 1)[-1] + ("" if mine else " (not VTK Ice's)"))
summary = [l.strip() for l in open(sys.argv[1], errors="replace")
           if re.search(r"(definitely|indirectly|possibly) lost:|ERROR SUMMARY", l)]
for line in summary:
    print("valgrind:" + re.sub(r"^==\d+==", "", line))
print("valgrind: %d definite leak(s) and %d memory error(s); %d of VTK Ice"
      % (len(leaks), len(errors), bad))
sys.exit(1 if bad else 0)
EOF
