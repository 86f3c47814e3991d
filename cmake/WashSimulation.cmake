# wash_add_reference(<target> SOURCE <file.cpp> [DIM 2|3] [INCLUDE_DIRECTORIES <dir>...])
#
# Builds a simulation source untranslated, against the reference runtime: the
# program that defines what the simulation computes. INCLUDE_DIRECTORIES are
# the folders its own headers are included from (relative ones from the
# current source folder).
function(wash_add_reference target)
  cmake_parse_arguments(ARG "" "SOURCE;DIM" "INCLUDE_DIRECTORIES" ${ARGN})
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
  foreach(include_dir IN LISTS ARG_INCLUDE_DIRECTORIES)
    get_filename_component(include_dir "${include_dir}" ABSOLUTE)
    target_include_directories(${target} PRIVATE "${include_dir}")
  endforeach()
  target_link_libraries(${target} PRIVATE wash::reference${ARG_DIM}d)
endfunction()

# wash_add_simulation(<target> SOURCE <file.cpp> BACKEND <one of WASH_BACKENDS>
#                     [INCLUDE_DIRECTORIES <dir>...])
#
# Translates a simulation source with the wash translator as a build step and
# builds the generated program against that backend's runtime. Headers the
# source includes (quoted, or found in INCLUDE_DIRECTORIES, relative ones from
# the current source folder) are translated with it. The translation reruns
# when the source or any file it includes changes (the translator's depfile).
function(wash_add_simulation target)
  cmake_parse_arguments(ARG "" "SOURCE;BACKEND" "INCLUDE_DIRECTORIES" ${ARGN})
  if(NOT ARG_SOURCE OR NOT ARG_BACKEND)
    message(FATAL_ERROR "wash_add_simulation(${target}): SOURCE and BACKEND are required")
  endif()
  if(NOT ARG_BACKEND IN_LIST WASH_BACKENDS)
    list(JOIN WASH_BACKENDS ", " names)
    message(FATAL_ERROR
      "wash_add_simulation(${target}): BACKEND must be one of ${names}, not '${ARG_BACKEND}'")
  endif()
  if(NOT TARGET wash::${ARG_BACKEND})
    message(FATAL_ERROR "wash_add_simulation(${target}): the ${ARG_BACKEND} backend is not built")
  endif()
  if(NOT TARGET wash::wash)
    message(FATAL_ERROR "wash_add_simulation(${target}): the wash translator is not available")
  endif()
  get_filename_component(source "${ARG_SOURCE}" ABSOLUTE)
  get_filename_component(stem "${source}" NAME_WE)
  set(dir "${CMAKE_CURRENT_BINARY_DIR}/${target}.wash")
  set(generated "${dir}/${stem}.${ARG_BACKEND}.cpp")
  set(depfile "${CMAKE_CURRENT_BINARY_DIR}/${target}.wash.d")
  set(compiler_args "")
  foreach(include_dir IN LISTS ARG_INCLUDE_DIRECTORIES)
    get_filename_component(include_dir "${include_dir}" ABSOLUTE)
    list(APPEND compiler_args "-I${include_dir}")
  endforeach()
  if(compiler_args)
    list(PREPEND compiler_args "--")
  endif()
  add_custom_command(OUTPUT "${generated}" "${dir}/${stem}.wash.hpp"
    COMMAND wash::wash --backend=${ARG_BACKEND} "${source}" -o "${dir}" --depfile "${depfile}"
            ${compiler_args}
    DEPENDS "${source}" wash::wash
    DEPFILE "${depfile}"
    COMMENT "wash: translating ${stem} for the ${ARG_BACKEND} backend"
    VERBATIM)
  add_executable(${target} "${generated}")
  target_include_directories(${target} PRIVATE "${dir}")
  target_link_libraries(${target} PRIVATE wash::${ARG_BACKEND})
endfunction()
