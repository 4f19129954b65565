# Precompiled headers: most of a translation unit's compile time is parsing
# the headers every one of them includes (Eigen/Core 1.5 s, nlohmann/json
# 1.3 s, yaml-cpp 0.7 s, fmt 0.5 s each, measured alone). They are parsed
# once, into fissure_core's precompiled header, which every other library
# reuses (and once more with gtest for the tests: tests/CMakeLists.txt).
set(FISSURE_PRECOMPILED_HEADERS
    <algorithm> <functional> <map> <memory> <optional> <string> <vector>
    <Eigen/Core> <Eigen/Dense> <Eigen/SparseCore> <fmt/format.h> <nlohmann/json.hpp>
    <yaml-cpp/yaml.h>)

# fissure_library(NAME SOURCES ... DEPENDS ...): one static library per module
# folder, with the repository root on the include path so that headers are
# included as "core/geometry/polygon.h".
function(fissure_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPENDS})
  if(name STREQUAL "fissure_core")
    target_precompile_headers(${name} PRIVATE ${FISSURE_PRECOMPILED_HEADERS})
  else()
    target_precompile_headers(${name} REUSE_FROM fissure_core)
  endif()
endfunction()

# fissure_module(NAME DIR DEPENDS ...): a library from every .cpp below the
# module folder's sub-folders (one sub-folder per process or component).
function(fissure_module name)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  fissure_library(${name} SOURCES ${sources} DEPENDS ${ARG_DEPENDS})
endfunction()
