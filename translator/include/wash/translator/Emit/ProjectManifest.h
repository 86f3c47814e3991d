//===- ProjectManifest.h - what wash wrote, by content ----------*- C++ -*-===//
//
// A generated project holds `.wash-project`: every file wash wrote there,
// and the depfile it wrote with it, with the SHA-256 of its content. A file
// whose content differs from its record (the user edited it), or that has
// none, is not wash's to overwrite or remove.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "llvm/ADT/StringRef.h"

#include <map>
#include <optional>
#include <string>

namespace wash::tr {

inline constexpr const char *ManifestName = ".wash-project";

struct Manifest {
  /// Each file's path (relative to the project; absolute for the depfile)
  /// and the SHA-256 of its content in hex.
  std::map<std::string, std::string> Files;
  /// Written by a wash that recorded names only (December 2026): its files
  /// are known by wash's banner atop them.
  bool NamesOnly = false;
};

/// The SHA-256 of Text, in lower-case hex.
std::string contentHash(llvm::StringRef Text);

/// The manifest file's text.
std::string manifestText(const Manifest &M);

/// The manifest in Dir, if it holds one.
std::optional<Manifest> readManifest(const std::string &Dir);

/// Whether Path is a regular file (not a symbolic link) holding what M
/// recorded for Name.
bool holdsRecordedContent(const std::string &Path, const Manifest &M, const std::string &Name);

} // namespace wash::tr
