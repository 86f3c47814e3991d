//===- Parse.cpp ----------------------------------------------------------===//
#include "wash/translator/Frontend/Parse.h"
#include "wash/translator/Emit/ProjectManifest.h"
#include "wash/translator/Frontend/DetectDimension.h"
#include "wash/translator/Frontend/ReadableFiles.h"

#include "clang/AST/ASTConsumer.h"
#include "clang/Frontend/CompilerInstance.h"
#include "clang/Frontend/FrontendAction.h"
#include "clang/Frontend/TextDiagnosticPrinter.h"
#include "clang/Lex/Lexer.h"
#include "clang/Lex/PPCallbacks.h"
#include "clang/Lex/Preprocessor.h"
#include "clang/Tooling/ArgumentsAdjusters.h"
#include "clang/Tooling/CompilationDatabase.h"
#include "clang/Tooling/Tooling.h"
#include "llvm/ADT/StringSet.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/raw_ostream.h"
#include "llvm/Support/thread.h"

#include <set>

using namespace clang;

namespace wash::tr {
namespace {

using Callback =
    std::function<void(ASTContext &, Diagnoser &, unsigned, const IncludeDirectives &)>;

/// Records every include directive the preprocessor reads, skipped ones too,
/// and the macros user files define.
class IncludeRecorder : public PPCallbacks {
public:
  IncludeRecorder(IncludeDirectives &Out, const SourceManager &SM) : Out(Out), SM(SM) {}
  void InclusionDirective(SourceLocation Hash, const Token &, StringRef, bool,
                          CharSourceRange FileName, OptionalFileEntryRef File, StringRef, StringRef,
                          const Module *, bool, SrcMgr::CharacteristicKind FileType) override {
    Out.push_back({Hash, FileName, File, FileType != SrcMgr::C_User});
  }

