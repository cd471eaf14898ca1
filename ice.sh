#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# VTK Ice's entry point, used by the README's Quick start and by CI.
#   ./ice.sh render [ice-render options]  install what is missing, build, render ice.png
#   ./ice.sh test [ctest options]         every test, as CI runs them: the VTK 9.1 stage, the VTK 9.7
#                                         wheel stage, the ParaView stage, Debian's VTK 9.1 installed
#                                         again, then the trixie and sid lanes; ends with a
#                                         table of the stages (passed, failed or skipped, tests,
#                                         minutes), exit 1 when one failed (VTKICE_SKIP_STAGES:
#                                         words of "vtk wheel wheels paraview fuzz trixie
#                                         sid" to skip)
#   ./ice.sh test-vtk [ctest options]     the VTK 9.1 stage alone: build, run its tests
#   ./ice.sh wheel [ctest options]        the wheel stage alone: a venv with the vtk 9.7.0 wheel and
#                                         PyVista, its SDK, pip install ., every test on VTK 9.7
#                                         (VTKICE_VTK_SOURCE: VTK 9.7.0's source archive)
#   ./ice.sh wheels                       manylinux wheels of vtkice for CPython 3.10-3.13 beside
#                                         PyPI's vtk 9.7.0 into dist/, compiled in a Debian 11
#                                         chroot (.ci/wheels.sh)
#   ./ice.sh wheels-test                  those wheels installed as users get them: fresh venvs of
#                                         this machine's Pythons and of Debian 13's and sid's
#                                         (chroots with no compiler), rendering without X
#   ./ice.sh lane trixie|sid [ctest opts] the VTK stage on Debian 13 (VTK 9.3) or sid (VTK 9.6) in a
#                                         chroot made with mmdebstrap, then PyVista from Debian,
#                                         then the ParaView stage on its ParaView (5.13, 6.1);
#                                         ends with the same table
#   ./ice.sh web [--port N]               the web viewer (Examples/Web) on http://127.0.0.1:N/ (8080),
#                                         rendered through EGL; makes the wheel's venv, SDK and
#                                         pip install . where missing, adds its trame packages
#   ./ice.sh vtk-sdk PREFIX               the SDK of the vtk wheel in VTKICE_PYTHON, made from
#                                         VTKICE_VTK_SOURCE, for CMAKE_PREFIX_PATH=PREFIX pip install .
#   ./ice.sh soak [frames] [seed] [WxH]   build, then the long soak (10 000 frames, ~15 min)
#   ./ice.sh sanitize [ctest options]     every test with ASan+UBSan, in build-asan/
#   ./ice.sh fuzz [seconds]               the libFuzzer harnesses, each for seconds (default 60),
#                                         built with clang in build-fuzz/
#   ./ice.sh bench [ice-bench options]    install what is missing, build, time ice against plain VTK
#   ./ice.sh valgrind [frames]            build, then valgrind memcheck on one full-ice run
#   ./ice.sh paraview [ctest options]     the ParaView stage alone: install ParaView 5.11 (in place
#                                         of Debian's VTK 9.1 dev packages), build the plugin, run
#                                         its tests; other commands swap the packages back
# Every package install waits for another program's hold on the package lock (.ci/apt-install.sh).
# ice-render needs no X server: without a working DISPLAY it renders through EGL (else OSMesa).
# The tests run under Xvfb when there is no working DISPLAY, then the tests labelled "backend"
# run again through EGL with no DISPLAY at all (Documentation/headless.md).
set -euo pipefail
cd "$(dirname "$0")"

