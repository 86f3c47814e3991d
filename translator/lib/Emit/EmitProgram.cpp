//===- EmitProgram.cpp - plan, rewrite, emit ------------------------------===//
#include "wash/translator/Emit/EmitProgram.h"
#include "wash/translator/Emit/CodePlan.h"
#include "wash/translator/Emit/EmitCMakeLists.h"
#include "wash/translator/Emit/EmitDriver.h"
#include "wash/translator/Emit/EmitStorage.h"
#include "wash/translator/Emit/RewriteSource.h"

#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/raw_ostream.h"

#include <algorithm>

#ifndef WASH_BUILD_PACKAGE_DIR
#define WASH_BUILD_PACKAGE_DIR ""
#endif

namespace wash::tr {
namespace {

/// A name for FD that the driver, at namespace scope, can call.
std::string calleeName(const clang::FunctionDecl *FD) {
  std::string Name = FD->getQualifiedNameAsString();
  const std::string Anonymous = "(anonymous namespace)::";
  for (size_t At; (At = Name.find(Anonymous)) != std::string::npos;)
    Name.erase(At, Anonymous.size());
  return "::" + Name;
}

std::string absolute(const std::string &Path) {
  llvm::SmallString<256> P(Path);
  llvm::sys::fs::make_absolute(P);
  llvm::sys::path::remove_dots(P, true);
  return std::string(P);
}

/// `#line Line "File"`, File escaped as a C string: a folder may be named
/// with a '"' or a backslash.
std::string lineDirective(size_t Line, llvm::StringRef File) {
  std::string Text = "#line " + std::to_string(Line) + " \"";
  for (char C : File) {
    if (C == '"' || C == '\\')
      Text += '\\';
    if (C == '\n')
      Text += "\\n";
    else
      Text += C;
  }
  return Text + "\"\n";
}

/// The user's macros that could meet an identifier of the generated header
/// or driver (not reserved names, NDEBUG or WASH_ settings, which configure
/// rather than name things).
std::vector<std::string> macrosToHide(const IncludeDirectives &Includes) {
  std::vector<std::string> Names;
  for (const UserMacro &M : Includes.Macros)
    if (M.Name[0] != '_' && M.Name != "NDEBUG" && M.Name.rfind("WASH_", 0) != 0)
      Names.push_back(M.Name);
  return Names;
}

/// Generated code between hideMacros and restoreMacros sees none of Names.
std::string hideMacros(const std::vector<std::string> &Names) {
  std::string Out;
  for (const std::string &N : Names)
    Out += "#pragma push_macro(\"" + N + "\")\n#undef " + N + "\n";
  return Out;
}

std::string restoreMacros(const std::vector<std::string> &Names) {
  std::string Out;
  for (const std::string &N : Names)
    Out += "#pragma pop_macro(\"" + N + "\")\n";
  return Out;
}

/// Header, its first line (#pragma once or a comment) kept first, with the
/// user's macros hidden inside it.
std::string withMacrosHidden(const std::string &Header, const std::vector<std::string> &Names) {
  if (Names.empty())
    return Header;
  size_t Once = Header.find("#pragma once\n");
  size_t At = Once == std::string::npos ? 0 : Once + 13;
  return Header.substr(0, At) + hideMacros(Names) + Header.substr(At) + restoreMacros(Names);
}

} // namespace

std::vector<std::string> packageHints(const std::string &ExecutablePath) {
  std::vector<std::string> Hints;
  llvm::SmallString<256> Installed(llvm::sys::path::parent_path(ExecutablePath));
  llvm::sys::path::append(Installed, "..", "lib", "cmake", "wash");
  llvm::sys::path::remove_dots(Installed, true);
  if (llvm::sys::fs::exists(Installed + "/washConfig.cmake"))
    Hints.push_back(std::string(Installed));
  if (std::string(WASH_BUILD_PACKAGE_DIR) != "")
    Hints.push_back(WASH_BUILD_PACKAGE_DIR);
  return Hints;
}

bool emitProgram(clang::ASTContext &Ctx, Diagnoser &D, const Model &M, const AstRefs &Refs,
                 const IncludeDirectives &Includes, const Options &Opts,
                 std::vector<GeneratedFile> &Files) {
  CodePlan Plan = planCode(M, Opts.Target, llvm::sys::path::stem(Opts.Source).str());
  std::optional<std::vector<RewrittenFile>> Rewritten =
      rewriteSource(Ctx, Plan, Includes, D, &Plan.Variables);
  if (!Rewritten)
    return false;
  for (RewrittenFile &F : *Rewritten)
    if (F.Text.empty() || F.Text.back() != '\n')
      F.Text += '\n';
  std::string *Body = &Rewritten->front().Text;

  std::vector<std::string> Callees;
  for (const clang::FunctionDecl *FD : Refs.Kernels)
    Callees.push_back(calleeName(FD));

  // The user's code keeps its own file name and line numbers (#line), so
  // compiler messages and CallSite locations point at the simulation source.
  std::string Source = generatedBanner(Plan) + lineDirective(1, absolute(Opts.Source)) + *Body;
  // The driver follows the user's code: their macros must not reach it.
  const std::vector<std::string> Hidden = macrosToHide(Includes);
  Source += hideMacros(Hidden);
  size_t NextLine = std::count(Source.begin(), Source.end(), '\n') + 2;
  Source += lineDirective(NextLine, Plan.sourceName()) + emitDriver(M, Plan, Callees);

  Files = {{Plan.headerName(), withMacrosHidden(emitStorageHeader(M, Plan), Hidden)},
           {Plan.sourceName(), Source},
           {"CMakeLists.txt", emitCMakeLists(Plan, packageHints(Opts.ExecutablePath))}};
  // Each header the simulation includes, rewritten, keeps its file name and
  // line numbers the same way.
  for (size_t I = 1; I < Rewritten->size(); ++I) {
    const RewrittenFile &F = (*Rewritten)[I];
    Files.push_back({F.ProjectPath, generatedBanner(Plan) + lineDirective(1, F.Original) + F.Text});
  }
  return true;
}

} // namespace wash::tr
