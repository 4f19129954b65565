# fissure_library(NAME SOURCES ... DEPENDS ...): one static library per module
# folder, with the repository root on the include path so that headers are
# included as "core/geometry/polygon.h".
function(fissure_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPENDS})
endfunction()

# fissure_module(NAME DIR DEPENDS ...): a library from every .cpp below the
# module folder's sub-folders (one sub-folder per process or component).
function(fissure_module name)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  fissure_library(${name} SOURCES ${sources} DEPENDS ${ARG_DEPENDS})
endfunction()
