#!/bin/bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# On the device tool's GPU machine, from the repository root, with .gl, .gpu/bundle.tar.xz and
# this file carried (.ci/gpu-bundle.sh made them): ice-render, a full ice-bench run (and the
# objects groups without multisampling) and the suite's EGL tests (the bundle's tests.txt), all
# under $OUT with the tests' pictures (tests.tar.gz: where a picture differs from llvmpipe's
# baseline, the candidate for an alternative baseline Name_1.png, to be looked at first).
set -u -o pipefail
T0=$(date +%s)
REPO=$(pwd)
elapsed() { echo $(($(date +%s) - T0)); }
exec > >(tee "$OUT/log.txt") 2>&1
echo "== machine"
head -2 /etc/os-release; ldd --version | head -1; nproc
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,memory.total --format=csv
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
mkdir -p /tmp/b
python3 -c "import tarfile; tarfile.open('.gpu/bundle.tar.xz').extractall('/tmp/b')"
export LD_LIBRARY_PATH=/tmp/b/lib
if ! /tmp/b/bin/ice-render --help > /dev/null 2>&1; then
  echo "(the system's libstdc++ is too old: Debian's used)"
  export LD_LIBRARY_PATH=/tmp/b/libstdcxx:/tmp/b/lib
fi
ldd /tmp/b/bin/ice-bench | grep -E "not found" && echo "(libraries missing)"
ls /usr/share/glvnd/egl_vendor.d /etc/glvnd/egl_vendor.d /usr/local/nvidia/share/glvnd/egl_vendor.d 2>&1
unset DISPLAY

echo "== smoke: ice-render --backend egl ($(elapsed) s)"
smoke() { timeout 90 /tmp/b/bin/ice-render --backend egl --out "$OUT/ice-gpu.png"; }
ok=0
if smoke; then ok=1; else
  nv=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  export __EGL_VENDOR_LIBRARY_FILENAMES=$nv
  export LD_LIBRARY_PATH=$LD_LIBRARY_PATH:/usr/local/nvidia/lib64:/usr/local/nvidia/lib
  echo "-- again with __EGL_VENDOR_LIBRARY_FILENAMES=$nv and the driver's lib folders"
  if smoke; then ok=1; fi
fi
[ $ok = 1 ] || { echo "EGL failed"; ldd /tmp/b/bin/ice-render; exit 3; }

echo "== ice-bench, VTK's default multisampling ($(elapsed) s)"
cd /tmp/b
timeout 260 bin/ice-bench --backend egl --frames 60 --csv "$OUT/gpu.csv" \
  --markdown "$OUT/gpu.md" --plot "$OUT/gpu.png"
echo "ice-bench exit $?"
if [ "$(elapsed)" -lt 280 ]; then
  echo "== ice-bench --only objects, no multisampling ($(elapsed) s)"
  timeout 120 bin/ice-bench --backend egl --frames 60 --only objects --multisamples 0 \
    --csv "$OUT/gpu-ms0.csv" --markdown "$OUT/gpu-ms0.md"
  echo "ice-bench exit $?"
fi
cd - > /dev/null

echo "== EGL tests on the GPU: the suite's backend tests as ctest runs them ($(elapsed) s)"
mkdir -p /tmp/gt
pass=0
fail=""
# TestIceOpticsFunctions compiles the GLSL files of this checkout.
export VTKICE_GLSL_DIR=$REPO/Module/Rendering/glsl
while IFS=$'\t' read -r -a fields; do
  name=${fields[0]}
  [ "$(elapsed)" -lt 540 ] || { echo "(out of time before $name)"; break; }
  environment=()
  [ "${fields[1]}" != - ] && read -r -a environment <<< "${fields[1]}"
  arguments=("${fields[@]:2}")
  arguments=("${arguments[@]//@REPO@/$REPO}")
  arguments=("${arguments[@]//@TMP@//tmp/gt}")
  env VTKICE_BACKEND=egl "${environment[@]}" timeout 60 /tmp/b/bin/IceCxxTests "${arguments[@]}" \
    > "/tmp/gt/$name.log" 2>&1
  rc=$?
  # ctest's failure expression (Testing/Cxx/CMakeLists.txt): VTK's errors fail a test too.
  if [ $rc = 0 ] && grep -q -E "ERROR:|ERR\||Segmentation fault" "/tmp/gt/$name.log"; then rc=1; fi
  if [ $rc = 0 ]; then
    pass=$((pass + 1)); echo "PASS $name"
  else
    fail="$fail $name"; echo "FAIL $name (exit $rc)"; tail -15 "/tmp/gt/$name.log"
  fi
done < /tmp/b/tests.txt
echo "== $pass passed; failed:$fail ($(elapsed) s)"
tar czf "$OUT/tests.tar.gz" -C /tmp/gt . 2>/dev/null
ls -la "$OUT"
