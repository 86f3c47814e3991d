//===- WriteProject.h - the generated CMake project on disk ----*- C++ -*-===//
#pragma once

#include <string>
#include <vector>

namespace wash::tr {

struct GeneratedFile {
  std::string Name; ///< Relative to the output directory.
  std::string Text;
};

/// What one translation writes.
struct ProjectOutput {
  std::string Dir; ///< -o; a symbolic link is followed.
  std::vector<GeneratedFile> Files;
  /// --depfile ("" for none; a symbolic link is followed), and the program
  /// it names as the target.
  std::string DepFile;
  std::string DepTarget;
  /// Every file the translation read: never written over, --force or not.
  std::vector<std::string> Inputs;
  /// --force: overwrite files wash did not write, or that changed since.
  bool Force = false;
};

/// Writes the project into Dir (created if needed) as a whole: staged beside
/// Dir and renamed into place, so an error leaves the previous content; then
/// the depfile. Dir must be new, empty or a previous wash project (it holds
/// `.wash-project`, the manifest of what wash wrote there and each file's
/// content hash). A file wash would write or remove that it did not write,
/// or whose content changed since, is refused unless Force; an input always.
/// Other files in Dir are kept. Returns an error message, or "" on success.
std::string writeOutputs(const ProjectOutput &Out);

/// The depfile `Target: Inputs` in Makefile syntax, as compilers write with
/// -MD and as CMake's add_custom_command(DEPFILE) and Ninja read. Target and
/// Inputs are made absolute.
std::string depfileText(const std::string &Target, const std::vector<std::string> &Inputs);

} // namespace wash::tr