  void MacroDefined(const Token &Name, const MacroDirective *MD) override {
    SourceLocation Loc = MD ? MD->getLocation() : SourceLocation();
    if (Loc.isInvalid() || !Loc.isFileID() || SM.isInSystemHeader(Loc) ||
        SM.getFileID(Loc) == SM.getPreambleFileID() || SM.isWrittenInBuiltinFile(Loc) ||
        SM.isWrittenInCommandLineFile(Loc))
      return;
    std::string Spelled = Name.getIdentifierInfo()->getName().str();
    if (Seen.insert(Spelled).second)
      Out.Macros.push_back({Spelled, Loc});
  }

private:
  IncludeDirectives &Out;
  const SourceManager &SM;
  std::set<std::string> Seen;
};

class Consumer : public ASTConsumer {
public:
  Consumer(const Callback &OnAST, unsigned Dim) : OnAST(OnAST), Dim(Dim) {}
  IncludeDirectives Includes;
  void HandleTranslationUnit(ASTContext &Ctx) override {
    // A source clang rejects has only clang's errors: analysing a broken AST
    // would add noise.
    if (Ctx.getDiagnostics().hasErrorOccurred())
      return;
    Diagnoser D(Ctx.getDiagnostics(), Ctx.getSourceManager());
    OnAST(Ctx, D, Dim, Includes);
  }

private:
  const Callback &OnAST;
  unsigned Dim;
};

class Action : public ASTFrontendAction {
public:
  Action(const Callback &OnAST, unsigned Dim) : OnAST(OnAST), Dim(Dim) {}
  std::unique_ptr<ASTConsumer> CreateASTConsumer(CompilerInstance &CI, StringRef) override {
    auto C = std::make_unique<Consumer>(OnAST, Dim);
    CI.getPreprocessor().addPPCallbacks(
        std::make_unique<IncludeRecorder>(C->Includes, CI.getSourceManager()));
    return C;
  }

private:
  const Callback &OnAST;
  unsigned Dim;
};

class Factory : public tooling::FrontendActionFactory {
public:
  Factory(const Callback &OnAST, unsigned Dim) : OnAST(OnAST), Dim(Dim) {}
  std::unique_ptr<FrontendAction> create() override { return std::make_unique<Action>(OnAST, Dim); }

private:
  const Callback &OnAST;
  unsigned Dim;
};

/// The wash API headers: <prefix>/include next to an installed wash, else the
/// source tree this wash was built from.
std::string apiIncludeDir(const std::string &Exe) {
  if (!Exe.empty()) {
    llvm::SmallString<256> Dir(llvm::sys::path::parent_path(llvm::sys::path::parent_path(Exe)));
    llvm::sys::path::append(Dir, "include");
    llvm::SmallString<256> Header(Dir);
    llvm::sys::path::append(Header, "wash", "wash.hpp");
    if (llvm::sys::fs::exists(Header))
      return std::string(Dir);
  }
  return WASH_API_INCLUDE_DIR;
}

/// The WASH_DIM the user defines after `--` (0 if none; 2 for a bare -DWASH_DIM).
unsigned definedDim(const std::vector<std::string> &Args) {
  unsigned Dim = 0;
  for (size_t I = 0; I < Args.size(); ++I) {
    StringRef A = Args[I];
    if (A == "-D" && I + 1 < Args.size())
      A = Args[++I];
    else if (!A.consume_front("-D"))
      continue;
    if (A.consume_front("WASH_DIM"))
      Dim = A.consume_front("=") && A == "3" ? 3 : 2;
  }
  return Dim;
}

/// Limits on what clang's parser handles by recursion and that no bracket
/// limit (-fbracket-depth) bounds: past them it overflows even the large
/// stack it runs on, or takes minutes (an else-if chain is quadratic).
constexpr unsigned MaxPrefixOperators = 1000;
constexpr unsigned MaxElseIfChain = 16384;
constexpr unsigned MaxConditionalChain = 10000;

/// Where a raw token starts in Text.
size_t offsetOf(const Token &Tok, SourceLocation Start) {
  return Tok.getLocation().getRawEncoding() - Start.getRawEncoding();
}

/// "file:line:col: error: too deeply nested ..." at the first construct of
/// Text nested past a limit, or "" if none is. A raw lexing pass, so it
/// runs before clang's parser could overflow its stack.
std::string nestingError(const std::string &File, llvm::StringRef Text) {
  LangOptions LangOpts;
  LangOpts.CPlusPlus = LangOpts.CPlusPlus20 = true;
  SourceLocation Start = SourceLocation::getFromRawEncoding(1);
  Lexer Lex(Start, LangOpts, Text.begin(), Text.begin(), Text.end());
  unsigned Prefix = 0, Conditionals = 0;
  size_t RunStart = 0;
  // Per open brace: else-if branches so far in the chain of that block.
  std::vector<unsigned> ElseIfs(1, 0);
  tok::TokenKind Last = tok::semi;
  auto Error = [&](size_t Offset, const std::string &What) {
    size_t Line = Text.take_front(Offset).count('\n') + 1;
    size_t LineStart = Text.take_front(Offset).rfind('\n');
    size_t Col = Offset - (LineStart == llvm::StringRef::npos ? 0 : LineStart + 1) + 1;
    return File + ":" + std::to_string(Line) + ":" + std::to_string(Col) +
           ": error: too deeply nested: " + What + "; wash (and clang's parser) cannot " +
           "translate it: split it into smaller statements or functions";
  };
  Token Tok;
  while (true) {
    Lex.LexFromRawLexer(Tok);
    if (Tok.is(tok::eof))
      break;
    tok::TokenKind K = Tok.getKind();
    // A prefix operator follows an operator or an opening bracket, not an
    // operand: `a - -b` has one.
    bool AfterOperand = Last == tok::identifier || Last == tok::numeric_constant ||
                        Last == tok::r_paren || Last == tok::r_square ||
                        Last == tok::string_literal || Last == tok::char_constant;
    bool IsPrefix =
        !AfterOperand &&
        (K == tok::minus || K == tok::plus || K == tok::exclaim || K == tok::tilde ||
         K == tok::star || K == tok::amp || K == tok::plusplus || K == tok::minusminus ||
         K == tok::raw_identifier &&
             (Tok.getRawIdentifier() == "sizeof" || Tok.getRawIdentifier() == "throw"));
    if (IsPrefix) {
      if (Prefix++ == 0)
        RunStart = offsetOf(Tok, Start);
      if (Prefix > MaxPrefixOperators)
        return Error(RunStart, "more than " + std::to_string(MaxPrefixOperators) +
                                   " prefix operators in a row");
    } else {
      Prefix = 0;
    }
    if (K == tok::question && ++Conditionals > MaxConditionalChain)
      return Error(offsetOf(Tok, Start), "more than " + std::to_string(MaxConditionalChain) +
                                             " conditional operators in one statement");
    if (K == tok::semi || K == tok::l_brace || K == tok::r_brace)
      Conditionals = 0;
    if (K == tok::l_brace)
      ElseIfs.push_back(0);
    if (K == tok::r_brace && ElseIfs.size() > 1)
      ElseIfs.pop_back();
    if (K == tok::raw_identifier && Tok.getRawIdentifier() == "if" && Last == tok::raw_identifier &&
        ++ElseIfs.back() > MaxElseIfChain)
      return Error(offsetOf(Tok, Start),
                   "an else-if chain of more than " + std::to_string(MaxElseIfChain) + " branches");
    // Raw identifiers keep their kind; remember `else` to spot `else if`.
    Last = K == tok::raw_identifier
               ? (Tok.getRawIdentifier() == "else" ? tok::raw_identifier : tok::identifier)
               : K;
  }
  return "";
}

std::string absolutePath(StringRef Path) {
  llvm::SmallString<256> P(Path);
  llvm::sys::fs::make_absolute(P);
  llvm::sys::path::remove_dots(P, true);
  return std::string(P);
}

} // namespace

std::vector<std::string> inputFiles(const std::string &Source, const IncludeDirectives &Includes) {
  std::vector<std::string> Files = {absolutePath(Source)};
  llvm::StringSet<> Seen;
  Seen.insert(Files[0]);
  for (const IncludeDirective &I : Includes)
    if (I.File)
      if (std::string Path = absolutePath(I.File->getName()); Seen.insert(Path).second)
        Files.push_back(Path);
  return Files;
}

std::vector<InputFile> hashedInputFiles(clang::SourceManager &SM, const std::string &Source,
                                        const IncludeDirectives &Includes) {
  std::vector<InputFile> Files = {
      {absolutePath(Source), contentHash(SM.getBufferData(SM.getMainFileID()))}};
  llvm::StringSet<> Seen;
  Seen.insert(Files[0].Path);
  for (const IncludeDirective &I : Includes) {
    if (!I.File)
      continue;
    std::string Path = absolutePath(I.File->getName());
    if (!Seen.insert(Path).second)
      continue;
    std::optional<llvm::MemoryBufferRef> Buffer = SM.getMemoryBufferForFileOrNone(*I.File);
    Files.push_back({Path, Buffer ? contentHash(Buffer->getBuffer()) : ""});
  }
  return Files;
}

bool parseSimulation(const Options &Opts, const Callback &OnAST) {
  if (std::string Reason = unreadableReason(Opts.Source); !Reason.empty()) {
    llvm::errs() << "wash: error: cannot read '" << Opts.Source << "': " << Reason << "\n";
    return false;
  }
  auto Buffer = llvm::MemoryBuffer::getFile(Opts.Source);
  if (!Buffer) {
    llvm::errs() << "wash: error: cannot read '" << Opts.Source
                 << "': " << Buffer.getError().message() << "\n";
    return false;
  }
  if (std::string Error = nestingError(Opts.Source, (*Buffer)->getBuffer()); !Error.empty()) {
    llvm::errs() << Error << "\n";
    return false;
  }
  unsigned UserDim = definedDim(Opts.CompilerArgs);
  unsigned Dim = UserDim ? UserDim : guessDimension((*Buffer)->getBuffer());

  std::vector<std::string> Flags = {"-std=c++20"};
  Flags.insert(Flags.end(), Opts.CompilerArgs.begin(), Opts.CompilerArgs.end());
  tooling::FixedCompilationDatabase DB(".", Flags);
  // Every file clang opens, each header included, passes the checks the
  // simulation file did.
  tooling::ClangTool Tool(DB, {Opts.Source}, std::make_shared<PCHContainerOperations>(),
                          readableFilesOnly(llvm::vfs::getRealFileSystem()));
  // -x c++: a simulation is C++ whatever its file is called.
  std::vector<std::string> Baked = {"-x", "c++", "-resource-dir=" WASH_CLANG_RESOURCE_DIR,
                                    "-isystem", apiIncludeDir(Opts.ExecutablePath),
                                    // wash's SPH library is user code on the API's
                                    // path: analysed and rewritten with the simulation.
                                    "--no-system-header-prefix=wash/sph/"};
  if (!UserDim)
    Baked.push_back("-DWASH_DIM=" + std::to_string(Dim));
  Tool.appendArgumentsAdjuster(
      tooling::getInsertArgumentAdjuster(Baked, tooling::ArgumentInsertPosition::BEGIN));

  // One printer for the driver's and the compiler's diagnostics, so that an
  // error either reports (an unknown flag, say) fails the run: ClangTool
  // itself returns 0 after a driver error.
  llvm::IntrusiveRefCntPtr<DiagnosticOptions> DiagOpts = new DiagnosticOptions();
  TextDiagnosticPrinter Printer(llvm::errs(), DiagOpts.get());
  Tool.setDiagnosticConsumer(&Printer);

  Factory F(OnAST, Dim);
  int Status = 1;
  // Deeply nested hostile input must not overflow the stack: run clang and
  // the passes, which recurse over the AST, on a thread with a large one.
  llvm::thread Worker(std::optional<unsigned>(512u << 20), [&] { Status = Tool.run(&F); });
  Worker.join();
  return Status == 0 && Printer.getNumErrors() == 0;
}

} // namespace wash::tr
