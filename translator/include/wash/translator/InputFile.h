//===- InputFile.h - a file the translation read ----------------*- C++ -*-===//
#pragma once

#include <string>

namespace wash::tr {

/// An input of the translation and the SHA-256 of its content as the parse
/// read it, in hex ("" if it could not be hashed).
struct InputFile {
  std::string Path; ///< Absolute.
  std::string Hash;
};

} // namespace wash::tr
