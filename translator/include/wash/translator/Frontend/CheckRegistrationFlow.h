//===- CheckRegistrationFlow.h - registrations run once, before start ----===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Frontend/ProgramIndex.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Decl.h"

namespace wash::tr {

/// The generated driver makes every registration main reaches exactly once,
/// before the run, so a registration that may be skipped or repeated when
/// wash::start runs (under an if, a switch, ?:, && or ||, in a try block or
/// a handler, after an early return, in a function using goto, in a
/// recursive function, after wash::start) would mean something else in the
/// translated program: reports it at the call. Also reports a wash::start
/// that may run more than once. Walks main like collectSimulation (calls as
/// if inlined), iteratively. Returns false on error.
bool checkRegistrationFlow(ProgramIndex &Index, Diagnoser &D, const clang::FunctionDecl *Main);

} // namespace wash::tr
