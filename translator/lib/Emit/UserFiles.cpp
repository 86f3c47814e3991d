//===- UserFiles.cpp ------------------------------------------------------===//
#include "wash/translator/Emit/UserFiles.h"

#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Path.h"

using namespace clang;

namespace wash::tr {
namespace {

namespace path = llvm::sys::path;

std::string absolute(llvm::StringRef Name) {
  llvm::SmallString<256> P(Name);
  llvm::sys::fs::make_absolute(P);
  path::remove_dots(P, /*remove_dot_dot=*/true);
  return std::string(P);
}

/// The deepest folder holding both A and B.
std::string commonFolder(llvm::StringRef A, llvm::StringRef B) {
  std::string Out;
  for (auto I = path::begin(A), J = path::begin(B);
       I != path::end(A) && J != path::end(B) && *I == *J; ++I, ++J) {
    llvm::SmallString<256> P(Out);
    path::append(P, *I);
    Out = std::string(P);
  }
  return Out;
}

/// For a header of wash's SPH library (<dir>/wash/sph/..., next to
/// <dir>/wash/wash.hpp), its path from <dir>: "wash/sph/kernels.hpp".
std::string libraryPath(llvm::StringRef Name) {
  size_t At = Name.rfind("/wash/sph/");
  if (At == llvm::StringRef::npos)
    return "";
  llvm::SmallString<256> Api(Name.substr(0, At));
  path::append(Api, "wash", "wash.hpp");
  if (!llvm::sys::fs::exists(Api))
    return "";
  return Name.substr(At + 1).str();
}

} // namespace

UserFiles::UserFiles(const SourceManager &SM, const IncludeDirectives &Includes,
                     const std::string &MainPath)
    : SM(SM) {
  FileID Main = SM.getMainFileID();
  Order.push_back(Main);
  if (OptionalFileEntryRef FE = SM.getFileEntryRefForID(Main))
    Original[Main] = absolute(FE->getName());
  Path[Main] = MainPath;
  // Headers included from user code that are user code themselves.
  for (const IncludeDirective &I : Includes) {
    if (!I.File || I.SystemFile || I.Hash.isInvalid() || SM.isInSystemHeader(I.Hash))
      continue;
    FileID F = SM.translateFile(*I.File);
    if (F.isInvalid() || Original.count(F))
      continue;
    Original[F] = absolute(I.File->getName());
    Order.push_back(F);
  }
  // wash's SPH library goes to user/wash/sph/, the user's own headers to
  // user/ under the deepest folder holding them all and the simulation.
  std::string Root = path::parent_path(Original[Main]).str();
  for (size_t K = 1; K < Order.size(); ++K) {
    std::string Library = libraryPath(Original[Order[K]]);
    if (!Library.empty())
      Path[Order[K]] = "user/" + Library;
    else
      Root = commonFolder(Root, path::parent_path(Original[Order[K]]));
  }
  for (size_t K = 1; K < Order.size(); ++K) {
    if (Path.count(Order[K]))
      continue;
    llvm::StringRef Relative = Original[Order[K]];
    Relative.consume_front(Root);
    Relative = Relative.ltrim('/');
    Path[Order[K]] = "user/" + Relative.str();
  }
}

FileID UserFiles::rewritten(FileID F) const {
  if (F.isInvalid())
    return F;
  auto [It, New] = Canonical.try_emplace(F);
  if (New) {
    OptionalFileEntryRef FE = SM.getFileEntryRefForID(F);
    FileID First = FE ? SM.translateFile(*FE) : FileID();
    It->second = Path.count(First) ? First : FileID();
  }
  return It->second;
}

FileID UserFiles::rewritten(SourceLocation Loc) const {
  if (Loc.isInvalid())
    return FileID();
  return rewritten(SM.getFileID(SM.getExpansionLoc(Loc)));
}

std::string includeSpelling(const std::string &From, const std::string &To) {
  llvm::StringRef Dir = path::parent_path(From);
  llvm::SmallVector<llvm::StringRef, 8> FromParts, ToParts;
  for (auto I = path::begin(Dir); I != path::end(Dir); ++I)
    FromParts.push_back(*I);
  for (auto I = path::begin(To); I != path::end(To); ++I)
    ToParts.push_back(*I);
  size_t Common = 0;
  while (Common < FromParts.size() && Common + 1 < ToParts.size() &&
         FromParts[Common] == ToParts[Common])
    ++Common;
  std::string Out;
  for (size_t K = Common; K < FromParts.size(); ++K)
    Out += "../";
  for (size_t K = Common; K < ToParts.size(); ++K)
    Out += ToParts[K].str() + (K + 1 < ToParts.size() ? "/" : "");
  return "\"" + Out + "\"";
}

} // namespace wash::tr
