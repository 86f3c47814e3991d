//===- RewriteSource.cpp - lowering particle accesses in the user's code --===//
#include "wash/translator/Emit/RewriteSource.h"
#include "wash/translator/Emit/UserFiles.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/ParentMapContext.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/Lex/Lexer.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <string_view>
#include <tuple>

using namespace clang;

namespace wash::tr {
namespace {

bool isParticleType(QualType T) {
  const auto *RD = T.isNull() ? nullptr : T.getCanonicalType()->getAsCXXRecordDecl();
  return RD && !isa<ClassTemplateSpecializationDecl>(RD) && involvesParticle(T);
}

bool isParticleVector(QualType T) {
  const auto *Spec = T.isNull() ? nullptr
                                : dyn_cast_or_null<ClassTemplateSpecializationDecl>(
                                      T.getCanonicalType()->getAsCXXRecordDecl());
  return Spec && Spec->getName() == "vector" && involvesParticle(T);
}

/// The user's files with replacements of ranges of their text. A
/// replacement may cover earlier ones (the lowering is post-order: an
/// access's arguments are lowered before it). Edits are found by offset, so
/// the text of a range costs its length; clang's Rewriter walks the buffer
/// from its start for each, which made long kernels quadratic.
class Edits {
public:
  Edits(SourceManager &SM, const LangOptions &LangOpts, const UserFiles &Files)
      : SM(SM), LangOpts(LangOpts), Files(Files) {}

  /// The text of a token range as rewritten so far. A range that begins or
  /// ends with a whole macro expansion (`x * GAIN`, `M_PI`) is the text
  /// of the source it was written as; nullopt when it cuts into a macro.
  std::optional<std::string> text(SourceRange Range) const {
    CharSourceRange Chars = CharSourceRange::getTokenRange(Range);
    if (Range.getBegin().isMacroID() || Range.getEnd().isMacroID()) {
      Chars = Lexer::makeFileCharRange(Chars, SM, LangOpts);
      if (Chars.isInvalid())
        return std::nullopt;
    }
    FileID F = Files.rewritten(Chars.getBegin());
    if (F.isInvalid())
      return Lexer::getSourceText(Chars, SM, LangOpts).str();
    auto [Begin, End] = offsets(Chars);
    StringRef Buffer = SM.getBufferData(F);
    std::string Out;
    unsigned At = Begin;
    const auto &Replaced = Edited[F];
    for (auto I = Replaced.lower_bound(Begin); I != Replaced.end() && I->first < End; ++I) {
      Out.append(Buffer.substr(At, I->first - At));
      Out += I->second.second;
      At = std::max(At, I->second.first);
    }
    if (At < End)
      Out.append(Buffer.substr(At, End - At));
    return Out;
  }

  /// Replaces a token range of a rewritten file; the replacements inside it go.
  void replace(SourceRange Range, std::string Text) {
    FileID F = Files.rewritten(Range.getBegin());
    if (F.isInvalid())
      return;
    auto [Begin, End] = offsets(Range);
    replace(F, Begin, End, std::move(Text));
  }

  void replace(FileID F, unsigned Begin, unsigned End, std::string Text) {
    auto &Replaced = Edited[F];
    Replaced.erase(Replaced.lower_bound(Begin), Replaced.lower_bound(End));
    Replaced[Begin] = {End, std::move(Text)};
  }

  std::string result(FileID F) const {
    StringRef Buffer = SM.getBufferData(F);
    std::string Out;
    unsigned At = 0;
    for (const auto &[Begin, Edit] : Edited[F]) {
      if (Begin < At) // overlaps the one before: cannot happen post-order
        continue;
      Out.append(Buffer.substr(At, Begin - At));
      Out += Edit.second;
      At = Edit.first;
    }
    return Out.append(Buffer.substr(At));
  }

  std::pair<unsigned, unsigned> offsets(SourceRange Range) const {
    return offsets(CharSourceRange::getTokenRange(Range));
  }

