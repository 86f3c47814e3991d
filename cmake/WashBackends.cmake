# wash_read_backends(<file>): reads backends/backends.def, the one list of
# backends, into WASH_BACKENDS (every backend, in order) and
# WASH_DISTRIBUTED_BACKENDS (those that run as several processes), in the
# caller's scope.
function(wash_read_backends file)
  file(STRINGS "${file}" lines REGEX "^WASH_BACKEND\\(")
  set(all "")
  set(distributed "")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^WASH_BACKEND\\(([A-Za-z0-9_]+), ([a-z0-9_]+), \"[^\"]*\", ([01])\\)")
      message(FATAL_ERROR "${file}: cannot read the line '${line}'")
    endif()
    list(APPEND all ${CMAKE_MATCH_2})
    if(CMAKE_MATCH_3 STREQUAL "1")
      list(APPEND distributed ${CMAKE_MATCH_2})
    endif()
  endforeach()
  set(WASH_BACKENDS ${all} PARENT_SCOPE)
  set(WASH_DISTRIBUTED_BACKENDS ${distributed} PARENT_SCOPE)
endfunction()