build_dir=${VTKICE_BUILD_DIR:-build}
# ccache (installed with the build's packages) serves the compiles a build made before: another
# clone's, the next CI run's, each lane's in its chroot. CMake reads the launchers from the
# environment when it configures a new build folder. VTKICE_CCACHE=0: none.
if [ "${VTKICE_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
  export CMAKE_C_COMPILER_LAUNCHER=${CMAKE_C_COMPILER_LAUNCHER:-ccache}
  export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
fi
# Tests run in parallel, one per core (on 2 cores the VTK stage's Xvfb pass took 5.1 min instead of
# 7.8); those that measure time or memory are marked RUN_SERIAL and run alone.
test_jobs=${VTKICE_TEST_JOBS:-$(nproc)}
xvfb=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")

build() {
  bash .ci/install-deps.sh
  if [ ! -f "$build_dir/build.ninja" ]; then
    cmake -S . -B "$build_dir" -G Ninja "${configure_options[@]}"
  fi
  cmake --build "$build_dir"
}
configure_options=(-DCMAKE_BUILD_TYPE=Release)

with_display() {
  if [ -n "${DISPLAY:-}" ] && command -v xdpyinfo >/dev/null 2>&1 && xdpyinfo >/dev/null 2>&1; then
    "$@"
  else
    "${xvfb[@]}" "$@"
  fi
}

command=${1:-}
[ $# -gt 0 ] && shift
case "$command" in
  render)
    build
    "$build_dir/bin/ice-render" "$@"
    ;;
  bench)
    build
    "$build_dir/bin/ice-bench" "$@"
    ;;
  test)
    # Each stage runs whatever the other did; the machine ends as the VTK 9.1 stage needs it. A
    # stage that fails does not stop the others; the table at the end says which did.
    # VTKICE_SKIP_STAGES: words of "vtk wheel wheels paraview fuzz trixie sid" not to run.
    . .ci/stages.sh
    me=./$(basename "$0")
    stage() { # stage WORD NAME COMMAND...
      local word=$1 name=$2
      shift 2
      case " ${VTKICE_SKIP_STAGES:-} " in
        *" $word "*) stage_skip "$name" VTKICE_SKIP_STAGES ;;
        *)
          echo "== $name"
          stage_run "$name" "$@"
          ;;
      esac
    }
    # Each test once, as in the lanes (those labelled backend through EGL, the rest under X): the
    # whole run fits in CI's hour. ./ice.sh test-vtk alone runs the backend tests under X as well.
    stage vtk "VTK 9.1 stage (./ice.sh test-vtk)" \
      env VTKICE_TESTS_ONCE="${VTKICE_TESTS_ONCE:-1}" "$me" test-vtk "$@"
    stage wheel "VTK 9.7 wheel stage (./ice.sh wheel)" "$me" wheel "$@"
    stage wheels "Ready wheels (./ice.sh wheels)" "$me" wheels
    stage wheels "Ready wheels installed (./ice.sh wheels-test)" "$me" wheels-test
    stage paraview "ParaView stage (./ice.sh paraview)" "$me" paraview "$@"
    stage paraview "Debian's VTK 9.1 again" bash .ci/install-deps.sh
    stage fuzz "Fuzzing (./ice.sh fuzz 60)" "$me" fuzz 60
    # The other Debian suites, in chroots: the host's packages stay as the VTK 9.1 stage needs them.
    for suite in trixie sid; do
      stage "$suite" "Debian $suite lane (./ice.sh lane $suite)" "$me" lane "$suite" "$@"
    done
    stage_table
    ;;
  test-vtk | sanitize)
    if [ "$command" = sanitize ]; then
      # AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer: a Debug build of
      # its own; the tests get the sanitizers' options from CMake (Documentation/reliability.md).
      build_dir=${VTKICE_SANITIZE_BUILD_DIR:-build-asan}
      configure_options=(-DCMAKE_BUILD_TYPE=Debug -DVTKICE_SANITIZE=ON)
    fi
    build
    status=0
    # VTKICE_TESTS_ONCE=1 (the Debian lanes): each test runs once, those labelled backend only
    # through EGL; the X window is still met by the others (the lanes' stages fit in CI's hour).
    x_labels=()
    [ "${VTKICE_TESTS_ONCE:-0}" = 1 ] && x_labels=(-LE backend)
    with_display ctest --test-dir "$build_dir" --output-on-failure -j "$test_jobs" \
      "${x_labels[@]}" "$@" || status=1
    echo "== Through EGL without an X server (VTKICE_BACKEND=egl, tests labelled backend)"
    env -u DISPLAY VTKICE_BACKEND=egl \
      ctest --test-dir "$build_dir" --output-on-failure -j "$test_jobs" -L backend "$@" ||
      status=1
    exit "$status"
    ;;
  paraview)
    # ParaView's own VTK: a build of its own in build-paraview (Documentation/paraview.md).
    bash .ci/install-deps.sh paraview
    pv_build_dir=${VTKICE_PARAVIEW_BUILD_DIR:-build-paraview}
    if [ ! -f "$pv_build_dir/build.ninja" ]; then
      cmake -S ParaView -B "$pv_build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DPython3_EXECUTABLE=/usr/bin/python3
    fi
    cmake --build "$pv_build_dir"
    # A tall screen: the GUI test's screenshot shows the Ice property group.
    xvfb-run -a -s "-screen 0 1280x1400x24 -noreset" \
      ctest --test-dir "$pv_build_dir" --output-on-failure -j "$test_jobs" "$@"
    ;;
  wheel)
    exec bash .ci/wheel.sh "$@"
    ;;
  wheels)
    exec bash .ci/wheels.sh "$@"
    ;;
  wheels-test)
    exec bash .ci/wheels-test.sh "$@"
    ;;
  web)
    # The wheel stage's environment (.ci/wheel-env.sh), then the trame app (Documentation/web.md).
    bash .ci/install-deps.sh
    bash .ci/wheel-env.sh --web
    exec "${VTKICE_WHEEL_DIR:-build-wheel}/venv/bin/python" Examples/Web/ice_web.py "$@"
    ;;
  vtk-sdk)
    exec bash .ci/vtk-sdk.sh "$@"
    ;;
  lane)
    exec bash .ci/lane.sh "$@"
    ;;
  fuzz)
    exec bash .ci/fuzz.sh "$@"
    ;;
  soak)
    build
    exec Testing/Scripts/soak.sh "$@"
    ;;
  valgrind)
    build
    exec Testing/Scripts/valgrind.sh "$@"
    ;;
  *)
    echo "usage: ./ice.sh render [ice-render options] | ./ice.sh test [ctest options]" \
      "| ./ice.sh test-vtk [ctest options]" \
      "| ./ice.sh fuzz [seconds] | ./ice.sh soak [frames] [seed] [WxH] | ./ice.sh sanitize [ctest options]" \
      "| ./ice.sh bench [ice-bench options] | ./ice.sh valgrind [frames]" \
      "| ./ice.sh paraview [ctest options] | ./ice.sh wheel [ctest options]" \
      "| ./ice.sh wheels | ./ice.sh wheels-test" \
      "| ./ice.sh web [--port N]" \
      "| ./ice.sh vtk-sdk PREFIX | ./ice.sh lane trixie|sid [ctest options]" >&2
    exit 2
    ;;
esac
