# The two HDF5 flavours of --format hdf5, as Debian installs them side by side:
# serial (libhdf5-dev: headers in /usr/include/hdf5/serial, libhdf5_serial)
# for the reference, serial and openmp runtimes, and parallel over Open MPI
# (libhdf5-openmpi-dev: /usr/include/hdf5/openmpi, libhdf5_openmpi) for the
# mpi backend. Both are required (scripts/install-deps.sh installs them).
# wash_hdf5_library(<flavour> <target>): a static library <target> of the
# H5Part writer (runtime/src/hdf5/h5part.cpp) built against that flavour.
find_path(WASH_HDF5_SERIAL_INCLUDE_DIR hdf5.h PATHS /usr/include/hdf5/serial NO_DEFAULT_PATH)
find_library(WASH_HDF5_SERIAL_LIBRARY NAMES hdf5_serial)
find_path(WASH_HDF5_OPENMPI_INCLUDE_DIR hdf5.h PATHS /usr/include/hdf5/openmpi NO_DEFAULT_PATH)
find_library(WASH_HDF5_OPENMPI_LIBRARY NAMES hdf5_openmpi)

function(wash_hdf5_library flavour target)
  string(TOUPPER "${flavour}" upper)
  if(NOT WASH_HDF5_${upper}_INCLUDE_DIR OR NOT WASH_HDF5_${upper}_LIBRARY)
    set(package libhdf5-dev)
    if(flavour STREQUAL "openmpi")
      set(package libhdf5-openmpi-dev)
    endif()
    message(FATAL_ERROR "wash: the ${flavour} HDF5 library was not found "
      "(Debian: ${package}; scripts/install-deps.sh installs it)")
  endif()
  add_library(${target} STATIC "${PROJECT_SOURCE_DIR}/runtime/src/hdf5/h5part.cpp")
  target_include_directories(${target} SYSTEM PRIVATE "${WASH_HDF5_${upper}_INCLUDE_DIR}")
  target_link_libraries(${target} PUBLIC wash_api PRIVATE "${WASH_HDF5_${upper}_LIBRARY}")
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
