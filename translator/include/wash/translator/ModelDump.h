//===- ModelDump.h - the model as stable text -------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <ostream>

namespace wash::tr {

/// Prints the model for --dump-model: one fact per line, fields listed in
/// Model::Fields order, no addresses or paths that change between machines
/// (locations are line:col in the simulation file), so the text can be
/// checked in and diffed.
void dumpModel(const Model &M, std::ostream &OS);

} // namespace wash::tr
