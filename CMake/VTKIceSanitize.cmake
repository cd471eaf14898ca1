# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# VTKICE_SANITIZE: build everything of VTK Ice with AddressSanitizer (with LeakSanitizer) and
# UndefinedBehaviorSanitizer, and run the tests with the sanitizers' options
# (Documentation/reliability.md). Use a build folder of its own: ./ice.sh sanitize.
option(VTKICE_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)

if (VTKICE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  # ASan's runtime must be the first library of a process. Programs built here link it first;
  # programs that are not (Debian's Python, the install test's consumer project) only load
  # instrumented libraries, so they get it with LD_PRELOAD.
  execute_process(COMMAND "${CMAKE_CXX_COMPILER}" -print-file-name=libasan.so
    OUTPUT_VARIABLE VTKICE_ASAN_RUNTIME OUTPUT_STRIP_TRAILING_WHITESPACE)
  # halt_on_error: the first report ends the test with a failure. Allocation stacks use the fast
  # (frame pointer) unwinder: the slow one deadlocks in libgcc's unwinder when llvmpipe's JIT
  # registers frames (malloc inside _Unwind_Find_FDE, which holds its lock).
  set(vtkice_asan_options "halt_on_error=1:detect_leaks=1")
  set(VTKICE_SANITIZER_ENVIRONMENT
    "ASAN_OPTIONS=${vtkice_asan_options}"
    "UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1"
    "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/Testing/Sanitizers/lsan.supp:print_suppressions=0")
  # For uninstrumented programs: the runtime preloaded, and no leak check (CPython, bash and
  # CMake do not free their heap at exit; their leaks are not VTK Ice's).
  set(VTKICE_SANITIZER_PRELOAD_ENVIRONMENT
    "ASAN_OPTIONS=${vtkice_asan_options}:detect_leaks=0"
    "UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1"
    "VTKICE_ASAN_RUNTIME=${VTKICE_ASAN_RUNTIME}")
endif ()

# Keeps Mesa's drivers loaded in `target` until exit, so that LeakSanitizer names the library of
# every leak (Testing/Sanitizers/IceKeepDriversLoaded.cxx). Nothing without VTKICE_SANITIZE.
function (vtkice_sanitize_keep_drivers target)
  if (NOT VTKICE_SANITIZE)
    return ()
  endif ()
  set(drivers
    "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/dri/swrast_dri.so" # Mesa for GLX and EGL
    "libOSMesa.so.8")                                          # the osmesa back end
  list(TRANSFORM drivers PREPEND "\"")
  list(TRANSFORM drivers APPEND "\"")
  list(JOIN drivers ", " drivers)
  target_sources("${target}" PRIVATE
    "${PROJECT_SOURCE_DIR}/Testing/Sanitizers/IceKeepDriversLoaded.cxx")
  set_property(SOURCE "${PROJECT_SOURCE_DIR}/Testing/Sanitizers/IceKeepDriversLoaded.cxx"
    TARGET_DIRECTORY "${target}" APPEND PROPERTY COMPILE_DEFINITIONS "VTKICE_KEEP_LOADED=${drivers}")
endfunction ()

# Gives the tests of the calling folder the sanitizers' environment (nothing without
# VTKICE_SANITIZE). PRELOAD_ALL: every test's command is an uninstrumented program (Python),
# run with the runtime in LD_PRELOAD and no leak check. PRELOAD: tests whose scripts start
# uninstrumented programs; they get VTKICE_ASAN_RUNTIME to preload for those, and no leak check.
function (vtkice_sanitize_tests)
  if (NOT VTKICE_SANITIZE)
    return ()
  endif ()
  cmake_parse_arguments(PARSE_ARGV 0 arg "PRELOAD_ALL" "" "PRELOAD")
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach (test IN LISTS tests)
    if (arg_PRELOAD_ALL)
      set(environment ${VTKICE_SANITIZER_PRELOAD_ENVIRONMENT} "LD_PRELOAD=${VTKICE_ASAN_RUNTIME}")
    elseif (test IN_LIST arg_PRELOAD)
      set(environment ${VTKICE_SANITIZER_PRELOAD_ENVIRONMENT})
    else ()
      set(environment ${VTKICE_SANITIZER_ENVIRONMENT})
    endif ()
    set_property(TEST "${test}" APPEND PROPERTY ENVIRONMENT ${environment})
  endforeach ()
endfunction ()
