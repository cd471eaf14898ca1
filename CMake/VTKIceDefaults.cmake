# Settings every VTK Ice project shares (the main build and ParaView/): C++17, a Release build
# unless told otherwise, shared libraries (VTK's Python and ClientServer wrapping need them).
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
if (NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif ()
set(BUILD_SHARED_LIBS ON)
