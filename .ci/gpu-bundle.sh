#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# Packs this machine's build (Debian 12, VTK 9.1) for a GPU machine of another Linux (the device
# tool's NVIDIA H200, Ubuntu 24.04): .gpu/bundle.tar.xz holds ice-render, ice-bench, IceCxxTests,
# the project's libraries and every library they load that is not glibc's or OpenGL's
# (OpenGL comes from the GPU's driver through glvnd, whose Debian packages go to .gl/).
# OpenImageIO and its dozens of libraries are replaced by a stub that aborts: nothing run there
# reads an image file. Then, on the device: carry .gl, .gpu/bundle.tar.xz, .ci/gpu-run.sh and
# run `bash .ci/gpu-run.sh` (performance.md, On a GPU).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
grep -qx '/.gl/' .git/info/exclude 2>/dev/null || echo /.gl/ >> .git/info/exclude
grep -qx '/.gpu/' .git/info/exclude 2>/dev/null || echo /.gpu/ >> .git/info/exclude
rm -rf .gpu/b && mkdir -p .gpu/b/bin .gpu/b/lib .gpu/b/libstdcxx .gpu/stub
cp "$build"/bin/ice-render "$build"/bin/ice-bench "$build"/bin/IceCxxTests .gpu/b/bin/
cp -a "$build"/lib/libRenderingIce.so* "$build"/lib/libRenderingIcePaper.so* \
  "$build"/lib/libFiltersIce.so* "$build"/lib/libIOIce.so* "$build"/lib/libLookIce.so* \
  "$build"/lib/libIceHeadless.so* .gpu/b/lib/

# The stub: every OpenImageIO function the project calls, aborting with a message.
programs=(.gpu/b/bin/* "$build"/lib/libRenderingIce.so.0.1.0 "$build"/lib/libRenderingIcePaper.so.0.1.0
  "$build"/lib/libFiltersIce.so.0.1.0
  "$build"/lib/libIOIce.so.0.1.0 "$build"/lib/libLookIce.so.0.1.0)
{
  echo '.section .note.GNU-stack,"",@progbits'
  echo '.text'
  for f in "${programs[@]}"; do objdump -T "$f"; done | awk '/\*UND\*/ && /OpenImageIO/ {print $NF}' |
    sort -u | while read -r symbol; do
      printf '.globl %s\n.type %s,@function\n%s:\n  jmp vtkice_oiio_stub\n' "$symbol" "$symbol" "$symbol"
    done
} > .gpu/stub/stub.s
printf '#include <stdio.h>\n#include <stdlib.h>\nvoid vtkice_oiio_stub(void) { fputs("OpenImageIO stub: no image files here\\n", stderr); abort(); }\n' > .gpu/stub/abort.c
for name in libOpenImageIO.so.2.4 libOpenImageIO_Util.so.2.4; do
  gcc -shared -fPIC -o ".gpu/b/lib/$name" -Wl,-soname,"$name" .gpu/stub/stub.s .gpu/stub/abort.c
done

# The libraries the programs load, but glibc, OpenGL and OpenImageIO (stubbed).
for f in "${programs[@]}"; do objdump -p "$f" | awk '/NEEDED/ {print $2}'; done | sort -u |
  grep -v -E 'OpenImageIO|libRenderingIce|libFiltersIce|libIOIce|libLookIce|libIceHeadless' | while read -r name; do
    path=$(ldconfig -p | awk -v n="$name" '$1 == n && !found {print $NF; found = 1}')
    [ -n "$path" ] && { echo "$path"; ldd "$path" | awk '/=>/ {print $3}'; }
  done | sort -u |
  grep -v -E '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*|libGL|libGLX|libEGL|libOpenGL|libGLdispatch)\.so' |
  while read -r lib; do
    case "$lib" in
      *libstdc++*|*libgcc_s*) cp -L "$lib" .gpu/b/libstdcxx/ ;; # used only if the system's is older
      *) cp -L "$lib" .gpu/b/lib/ ;;
    esac
  done
strip --strip-unneeded .gpu/b/bin/* .gpu/b/lib/*.so* 2> /dev/null || true

# The suite's C++ tests that render through the back end (ctest's label backend) as ctest runs
# them, for .ci/gpu-run.sh: one line each, name, environment, arguments, tab-separated, this
# checkout's folder as @REPO@ and the test's output folder as @TMP@. Left out: the environment
# reader's test (OpenImageIO is stubbed), the X and OSMesa back ends (neither is there).
ctest --test-dir "$build" -N -L backend --show-only=json-v1 > .gpu/tests.json
python3 - "$PWD" "$build" .gpu/tests.json > .gpu/b/tests.txt <<'PY'
import json, os, sys
repo, build, listing = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
temporary = os.path.join(build, "Testing", "Temporary")
skipped = ("Cxx.TestIceEnvironmentReader", "Cxx.TestIceBackend.x", "Cxx.TestIceBackend.osmesa")
for test in json.load(open(listing))["tests"]:
    if not test["name"].startswith("Cxx.") or test["name"] in skipped:
        continue
    environment = [v for p in test.get("properties", []) if p["name"] == "ENVIRONMENT"
                   for v in p["value"]]
    arguments = [a.replace(temporary, "@TMP@").replace(repo, "@REPO@") for a in test["command"][1:]]
    print("\t".join([test["name"], " ".join(environment) or "-"] + arguments))
PY
echo "$(wc -l < .gpu/b/tests.txt) tests listed for the GPU run"
tar cJf .gpu/bundle.tar.xz -C .gpu/b .

# glvnd's loaders, unpacked there over the driver's image.
mkdir -p .gl /tmp/amd64/partial
o=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64)
apt-get "${o[@]}" update > /dev/null
(cd .gl && apt-get "${o[@]}" download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 2> /dev/null)
du -sh .gpu/bundle.tar.xz .gl
