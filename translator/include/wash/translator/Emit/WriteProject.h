//===- WriteProject.h - the generated CMake project on disk ----*- C++ -*-===//
#pragma once

#include <string>
#include <vector>

namespace wash::tr {

struct GeneratedFile {
  std::string Name; ///< Relative to the output directory.
  std::string Text;
};

/// Writes Files into Dir (created if needed). Each file is written to a
/// temporary name first and renamed, so an error leaves no partial file.
/// Returns an error message, or "" on success.
std::string writeProject(const std::string &Dir, const std::vector<GeneratedFile> &Files);

} // namespace wash::tr
