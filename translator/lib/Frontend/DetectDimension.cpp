//===- DetectDimension.cpp ------------------------------------------------===//
#include "wash/translator/Frontend/DetectDimension.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/Lex/Lexer.h"

using namespace clang;

namespace wash::tr {

unsigned guessDimension(llvm::StringRef Source) {
  LangOptions LO;
  LO.CPlusPlus = LO.CPlusPlus20 = true;
  Lexer L(SourceLocation(), LO, Source.begin(), Source.begin(), Source.end());
  Token T;
  bool AfterVec = false; // Inside `Vec<...`: the last number before `>` is D.
  unsigned LastNumber = 0;
  while (!L.LexFromRawLexer(T) || T.isNot(tok::eof)) {
    if (T.is(tok::eof))
      break;
    if (T.is(tok::raw_identifier)) {
      StringRef Id = T.getRawIdentifier();
      if (Id == "Vec2D")
        return 2;
      if (Id == "Vec3D")
        return 3;
      AfterVec = Id == "Vec";
      LastNumber = 0;
      continue;
    }
    if (!AfterVec)
      continue;
    if (T.is(tok::numeric_constant)) {
      StringRef N(T.getLiteralData(), T.getLength());
      LastNumber = N == "2" ? 2 : N == "3" ? 3 : 0;
    } else if (T.is(tok::greater)) {
      if (LastNumber)
        return LastNumber;
      AfterVec = false;
    } else if (T.isOneOf(tok::semi, tok::l_brace, tok::r_brace)) {
      AfterVec = false;
    }
  }
  return 2;
}

namespace {
/// Finds the first written vector type of each dimension in user code.
class VecFinder : public RecursiveASTVisitor<VecFinder> {
public:
  explicit VecFinder(const SourceManager &SM) : SM(SM) {}
  bool VisitTypeLoc(TypeLoc TL) {
    SourceLocation L = TL.getBeginLoc();
    if (L.isInvalid() || SM.isInSystemHeader(SM.getExpansionLoc(L)))
      return true;
    if (auto D = vecDimension(TL.getType()))
      if (*D == 2 || *D == 3)
        if (First[*D - 2].isInvalid() || SM.isBeforeInTranslationUnit(L, First[*D - 2]))
          First[*D - 2] = L;
    return true;
  }
  SourceLocation First[2];

private:
  const SourceManager &SM;
};
} // namespace

std::optional<unsigned> detectDimension(ASTContext &Ctx, Diagnoser &D, unsigned ParsedDim) {
  VecFinder F(Ctx.getSourceManager());
  F.TraverseAST(Ctx);
  SourceLocation L2 = F.First[0], L3 = F.First[1];
  if (L2.isValid() && L3.isValid()) {
    bool TwoFirst = Ctx.getSourceManager().isBeforeInTranslationUnit(L2, L3);
    D.report(DiagId::MixedDimensions, TwoFirst ? L3 : L2,
             {TwoFirst ? "2" : "3", TwoFirst ? "3" : "2"});
    D.report(DiagId::NoteFirstVectorHere, TwoFirst ? L2 : L3, {TwoFirst ? "2" : "3"});
    return std::nullopt;
  }
  return L3.isValid() ? 3 : L2.isValid() ? 2 : ParsedDim;
}

} // namespace wash::tr
