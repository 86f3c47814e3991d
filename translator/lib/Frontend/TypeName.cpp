//===- TypeName.cpp -------------------------------------------------------===//
#include "wash/translator/Frontend/TypeName.h"
#include "wash/translator/Frontend/WashApi.h"

#include <algorithm>
#include <cctype>

using namespace clang;

namespace wash::tr {

std::optional<std::string> particleTypeName(const Expr *NameArg, ASTContext &Ctx, Diagnoser &D,
                                            const CallContext *Context) {
  std::optional<std::string> Name = evaluateString(NameArg, Ctx, Context);
  if (!Name) {
    D.report(DiagId::ParticleTypeNotConstant, NameArg->getExprLoc());
    return std::nullopt;
  }
  const bool Identifier = !Name->empty() && !std::isdigit((unsigned char)(*Name)[0]) &&
                          std::all_of(Name->begin(), Name->end(), [](char C) {
                            return std::isalnum((unsigned char)C) || C == '_';
                          });
  if (!Identifier) {
    D.report(DiagId::ParticleTypeInvalid, NameArg->getExprLoc(), {*Name});
    return std::nullopt;
  }
  return Name;
}

std::optional<std::string> knownParticleType(const Expr *NameArg, ASTContext &Ctx, Diagnoser &D,
                                             const std::vector<ParticleType> &Types,
                                             const CallContext *Context) {
  std::optional<std::string> Name = evaluateString(NameArg, Ctx, Context);
  if (!Name) {
    D.report(DiagId::ParticleTypeNotConstant, NameArg->getExprLoc());
    return std::nullopt;
  }
  for (const ParticleType &T : Types)
    if (T.Name == *Name)
      return Name;
  D.report(DiagId::ParticleTypeUnknown, NameArg->getExprLoc(),
           {*Name, Types.empty() ? " (this simulation adds no particle type)" : ""});
  return std::nullopt;
}

} // namespace wash::tr
