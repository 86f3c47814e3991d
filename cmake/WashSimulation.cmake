# wash_add_reference(<target> SOURCE <file.cpp> [DIM 2|3])
#
# Builds a simulation source untranslated, against the reference runtime: the
# program that defines what the simulation computes.
function(wash_add_reference target)
  cmake_parse_arguments(ARG "" "SOURCE;DIM" "" ${ARGN})
  if(NOT ARG_SOURCE)
    message(FATAL_ERROR "wash_add_reference(${target}): SOURCE is required")
  endif()
  if(NOT ARG_DIM)
    set(ARG_DIM 2)
  endif()
  if(NOT ARG_DIM MATCHES "^[23]$")
    message(FATAL_ERROR "wash_add_reference(${target}): DIM must be 2 or 3, not '${ARG_DIM}'")
  endif()
  add_executable(${target} ${ARG_SOURCE})
  target_link_libraries(${target} PRIVATE wash::reference${ARG_DIM}d)
endfunction()