  /// Whether an edit so far touches [From, To) of the file of `At`.
  bool editedBetween(SourceLocation At, unsigned From, unsigned To) const {
    FileID F = Files.rewritten(At);
    if (F.isInvalid())
      return false;
    for (const auto &[Begin, Edit] : Edited[F])
      if (Begin < To && Edit.first > From)
        return true;
    return false;
  }

private:
  std::pair<unsigned, unsigned> offsets(CharSourceRange Range) const {
    unsigned Begin = SM.getFileOffset(Range.getBegin());
    unsigned End = SM.getFileOffset(Range.getEnd());
    if (Range.isTokenRange())
      End += Lexer::MeasureTokenLength(Range.getEnd(), SM, LangOpts);
    return {Begin, std::max(Begin, End)};
  }

  SourceManager &SM;
  const LangOptions &LangOpts;
  const UserFiles &Files;
  /// Per rewritten file: begin offset -> (end offset, new text), non-overlapping.
  mutable std::map<FileID, std::map<unsigned, std::pair<unsigned, std::string>>> Edited;
};

class Lowering : public RecursiveASTVisitor<Lowering> {
public:
  Lowering(ASTContext &Ctx, const CodePlan &Plan, const UserFiles &Files, Diagnoser &D, Edits &R)
      : Ctx(Ctx), SM(Ctx.getSourceManager()), Plan(Plan), Files(Files), D(D), R(R) {}

  // Children first, so that an access's arguments are lowered before it.
  bool shouldTraversePostOrder() const { return true; }

  bool TraverseDecl(Decl *Decl) {
    // Only the user's files: the API and system headers stay as they are.
    if (Decl && !isa<TranslationUnitDecl>(Decl) && !inUserFile(Decl->getBeginLoc()))
      return true;
    return RecursiveASTVisitor::TraverseDecl(Decl);
  }

  /// An alias of the particle type (`using Particle = wash::Particle;`)
  /// names the generated particle type; its uses are rewritten where they are.
  bool TraverseTypeAliasDecl(TypeAliasDecl *Alias) {
    bool Outer = InAlias;
    InAlias = true;
    bool Result = RecursiveASTVisitor::TraverseTypeAliasDecl(Alias);
    InAlias = Outer;
    return Result;
  }
  bool TraverseTypedefDecl(TypedefDecl *Alias) {
    bool Outer = InAlias;
    InAlias = true;
    bool Result = RecursiveASTVisitor::TraverseTypedefDecl(Alias);
    InAlias = Outer;
    return Result;
  }

  bool TraverseTypeLoc(TypeLoc TL) {
    if (!TL || !inUserFile(TL.getBeginLoc()))
      return RecursiveASTVisitor::TraverseTypeLoc(TL);
    if (auto Ref = TL.getAs<LValueReferenceTypeLoc>()) {
      TypeLoc Pointee = Ref.getPointeeLoc();
      if (isParticleType(Pointee.getType()) && !Pointee.getType().isConstQualified())
        return replace({withQualifier(Pointee.getBeginLoc()), Pointee.getEndLoc()},
                       "wash_gen::Self");
    }
    if (!TL.getAs<QualifiedTypeLoc>()) {
      QualType T = TL.getType();
      if (isParticleVector(T))
        return replace({withQualifier(TL.getBeginLoc()), TL.getEndLoc()},
                       "wash_gen::NeighbourList");
      if (isParticleType(T)) // a const reference or a copy: a self or a neighbour
        return replace({withQualifier(TL.getBeginLoc()), TL.getEndLoc()},
                       InAlias ? "wash_gen::Self" : "auto");
    }
    return RecursiveASTVisitor::TraverseTypeLoc(TL);
  }

  /// An expression over one neighbour computed before the kernel: its column.
  bool VisitExpr(Expr *E) {
    if (Plan.HoistAt.empty() || E->getBeginLoc().isMacroID() || E->getEndLoc().isMacroID() ||
        !inUserFile(E->getBeginLoc()))
      return true;
    if (auto Column = Plan.hoistedText(D.toPos(E->getBeginLoc()), D.toPos(E->getEndLoc())))
      return replace(E->getSourceRange(), *Column);
    return true;
  }

