//===- Diagnoser.cpp ------------------------------------------------------===//
#include "wash/translator/Frontend/Diagnoser.h"

#include "clang/Basic/FileManager.h"

using namespace clang;

namespace wash::tr {

Diagnoser::Diagnoser(DiagnosticsEngine &Engine, SourceManager &SM) : Engine(Engine), SM(SM) {
#define WASH_DIAG(Name, Level, Message)                                                            \
  Ids.push_back(Engine.getCustomDiagID(DiagnosticsEngine::Level, Message));
#include "wash/translator/DiagnosticKinds.def"
}

void Diagnoser::report(DiagId Id, SourceLocation Loc, llvm::ArrayRef<std::string> Args) {
  bool IsNote = diagLevel(Id) == DiagLevel::Note;
  if (IsNote && LastDropped)
    return;
  if (!IsNote) {
    LastDropped = !Seen.insert({Loc.getRawEncoding(), Id}).second;
    if (LastDropped)
      return;
  }
  if (diagLevel(Id) == DiagLevel::Error)
    ++Errors;
  auto Builder = Engine.Report(Loc, Ids[static_cast<unsigned>(Id)]);
  for (const std::string &A : Args)
    Builder << A;
}

void Diagnoser::report(const Finding &F) {
  report(F.Id, fromPos(F.Pos), F.Args);
  for (const Finding &N : F.Notes)
    report(N);
}

SourcePos Diagnoser::toPos(SourceLocation Loc) const {
  if (Loc.isInvalid())
    return {};
  SourceLocation E = SM.getExpansionLoc(Loc);
  OptionalFileEntryRef FE = SM.getFileEntryRefForID(SM.getFileID(E));
  return {FE ? FE->getName().str() : std::string(), SM.getExpansionLineNumber(E),
          SM.getExpansionColumnNumber(E)};
}

SourceLocation Diagnoser::fromPos(const SourcePos &P) const {
  if (!P.valid())
    return {};
  auto FE = SM.getFileManager().getOptionalFileRef(P.File);
  if (!FE)
    return {};
  return SM.translateFileLineCol(*FE, P.Line, P.Col);
}

} // namespace wash::tr
