//===- wash/mpi/watchdog.hpp - ending a job whose rank stopped answering -*- C++ -*-===//
//
// A rank that is stopped (SIGSTOP, a frozen host) leaves the others waiting in
// a collective for ever. Each rank runs a watchdog thread: when its main
// thread has made no progress (no collective call returned) for the watchdog
// time, it asks every other rank's watchdog whether it is alive, on a
// communicator of its own; a rank that gives no answer within the watchdog
// time again is named, and the job ends (MPI_Abort). A rank that is only slow
// still answers, so a long step or a long write is never taken for a hang.
// The main thread's part is one clock read and two relaxed stores per
// collective call; the thread wakes ten times a second.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <optional>
#include <string>

namespace wash::mpi {

/// The watchdog time when --watchdog is not given: 10 times the longest time
/// between two collective calls so far, at least this.
constexpr double defaultWatchdogSeconds = 60.0;

/// The thread level to ask MPI_Init_thread for: the watchdog thread calls MPI
/// while the main thread waits in a collective.
int watchdogThreadLevel(std::optional<double> seconds);

/// After MPI_Init_thread: starts the watchdog (not with one rank, nor with
/// --watchdog 0, nor where MPI gave less than `watchdogThreadLevel`).
/// `seconds`: --watchdog, if given; `program` starts its message.
void startWatchdog(std::optional<double> seconds, int providedThreadLevel, std::string program);
/// Before MPI_Finalize, on every rank (collective): stops it.
void stopWatchdog();

/// The main thread made progress (a collective call returned).
void progressed();

} // namespace wash::mpi
