//===- wash/backend/run.hpp - what a generated program's start() calls -*- C++ -*-===//
//
// The run around the generated kernels is the runtime's shared one
// (wash/detail/run.hpp, wash/detail/run_settings.hpp), the same the reference
// runtime uses; these are the names generated code spells it with.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/detail/run.hpp>
#include <wash/detail/run_settings.hpp>

namespace wash::backend {

using Settings = detail::RunSettings;
/// Generated storage headers set settings().dimensions in a static initialiser.
inline Settings &settings() { return detail::runSettings(); }
using detail::programOptions;

using detail::finite;
using detail::Run;
using detail::Translation;

} // namespace wash::backend