  bool VisitCXXMemberCallExpr(CXXMemberCallExpr *E) {
    if (!inUserFile(E->getBeginLoc()))
      return true;
    // Distance uses are keyed by file, line and column.
    if (!Plan.DistanceAt.empty() && !E->getBeginLoc().isMacroID())
      if (auto Distance = Plan.distanceText(D.toPos(E->getBeginLoc()), text(E->getSourceRange())))
        return replace(E->getSourceRange(), *Distance);
    auto Accessor = particleAccessor(E->getMethodDecl());
    if (!Accessor)
      return true;
    const auto *Callee = dyn_cast<MemberExpr>(E->getCallee()->IgnoreParens());
    if (!Callee)
      return true;
    const Expr *Base = Callee->getBase()->IgnoreImplicit();
    // `it->get_vel()` on a class iterator: the base is the `operator->` call.
    if (const auto *Op = dyn_cast<CXXOperatorCallExpr>(Base);
        Op && Op->getOperator() == OO_Arrow && Op->getNumArgs() > 0)
      Base = Op->getArg(0);
    std::string Object = text(Base->getSourceRange());
    if (Callee->isArrow())
      Object = "(*" + Object + ")";
    bool IsSet = Accessor->How == Mode::Write;
    if (Accessor->IsType) {
      auto Type = E->getNumArgs() ? evaluateString(E->getArg(0), Ctx) : std::nullopt;
      if (!Type) // InferAccesses already rejected this; keep the pass total.
        return true;
      std::string Lowered =
          IsSet ? Plan.setTypeText(Object, *Type) : Plan.isTypeText(Object, *Type);
      return replace(E->getSourceRange(), IsSet && !isStatement(E) ? "(" + Lowered + ")" : Lowered);
    }
    std::string Field, Value;
    unsigned ValueArg = 0;
    if (Accessor->isForce()) {
      auto Name = evaluateString(E->getArg(0), Ctx);
      if (!Name) // InferAccesses already rejected this; keep the pass total.
        return true;
      Field = *Name;
      ValueArg = 1;
    } else {
      Field = Accessor->Field->Name;
    }
    if (IsSet)
      Value = text(E->getArg(ValueArg)->getSourceRange());
    std::string Lowered =
        IsSet ? Plan.writeText(Field, Object, Value) : Plan.readText(Field, Object, Accessor->Kind);
    if (IsSet && !isStatement(E))
      Lowered = "(" + Lowered + ")";
    return replace(E->getSourceRange(), Lowered);
  }

  bool VisitCallExpr(CallExpr *E) {
    const ApiCallInfo *Call = washCall(E->getDirectCallee());
    if (!inUserFile(E->getBeginLoc()) || !Call)
      return true;
    switch (Call->Lowering) {
    case CallLowering::Drop:
      return replace(E->getSourceRange(), "(void)0 /* " + registrationNote(E, *Call) + " */");
    case CallLowering::Generated:
      return replace(E->getCallee()->getSourceRange(), std::string("wash_gen::") + Call->Name);
    case CallLowering::Keep:
      if (Call->Id == ApiCall::get_variable)
        lowerVariableRead(E);
      pinCallSite(E);
      return true;
    }
    return true;
  }

  /// A kept call that leaves its CallSite to the default gets it written
  /// out, where the compiler would have put it in the user's source: the
  /// rewrite of accesses before it on its line moves its columns, and an
  /// error it reports must name the same column on every build (g++ gives
  /// the opening parenthesis, clang the start of the call's expression:
  /// wash::CallSite::written picks). Not where an earlier argument is left
  /// to its default too (the last one cannot be named alone).
  void pinCallSite(const CallExpr *E) {
    const unsigned N = E->getNumArgs();
    if (!N || E->getBeginLoc().isMacroID() || E->getRParenLoc().isMacroID() ||
        E->getCallee()->getEndLoc().isMacroID() || !isa<CXXDefaultArgExpr>(E->getArg(N - 1)))
      return;
    const auto *Site = E->getArg(N - 1)->getType()->getAsCXXRecordDecl();
    if (!Site || Site->getName() != "CallSite")
      return;
    for (unsigned I = 0; I + 1 < N; ++I)
      if (isa<CXXDefaultArgExpr>(E->getArg(I)))
        return;
    std::optional<Token> Paren =
        Lexer::findNextToken(E->getCallee()->getEndLoc(), SM, Ctx.getLangOpts());
    if (!Paren || !Paren->is(tok::l_paren))
      return;
    PresumedLoc Start = SM.getPresumedLoc(E->getBeginLoc());
    PresumedLoc Open = SM.getPresumedLoc(Paren->getLocation());
    if (Start.isInvalid() || Open.isInvalid() || !mayMove(E, Paren->getLocation()))
      return;
    replace(E->getRParenLoc(),
            std::string(N > 1 ? ", " : "") + "wash::CallSite::written(__FILE__, " +
                std::to_string(Start.getLine()) + ", " + std::to_string(Start.getColumn()) + ", " +
                std::to_string(Open.getLine()) + ", " + std::to_string(Open.getColumn()) + "))");
  }

