//===- WashApi.h - recognising the wash API in the AST ----------*- C++ -*-===//
//
// The frontend passes recognise the API by declaration (namespace wash, the
// Particle class), never by spelling, so aliases and using-declarations work;
// what a declaration means comes from the table (WashApi.def).
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/WashApiTable.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Decl.h"
#include "clang/AST/Expr.h"

#include <initializer_list>
#include <optional>
#include <string>

namespace wash::tr {

struct CallContext;

/// FD is a free function directly in namespace wash (the API or its math).
bool isWashFunction(const clang::FunctionDecl *FD);
/// The table's entry for FD, if it is one of the API's free functions.
const ApiCallInfo *washCall(const clang::FunctionDecl *FD);
/// FD is the API function Id.
bool isWashCall(const clang::FunctionDecl *FD, ApiCall Id);
/// One of the calls main uses to configure and register (readFromMain).
bool isRegistrationFunction(const clang::FunctionDecl *FD);
/// FD is a member function of wash::Particle.
bool isParticleMethod(const clang::FunctionDecl *FD);
/// The accessor FD is, if it is a wash::Particle getter, setter or force accessor.
std::optional<ParticleAccessor> particleAccessor(const clang::FunctionDecl *FD);
/// T mentions wash::Particle: the class, a reference or pointer to it, or a
/// std::vector of it (what a helper must receive to access particles).
bool involvesParticle(clang::QualType T);
/// The D of wash::Vec<T, D>, through typedefs, references and cv-qualifiers.
std::optional<unsigned> vecDimension(clang::QualType T);

/// N is one of Names (a function or method name the passes know).
inline bool isOneOf(llvm::StringRef N, std::initializer_list<llvm::StringRef> Names) {
  for (llvm::StringRef S : Names)
    if (N == S)
      return true;
  return false;
}

/// D is in a file the user wrote, not a system header (the standard library,
/// the wash API, which is passed with -isystem).
bool isUserCode(const clang::SourceManager &SM, const clang::Decl *D);

/// The value of a string argument: a literal, a constant the evaluator can
/// fold, or a const variable (std::string, const char *) initialised by one,
/// as C++ evaluates it (a literal up to its first NUL; not std::string(s, n)).
/// A parameter is read as the call in Context binds it (its argument, or its
/// default when the caller passes none); without a context, as every call of
/// its function binds it when they all agree and are all visible
/// (ParameterBindings.h). A parameter the function may change is not constant.
std::optional<std::string> evaluateString(const clang::Expr *E, clang::ASTContext &Ctx,
                                          const CallContext *Context = nullptr);
std::optional<long long> evaluateInt(const clang::Expr *E, clang::ASTContext &Ctx,
                                     const CallContext *Context = nullptr);
/// Shortest text that reads back as the same double.
std::optional<std::string> evaluateNumber(const clang::Expr *E, clang::ASTContext &Ctx,
                                          const CallContext *Context = nullptr);
/// The source text of E, for settings only known at run time.
std::string sourceText(const clang::Expr *E, clang::ASTContext &Ctx);

} // namespace wash::tr
