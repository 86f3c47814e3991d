//===- wash/backend/program.hpp - what generated code includes ----*- C++ -*-===//
//
// Generated programs include this instead of <wash/wash.hpp>: the API's
// vectors, constants and settings, plus the pieces the generated driver uses.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/cell_grid.hpp>
#include <wash/backend/columns.hpp>
#include <wash/backend/frame_builder.hpp>
#include <wash/backend/neighbours.hpp>
#include <wash/backend/periodic.hpp>
#include <wash/backend/reduce.hpp>
#include <wash/backend/run.hpp>
#include <wash/math.hpp>
#include <wash/settings.hpp>
#include <wash/vec.hpp>