  /// Whether the rewrite may move the call `E` on its line: an edit before
  /// its parenthesis on that line (the traversal goes left to right), or an
  /// enclosing particle access, which is lowered after it.
  bool mayMove(const CallExpr *E, SourceLocation Paren) {
    const unsigned Open = SM.getFileOffset(Paren);
    const unsigned Column = SM.getSpellingColumnNumber(E->getBeginLoc());
    const unsigned LineStart = SM.getFileOffset(E->getBeginLoc()) - (Column - 1);
    if (R.editedBetween(E->getBeginLoc(), LineStart, Open))
      return true;
    DynTypedNodeList Parents = Ctx.getParents(*E);
    while (!Parents.empty()) {
      if (const auto *Call = Parents[0].get<CXXMemberCallExpr>())
        if (particleAccessor(Call->getMethodDecl()))
          return true;
      if (!Parents[0].get<Expr>())
        return false;
      Parents = Ctx.getParents(Parents[0]);
    }
    return false;
  }

  /// `get_variable("dt")` becomes `get_variable(wash_gen::var_dt)`, a read
  /// without a lookup (wash/backend/variables.hpp). The callee and the
  /// parenthesis stay where they were, so the location the call reports an
  /// error at does too. Names known only at run time keep the lookup.
  void lowerVariableRead(const CallExpr *E) {
    if (E->getNumArgs() == 0 || E->getBeginLoc().isMacroID())
      return;
    const Expr *Arg = E->getArg(0);
    std::optional<std::string> Name = evaluateString(Arg, Ctx);
    SourceRange Range = Arg->getSourceRange();
    if (!Name || Range.getBegin().isMacroID() || Range.getEnd().isMacroID())
      return;
    if (std::find(Variables.begin(), Variables.end(), *Name) == Variables.end())
      Variables.push_back(*Name);
    replace(Range, "wash_gen::" + CodePlan::variableSlot(*Name));
  }

  /// Names the rewrite wrote into the user's code (wash_gen, P, Self, column
  /// members...), each with the first place it did: a user macro of the same
  /// name would replace them.
  std::map<std::string, SourceLocation> Introduced;

  /// The variables lowerVariableRead gave slots, in order of first use.
  std::vector<std::string> Variables;

  /// Each include directive in a rewritten file that names another one
  /// names its copy instead; `#include <wash/wash.hpp>` becomes the
  /// generated header's, which declares what the API does for generated code
  /// (both in one program would define wash::dimensions twice).
  void redirectIncludes(const IncludeDirectives &Includes) {
    for (const IncludeDirective &I : Includes) {
      FileID From = Files.rewritten(I.Hash);
      if (From.isInvalid() || !I.File)
        continue;
      FileID To = I.SystemFile ? FileID() : Files.rewritten(SM.translateFile(*I.File));
      bool Api = I.SystemFile && isApiHeader(I.File->getName());
      if (!Api && To.isInvalid())
        continue;
      if (I.Hash.isMacroID() || I.FileName.getBegin().isMacroID()) {
        D.report(DiagId::CodegenInMacro, SM.getExpansionLoc(I.Hash));
        continue;
      }
      const std::string &FromPath = Files.projectPath(From);
      unsigned Begin = SM.getFileOffset(I.FileName.getBegin());
      unsigned End = SM.getFileOffset(I.FileName.getEnd());
      if (I.FileName.isTokenRange())
        End += Lexer::MeasureTokenLength(I.FileName.getEnd(), SM, Ctx.getLangOpts());
      if (!Api) {
        R.replace(From, Begin, End, includeSpelling(FromPath, Files.projectPath(To)));
        continue;
      }
      // The whole directive, from the start of its line when only blanks
      // come before it.
      unsigned Hash = SM.getFileOffset(I.Hash);
      StringRef Buffer = SM.getBufferData(From);
      size_t LineStart = Buffer.rfind('\n', Hash);
      LineStart = LineStart == StringRef::npos ? 0 : LineStart + 1;
      if (Buffer.slice(LineStart, Hash).find_first_not_of(" \t") == StringRef::npos)
        Hash = LineStart;
      R.replace(From, Hash, End, "#include " + includeSpelling(FromPath, Plan.headerName()));
    }
  }

private:
  bool inUserFile(SourceLocation L) const { return Files.rewritten(L).isValid(); }

