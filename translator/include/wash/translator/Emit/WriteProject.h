//===- WriteProject.h - the generated CMake project on disk ----*- C++ -*-===//
#pragma once

#include <string>
#include <vector>

namespace wash::tr {

struct GeneratedFile {
  std::string Name; ///< Relative to the output directory.
  std::string Text;
};

/// Writes Files into Dir (created if needed) as a whole: staged beside Dir
/// and renamed into place, so an error leaves the previous content. Dir must
/// be new, empty or a previous wash project (it holds the marker file
/// `.wash-project` listing what wash wrote); other files in it are kept.
/// Returns an error message, or "" on success.
std::string writeProject(const std::string &Dir, const std::vector<GeneratedFile> &Files);

} // namespace wash::tr
