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

/// Writes Path (a temporary file, then renamed): the depfile `Target: Inputs`
/// in Makefile syntax, as compilers write with -MD and as CMake's
/// add_custom_command(DEPFILE) and Ninja read. Target and Inputs are made
/// absolute. Returns an error message, or "" on success.
std::string writeDepfile(const std::string &Path, const std::string &Target,
                         const std::vector<std::string> &Inputs);

} // namespace wash::tr
