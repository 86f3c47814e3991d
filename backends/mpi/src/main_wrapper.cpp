//===- main_wrapper.cpp - the entry point of MPI programs ---------------===//
//
// MPI is initialised before the simulation's main and finalised after it. A
// failure on any rank ends the whole job (MPI_Abort) instead of leaving the
// other ranks waiting in a collective. Ranks other than 0 write no standard
// output: the simulation's own prints and the run summary appear once.
//
//===----------------------------------------------------------------------===//
#include <wash/backend/thread_waiting.hpp>
#include <wash/detail/checkpoint.hpp>
#include <wash/detail/entry.hpp>
#include <wash/detail/hdf5_series.hpp>
#include <wash/mpi/comm.hpp>
#include <wash/mpi/watchdog.hpp>

#include <mpi.h>

#include <cstdio>
#include <cstdlib>

extern "C" int __real_main(int argc, char **argv);
extern "C" int __wrap_main(int argc, char **argv) {
  wash::backend::boundThreadWaiting(argv); // before MPI starts
  // --watchdog decides the thread level, before runProgram reads (and checks)
  // every option.
  std::optional<double> watchdog;
  try {
    watchdog = wash::detail::parseProgramOptions(argc, argv).options.watchdog;
  } catch (const wash::detail::OptionError &) {
  }
  // A rank waiting for a message polls; beside other processes on its core
  // (more ranks than cores, or a busy machine) it then yields the core
  // (Open MPI reads this in MPI_Init; the user's setting is kept).
  setenv("OMPI_MCA_mpi_yield_when_idle", "1", /*overwrite=*/0);
  int provided = 0;
  MPI_Init_thread(&argc, &argv, wash::mpi::watchdogThreadLevel(watchdog), &provided);
  wash::mpi::startWatchdog(watchdog, provided, argc > 0 ? argv[0] : "wash");
  if (wash::mpi::rank() != 0 && !std::freopen("/dev/null", "w", stdout))
    std::fprintf(stderr, "wash mpi: rank %d could not silence its standard output\n",
                 wash::mpi::rank());
  wash::detail::processes() = &wash::mpi::writerProcesses();
  wash::detail::hdf5Opener() = &wash::detail::openParallelHdf5Series;
  int status = wash::detail::runProgram(argc, argv, &__real_main);
  std::fflush(stdout);
  // A run stopped by a signal stopped on every rank, its checkpoint complete.
  if (status != 0 && status != wash::detail::interruptedExitStatus && wash::mpi::ranks() > 1)
    MPI_Abort(MPI_COMM_WORLD, status);
  wash::mpi::stopWatchdog();
  MPI_Finalize();
  return status;
}
