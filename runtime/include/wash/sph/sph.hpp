//===- wash/sph/sph.hpp - the whole SPH library -----------------*- C++ -*-===//
//
// wash's SPH library: kernels, equations of state, artificial dissipation,
// Adami walls and time-step criteria, written against the public API like a
// simulation's own headers (the translator rewrites them with the
// simulation). See docs/sph-library.md.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/sph/diagnostics.hpp>
#include <wash/sph/dissipation.hpp>
#include <wash/sph/eos.hpp>
#include <wash/sph/kernels.hpp>
#include <wash/sph/time_step.hpp>
#include <wash/sph/walls.hpp>