  static bool isApiHeader(StringRef Name) {
    return Name.ends_with("/wash/wash.hpp") || Name == "wash/wash.hpp";
  }

  /// Begin moved back over a written `std::` or `wash::` (or `::wash::`,
  /// `a::b::`) that the TypeLoc under a cv-qualifier does not cover.
  SourceLocation withQualifier(SourceLocation Begin) const {
    if (Begin.isMacroID())
      return Begin;
    const char *Start = SM.getBufferData(SM.getFileID(Begin)).data();
    const char *P = SM.getCharacterData(Begin);
    while (true) {
      const char *Q = P;
      while (Q > Start && (Q[-1] == ' ' || Q[-1] == '\t'))
        --Q;
      if (Q - Start < 2 || Q[-1] != ':' || Q[-2] != ':')
        break;
      Q -= 2;
      while (Q > Start && (Q[-1] == ' ' || Q[-1] == '\t'))
        --Q;
      while (Q > Start && (std::isalnum((unsigned char)Q[-1]) || Q[-1] == '_'))
        --Q;
      P = Q;
    }
    return Begin.getLocWithOffset(-(SM.getCharacterData(Begin) - P));
  }

  /// The text of a range as rewritten so far; a range that cuts into a macro
  /// expansion cannot be rewritten.
  std::string text(SourceRange Range) const {
    if (std::optional<std::string> Text = R.text(Range))
      return *Text;
    D.report(DiagId::CodegenInMacro, Range.getBegin());
    return "";
  }

  /// What a dropped registration did, for the comment that replaces it: the
  /// call as written, whitespace collapsed except for newlines (the line
  /// count must not change), and nothing that ends or opens a comment.
  std::string registrationNote(const CallExpr *E, const ApiCallInfo &Call) const {
    std::string Written = text(E->getSourceRange()), Note;
    for (size_t I = 0; I < Written.size();) {
      if (!std::isspace((unsigned char)Written[I])) {
        char C = Written[I++];
        Note += C;
        // `*/` would end the comment, `/*` draws -Wcomment.
        if ((C == '*' || C == '/') && I < Written.size() && Written[I] == (C == '*' ? '/' : '*'))
          Note += ' ';
        continue;
      }
      size_t End = Written.find_first_not_of(" \t\n\v\f\r", I);
      std::string_view Space(Written.data() + I,
                             (End == std::string::npos ? Written.size() : End) - I);
      size_t Newlines = std::count(Space.begin(), Space.end(), '\n');
      Note += Newlines ? std::string(Newlines, '\n') : " ";
      I += Space.size();
    }
    if (Call.Id == ApiCall::allow_shared_state)
      return Note + ": a marker for the translator";
    return Note + (Call.Kernel ? ": run by the driver" : ": registered by the translator");
  }

  /// The identifiers of Text outside comments and string and character
  /// literals (where macros do not expand).
  static std::map<std::string, unsigned> identifiers(const std::string &Text) {
    std::map<std::string, unsigned> Names;
    for (size_t I = 0; I < Text.size();) {
      if (Text.compare(I, 2, "/*") == 0) {
        size_t End = Text.find("*/", I + 2);
        I = End == std::string::npos ? Text.size() : End + 2;
        continue;
      }
      if (Text.compare(I, 2, "//") == 0) {
        size_t End = Text.find('\n', I);
        I = End == std::string::npos ? Text.size() : End;
        continue;
      }
      if (Text[I] == '"' || Text[I] == '\'') {
        size_t End = I + 1;
        while (End < Text.size() && Text[End] != Text[I])
          End += Text[End] == '\\' ? 2 : 1;
        I = End + 1;
        continue;
      }
      if (std::isdigit((unsigned char)Text[I])) { // a number's suffix is not a name
        while (I < Text.size() && (std::isalnum((unsigned char)Text[I]) || Text[I] == '.'))
          ++I;
        continue;
      }
      if (!std::isalpha((unsigned char)Text[I]) && Text[I] != '_') {
        ++I;
        continue;
      }
      size_t End = I;
      while (End < Text.size() && (std::isalnum((unsigned char)Text[End]) || Text[End] == '_'))
        ++End;
      ++Names[Text.substr(I, End - I)];
      I = End;
    }
    return Names;
  }

