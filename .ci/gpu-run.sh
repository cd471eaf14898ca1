#!/bin/bash
# On the device tool's GPU machine, from the repository root, with .gl, .gpu/bundle.tar.xz and
# this file carried (.ci/gpu-bundle.sh made them): ice-render, a full ice-bench run (and the
# objects groups without multisampling) and the EGL tests, all under $OUT. About a minute on
# an NVIDIA H200.
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

echo "== EGL tests on the GPU ($(elapsed) s)"
mkdir -p /tmp/gt
pass=0
fail=""
for t in TestIceMapperReference TestIceInteriorMethods TestIceTeapot TestIceCracks \
  TestIceAirAndBumps TestIceExitPoint TestIceBackfaceCulling TestIceFigure1 TestIceFigure4 \
  TestIceFigure5 TestIceGlistening TestIceGlisteningPlane TestIceGlisteningSnow \
  TestIceCracksConcave TestIceCubeMapPass TestIceCubeMapHDR TestIceCubeMapCompositor \
  TestIcePassScenes TestIcePassTwoIce TestIcePassCamera TestIcePassPicking TestIcePassStereo \
  TestIcePassRendererOptions TestIcePassLayouts TestIcePassNoIce TestIcePassWork \
  TestIceRepresentations TestIceColorByArray TestIceInvisible TestIceNoEnvironment \
  TestIcePlacementBounds TestIceSources TestIceViewer TestIcePanoramaEnvironment \
  TestIceLifecycle TestIceBackend; do
  [ "$(elapsed)" -lt 520 ] || { echo "(out of time before $t)"; break; }
  extra=()
  [ $t = TestIceBackend ] && extra=(--backend egl)
  base=$t
  [ $t = TestIceBackend ] && base=TestIceTeapot
  VTKICE_BACKEND=egl timeout 60 /tmp/b/bin/IceCxxTests $t "${extra[@]}" \
    -V "$REPO/Testing/Data/Baseline/$base.png" -T /tmp/gt > /tmp/gt/$t.log 2>&1
  rc=$?
  if [ $rc = 0 ]; then
    pass=$((pass + 1)); echo "PASS $t"
  else
    fail="$fail $t"; echo "FAIL $t (exit $rc)"; tail -15 /tmp/gt/$t.log
  fi
done
echo "== $pass passed; failed:$fail ($(elapsed) s)"
tar czf "$OUT/tests.tar.gz" -C /tmp/gt . 2>/dev/null
ls -la "$OUT"
