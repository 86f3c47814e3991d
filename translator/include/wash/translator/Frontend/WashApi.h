//===- WashApi.h - recognising the wash API in the AST ----------*- C++ -*-===//
//
// The frontend passes recognise the API by declaration (namespace wash, the
// Particle class), never by spelling, so aliases and using-declarations work.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "clang/AST/ASTContext.h"
#include "clang/AST/Decl.h"
#include "clang/AST/Expr.h"

#include <optional>
#include <string>

namespace wash::tr {

/// FD is the free function wash::Name (Name empty: any function directly in wash).
bool isWashFunction(const clang::FunctionDecl *FD, llvm::StringRef Name = {});
/// One of the calls main uses to configure and register: set_*, add_*, start.
bool isRegistrationFunction(const clang::FunctionDecl *FD);
/// FD is a member function of wash::Particle.
bool isParticleMethod(const clang::FunctionDecl *FD);
/// T mentions wash::Particle: the class, a reference or pointer to it, or a
/// std::vector of it (what a helper must receive to access particles).
bool involvesParticle(clang::QualType T);
/// The D of wash::Vec<T, D>, through typedefs, references and cv-qualifiers.
std::optional<unsigned> vecDimension(clang::QualType T);

/// D is in a file the user wrote, not a system header (the standard library,
/// the wash API, which is passed with -isystem).
bool isUserCode(const clang::SourceManager &SM, const clang::Decl *D);

/// The value of a string argument: a literal, a constant the evaluator can
/// fold, or a const variable (std::string, const char *) initialised by one.
std::optional<std::string> evaluateString(const clang::Expr *E, clang::ASTContext &Ctx);
std::optional<long long> evaluateInt(const clang::Expr *E, clang::ASTContext &Ctx);
/// Shortest text that reads back as the same double.
std::optional<std::string> evaluateNumber(const clang::Expr *E, clang::ASTContext &Ctx);
/// The source text of E, for settings only known at run time.
std::string sourceText(const clang::Expr *E, clang::ASTContext &Ctx);

} // namespace wash::tr
