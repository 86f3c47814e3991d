//===- ModelDump.h - the model as stable text -------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <ostream>

namespace wash::tr {

/// Prints the model for --dump-model: one fact per line, fields listed in
/// Model::Fields order, no addresses or paths that change between machines
/// (locations are line:col in the simulation file), so the text can be
/// checked in and diffed. --dump-after prints a model that later passes have
/// not filled in yet: what they derive is still at its default (no fields,
/// empty sets, `dead`, `search: -1`, no searches).
void dumpModel(const Model &M, std::ostream &OS);

} // namespace wash::tr