  void noteIntroducedNames(const std::string &Old, const std::string &New, SourceLocation At) {
    // Counted: `p.set_density(P)` keeps the user's P and adds wash_gen::P.
    std::map<std::string, unsigned> Before = identifiers(Old);
    for (const auto &[Name, Count] : identifiers(New))
      if (Count > Before[Name])
        Introduced.try_emplace(Name, At);
  }

  /// Whether E's value is unused: it is a statement of its own.
  bool isStatement(const Expr *E) const {
    auto Parents = Ctx.getParents(*E);
    if (Parents.empty())
      return false;
    if (const auto *P = Parents[0].get<Stmt>())
      return !isa<Expr>(P) || isa<ExprWithCleanups>(P) && isStatement(cast<Expr>(P));
    return false;
  }

  /// Replaces Range (token range) keeping the number of lines, so the user's
  /// line numbers still hold in the generated file.
  bool replace(SourceRange Range, std::string Text) {
    if (Range.getBegin().isMacroID() || Range.getEnd().isMacroID()) {
      D.report(DiagId::CodegenInMacro, Range.getBegin());
      return true;
    }
    // Each range of a file is rewritten once: the traversal can reach one
    // TypeLoc twice (a parameter through its declaration and through the
    // function's type), and a header included twice is one file of the
    // project, rewritten as its first inclusion reads (a later one's text,
    // computed over those edits, would nest them).
    auto [Begin, End] = R.offsets(Range);
    if (!Done.insert({Files.rewritten(Range.getBegin()), Begin, End}).second)
      return true;
    std::string Old = text(Range);
    noteIntroducedNames(Old, Text, Range.getBegin());
    size_t Lines = std::count(Old.begin(), Old.end(), '\n');
    size_t NewLines = std::count(Text.begin(), Text.end(), '\n');
    if (NewLines < Lines)
      Text.append(Lines - NewLines, '\n');
    R.replace(Range, std::move(Text));
    return true;
  }

  ASTContext &Ctx;
  SourceManager &SM;
  const CodePlan &Plan;
  const UserFiles &Files;
  Diagnoser &D;
  Edits &R;
  /// The ranges rewritten: (file, begin offset, end offset).
  std::set<std::tuple<FileID, unsigned, unsigned>> Done;
  bool InAlias = false;
};

} // namespace

std::optional<std::vector<RewrittenFile>> rewriteSource(ASTContext &Ctx, const CodePlan &Plan,
                                                        const IncludeDirectives &Includes,
                                                        Diagnoser &D,
                                                        std::vector<std::string> *Variables) {
  UserFiles Files(Ctx.getSourceManager(), Includes, Plan.sourceName());
  Edits R(Ctx.getSourceManager(), Ctx.getLangOpts(), Files);
  Lowering L(Ctx, Plan, Files, D, R);
  L.TraverseDecl(Ctx.getTranslationUnitDecl());
  L.redirectIncludes(Includes);
  for (const UserMacro &Macro : Includes.Macros)
    if (auto It = L.Introduced.find(Macro.Name); It != L.Introduced.end()) {
      D.report(DiagId::MacroNamesGeneratedCode, Macro.Loc, {Macro.Name});
      D.report(DiagId::NoteGeneratedNameHere, It->second, {Macro.Name});
    }
  if (D.hasErrors())
    return std::nullopt;
  if (Variables)
    *Variables = L.Variables;
  std::vector<RewrittenFile> Out;
  for (FileID F : Files.files())
    Out.push_back({Files.original(F), Files.projectPath(F), R.result(F)});
  return Out;
}

} // namespace wash::tr
