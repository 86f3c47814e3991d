//===- UserFiles.h - the user's files a translation rewrites ----*- C++ -*-===//
//
// The main file and every user file it reaches through include directives
// (quoted, or found on an include path the user passed: anything that is not
// a system header) are rewritten like the main file. The copies go into the
// generated project: the main file as the program's source, each header
// under `user/`, at its path relative to the folder that holds them all, so
// that the project mirrors the user's layout and never touches the originals.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Frontend/Includes.h"

#include "clang/Basic/SourceManager.h"

#include <map>
#include <string>
#include <vector>

namespace wash::tr {

class UserFiles {
public:
  /// The main file (its copy at MainPath) and the user files Includes reach.
  UserFiles(const clang::SourceManager &SM, const IncludeDirectives &Includes,
            const std::string &MainPath);

  /// The FileID of the first inclusion of Loc's file if wash rewrites that
  /// file, else an invalid one. Every inclusion of a file shares its edits.
  clang::FileID rewritten(clang::SourceLocation Loc) const;
  clang::FileID rewritten(clang::FileID F) const;
  /// Where F's copy goes, relative to the generated project's root.
  const std::string &projectPath(clang::FileID F) const { return Path.at(F); }
  /// The user's file, absolute.
  const std::string &original(clang::FileID F) const { return Original.at(F); }
  /// The rewritten files: the main file first, then the headers.
  const std::vector<clang::FileID> &files() const { return Order; }

private:
  const clang::SourceManager &SM;
  std::map<clang::FileID, std::string> Path, Original;
  std::vector<clang::FileID> Order;
  mutable std::map<clang::FileID, clang::FileID> Canonical;
};

/// The quoted-include spelling of the project file To seen from the project
/// file From: `"detail/x.hpp"`, `"../../sim.wash.hpp"`.
std::string includeSpelling(const std::string &From, const std::string &To);

} // namespace wash::tr
