//===- WriteProject.cpp - the generated project, written atomically -------===//
//
// The whole project is written to a staging folder beside the output folder
// and swapped in with one rename, so that a failure (a full disk, say)
// leaves the previous project or nothing, never a mix. wash writes only into
// a new or empty folder or one holding its manifest (ProjectManifest.h),
// which lists the files it wrote there with their content hashes; anything
// else in such a folder (a build folder, say, or a file in `user/`) is the
// user's and is carried over untouched. A file wash would write or remove
// that it did not write, or that changed since, is refused (--force
// overrides); an input of the translation always is.
//
// -o and --depfile at a symbolic link are written through it: the link stays.
//
// A folder that cannot be swapped (the working directory or one above it, a
// mount point) is filled in place instead: every file is written in full to
// a staging folder inside it first, then renamed over its old version.
//
//===----------------------------------------------------------------------===//
#include "wash/translator/Emit/WriteProject.h"
#include "wash/translator/Emit/ProjectManifest.h"

#include "llvm/ADT/STLExtras.h"
#include "llvm/ADT/StringSet.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Path.h"

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <optional>
#include <system_error>
#include <unistd.h>

namespace wash::tr {
namespace {

namespace fs = llvm::sys::fs;
namespace path = llvm::sys::path;

std::string join(llvm::StringRef Dir, llvm::StringRef Name) {
  llvm::SmallString<256> P(Dir);
  path::append(P, Name);
  return std::string(P);
}

std::string errnoMessage() { return std::error_code(errno, std::generic_category()).message(); }

/// Writes Text to a new file Path; every failed write or close is reported.
std::string writeFile(const std::string &Path, llvm::StringRef Text) {
  int FD = ::open(Path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (FD < 0)
    return "cannot create '" + Path + "': " + errnoMessage();
  const char *Data = Text.data();
  size_t Left = Text.size();
  while (Left > 0) {
    ssize_t N = ::write(FD, Data, Left);
    if (N < 0 && errno == EINTR)
      continue;
    if (N <= 0) {
      std::string Why = N < 0 ? errnoMessage() : "nothing written";
      ::close(FD);
      return "cannot write '" + Path + "': " + Why;
    }
    Data += N;
    Left -= static_cast<size_t>(N);
  }
  if (::close(FD) != 0)
    return "cannot write '" + Path + "': " + errnoMessage();
  return "";
}

/// Creates the folders above Name inside Dir.
std::string makeParents(const std::string &Dir, llvm::StringRef Name) {
  llvm::StringRef Parent = path::parent_path(Name);
  if (Parent.empty())
    return "";
  if (std::error_code EC = fs::create_directories(join(Dir, Parent)))
    return "cannot create folder '" + join(Dir, Parent) + "': " + EC.message();
  return "";
}

/// The folders that the manifest's files lie in, relative to the project.
llvm::StringSet<> recordedFolders(const Manifest &M) {
  llvm::StringSet<> Folders;
  for (const auto &Record : M.Files)
    for (llvm::StringRef P = path::parent_path(Record.first); !P.empty() && !path::is_absolute(P);
         P = path::parent_path(P))
      Folders.insert(P);
  return Folders;
}

/// What Dir holds now.
struct Existing {
  bool Exists = false;
  /// It holds a previous project's manifest, Previous.
  bool HasProject = false;
  Manifest Previous;
  /// Entries wash did not write (relative paths; a folder as a whole).
  std::vector<std::string> Theirs;
  /// Files wash wrote whose content changed since.
  std::vector<std::string> Changed;
};

/// Sorts the entries of the folder Rel of Dir into E: wash's files, changed
/// or not, wash's folders (walked), the rest.
std::string walk(const std::string &Dir, const std::string &Rel, const llvm::StringSet<> &Folders,
                 Existing &E) {
  std::string Here = Rel.empty() ? Dir : join(Dir, Rel);
  std::error_code EC;
  for (fs::directory_iterator I(Here, EC), End; I != End && !EC; I.increment(EC)) {
    std::string Name = (Rel.empty() ? "" : Rel + "/") + path::filename(I->path()).str();
    std::string Path = join(Dir, Name);
    fs::file_status Status;
    if (Name == ManifestName)
      continue;
    if (E.Previous.Files.count(Name)) {
      if (!holdsRecordedContent(Path, E.Previous, Name))
        E.Changed.push_back(Name);
    } else if (Folders.contains(Name) && !fs::status(Path, Status, /*Follow=*/false) &&
               Status.type() == fs::file_type::directory_file) {
      if (std::string Error = walk(Dir, Name, Folders, E); !Error.empty())
        return Error;
    } else {
      E.Theirs.push_back(Name);
    }
  }
  if (EC)
    return "cannot read output folder '" + Here + "': " + EC.message();
  return "";
}

/// Dir's content, or an error if wash must not write there.
std::string inspect(const std::string &Dir, Existing &E) {
  fs::file_status Status;
  if (fs::status(Dir, Status))
    return "";
  if (Status.type() != fs::file_type::directory_file)
    return "output folder '" + Dir + "' exists and is not a folder";
  E.Exists = true;
  std::error_code EC;
  fs::directory_iterator First(Dir, EC);
  if (EC)
    return "cannot read output folder '" + Dir + "': " + EC.message();
  if (First == fs::directory_iterator())
    return "";
  std::optional<Manifest> Previous = readManifest(Dir);
  if (!Previous)
    return "output folder '" + Dir + "' is not empty and holds no wash project (no '" +
           ManifestName + "' file); wash never overwrites files it did not write: choose a new " +
           "or empty folder with -o";
  E.HasProject = true;
  E.Previous = std::move(*Previous);
  return walk(Dir, "", recordedFolders(E.Previous), E);
}

/// Whether Name is Entry or lies inside the folder Entry.
bool within(llvm::StringRef Name, llvm::StringRef Entry) {
  return Name == Entry || (Name.starts_with(Entry) && Name[Entry.size()] == '/');
}

/// Refuses to overwrite or remove what wash did not write or what changed
/// since, unless Force; Replaced gets the user's entries --force replaces.
std::string checkOwnership(const ProjectOutput &Out, const std::string &Dir, const Existing &E,
                           llvm::StringSet<> &Replaced) {
  const char *HowToProceed = ": move or delete it, or rerun with --force to overwrite it";
  for (const GeneratedFile &F : Out.Files)
    for (const std::string &Name : E.Theirs)
      if (within(F.Name, Name)) {
        if (!Out.Force)
          return "'" + join(Dir, Name) + "' was not written by wash; it is not overwritten" +
                 HowToProceed;
        Replaced.insert(Name);
      }
  if (!E.Changed.empty() && !Out.Force)
    return "'" + join(Dir, E.Changed.front()) +
           "' was written by wash but has changed since (its content is not what wash " +
           "recorded); it is not overwritten" + HowToProceed;
  return "";
}

/// Absolute, without `.` and `..`.
std::string absolute(llvm::StringRef Path) {
  llvm::SmallString<256> P(Path);
  fs::make_absolute(P);
  path::remove_dots(P, /*remove_dot_dot=*/true);
  return std::string(P);
}

/// Refuses to write or remove any of the translation's inputs, --force or
/// not: the generated files, the manifest, the previous project's files and
/// the depfile are compared with each input by identity (device and inode).
std::string checkInputs(const ProjectOutput &Out, const std::string &Dir, const Existing &E,
                        const std::string &DepFile) {
  std::vector<fs::UniqueID> Inputs;
  for (const std::string &Input : Out.Inputs)
    if (fs::UniqueID Id; !fs::getUniqueID(Input, Id))
      Inputs.push_back(Id);
  auto IsInput = [&](const std::string &Path) {
    fs::UniqueID Id;
    return !fs::getUniqueID(Path, Id) && llvm::is_contained(Inputs, Id);
  };
  const char *Why = "' is a file the translation reads (the simulation or a header it includes); "
                    "wash never writes over its input: choose another ";
  if (!DepFile.empty() && IsInput(DepFile))
    return "depfile '" + DepFile + Why + "--depfile";
  std::vector<std::string> Written = {ManifestName};
  for (const GeneratedFile &F : Out.Files)
    Written.push_back(F.Name);
  for (const auto &Record : E.Previous.Files)
    if (!path::is_absolute(Record.first))
      Written.push_back(Record.first);
  for (const std::string &Name : Written)
    if (IsInput(join(Dir, Name)))
      return "'" + join(Dir, Name) + Why + "output folder with -o";
  return "";
}

/// Name in a depfile: spaces, `#` and `$` escaped as Make and Ninja read them.
std::string depfileName(llvm::StringRef Name) {
  std::string Out;
  for (char C : absolute(Name)) {
    if (C == ' ' || C == '#' || C == '\\')
      Out += '\\';
    if (C == '$')
      Out += '$';
    Out += C;
  }
  return Out;
}

/// Refuses a depfile that would overwrite a file of the project or a file
/// wash did not write: one the previous project recorded (by content), or
/// one naming this project's program as its target, is wash's.
std::string checkDepfile(const ProjectOutput &Out, const std::string &Dir, const Existing &E,
                         const std::string &DepFile) {
  if (DepFile.empty())
    return "";
  std::string Abs = absolute(DepFile);
  for (const GeneratedFile &F : Out.Files)
    if (Abs == absolute(join(Dir, F.Name)))
      return "depfile '" + DepFile + "' is a file of the generated project: choose another " +
             "--depfile";
  if (Abs == absolute(join(Dir, ManifestName)))
    return "depfile '" + DepFile + "' is wash's manifest: choose another --depfile";
  for (const std::string &Name : Out.Inputs)
    if (Name.find_first_of("\n\r") != std::string::npos)
      return "cannot write depfile '" + DepFile + "': the path of '" + Name +
             "' has a line break, which a depfile cannot express";
  fs::file_status Status;
  if (fs::status(DepFile, Status, /*Follow=*/false))
    return "";
  if (Status.type() == fs::file_type::directory_file)
    return "depfile '" + DepFile + "' is a folder: choose another --depfile";
  if (Out.Force || holdsRecordedContent(DepFile, E.Previous, Abs))
    return "";
  if (Status.type() == fs::file_type::regular_file)
    if (auto Buffer = llvm::MemoryBuffer::getFile(DepFile))
      if ((*Buffer)->getBuffer().starts_with(depfileName(Out.DepTarget) + ":"))
        return "";
  return "'" + DepFile + "' exists and is not the depfile wash wrote for this project; it is " +
         "not overwritten: delete it, or rerun with --force to overwrite it";
}

/// Path with a symbolic link at its end followed (-o and --depfile are
/// written through, never replaced); Error set if the link dangles.
std::string followLink(const std::string &Path, const std::string &What, std::string &Error) {
  fs::file_status Status;
  if (fs::status(Path, Status, /*Follow=*/false) || Status.type() != fs::file_type::symlink_file)
    return Path;
  llvm::SmallString<256> Target;
  if (std::error_code EC = fs::real_path(Path, Target)) {
    Error = What + " '" + Path + "' is a symbolic link whose target cannot be found (" +
            EC.message() + "); wash writes through a link, never over it: create the target " +
            "or remove the link";
    return Path;
  }
  return std::string(Target);
}

/// Writes every file and the manifest into the new folder Stage.
std::string stage(const std::string &Stage, const std::vector<GeneratedFile> &Files,
                  const Manifest &New) {
  for (const GeneratedFile &F : Files) {
    if (std::string Error = makeParents(Stage, F.Name); !Error.empty())
      return Error;
    if (std::string Error = writeFile(join(Stage, F.Name), F.Text); !Error.empty())
      return Error;
  }
  return writeFile(join(Stage, ManifestName), manifestText(New));
}

/// A new, empty folder named after Base; "" if none can be made.
std::string makeStagingFolder(const std::string &Base) {
  for (unsigned I = 0; I < 100; ++I) {
    std::string Name = Base + "." + std::to_string(::getpid()) + "." + std::to_string(I);
    std::error_code EC = fs::create_directory(Name, /*IgnoreExisting=*/false);
    if (!EC)
      return Name;
    if (EC != std::errc::file_exists)
      break;
  }
  return "";
}

/// Whether Dir is the working directory or a folder above it: swapping it
/// would leave the user's shell in a removed folder.
bool holdsWorkingDirectory(const std::string &Dir) {
  llvm::SmallString<256> Real, Cwd;
  if (fs::real_path(Dir, Real) || fs::current_path(Cwd) || fs::real_path(Cwd, Cwd))
    return true;
  llvm::StringRef C = Cwd;
  return C == Real || (C.starts_with(Real) && (Real == "/" || C[Real.size()] == '/'));
}

/// Moves the user's entries of From into To (or back); false if one failed.
bool moveEntries(const std::vector<std::string> &Names, const std::string &From,
                 const std::string &To) {
  for (const std::string &Name : Names)
    if (!makeParents(To, Name).empty() ||
        std::rename(join(From, Name).c_str(), join(To, Name).c_str()) != 0)
      return false;
  return true;
}

/// The whole project swapped in by rename; false (and nothing changed) if Dir
/// cannot be swapped, with Error set if the project could not be written.
bool writeBeside(const std::string &Dir, const std::vector<GeneratedFile> &Files,
                 const Manifest &New, const Existing &E, const std::vector<std::string> &Kept,
                 std::string &Error) {
  std::string Abs = absolute(Dir);
  if (path::filename(Abs).empty() || (E.Exists && holdsWorkingDirectory(Dir)))
    return false;
  std::string Parent = std::string(path::parent_path(Abs));
  if (std::error_code EC = fs::create_directories(Parent)) {
    Error = "cannot create output folder '" + Dir + "': " + EC.message();
    return true;
  }
  std::string Stage = makeStagingFolder(join(Parent, "." + path::filename(Abs).str() + ".wash"));
  if (Stage.empty())
    return false;
  Error = stage(Stage, Files, New);
  if (!Error.empty()) {
    fs::remove_directories(Stage);
    return true;
  }
  bool Swapped;
  if (E.HasProject) {
    // A previous project: carry the user's entries over, then exchange the
    // folders in one step; the old project ends up in Stage.
    Swapped = moveEntries(Kept, Dir, Stage) &&
              ::renameat2(AT_FDCWD, Stage.c_str(), AT_FDCWD, Dir.c_str(), RENAME_EXCHANGE) == 0;
    if (!Swapped)
      moveEntries(Kept, Stage, Dir);
  } else {
    // Renaming over an empty folder replaces it.
    Swapped = std::rename(Stage.c_str(), Dir.c_str()) == 0;
  }
  fs::remove_directories(Stage);
  return Swapped;
}

/// Every file written in full to a staging folder inside Dir, then renamed
/// into place; the previous run's files that are no longer generated go.
std::string writeInPlace(const std::string &Dir, const std::vector<GeneratedFile> &Files,
                         const Manifest &New, const Existing &E) {
  if (std::error_code EC = fs::create_directories(Dir))
    return "cannot create output folder '" + Dir + "': " + EC.message();
  std::string Stage = makeStagingFolder(join(Dir, ".wash-staging"));
  if (Stage.empty())
    return "cannot create a staging folder in '" + Dir + "': " + errnoMessage();
  std::string Error = stage(Stage, Files, New);
  // The manifest last: until it is replaced, it still lists the old files.
  std::vector<std::string> Order;
  for (const GeneratedFile &F : Files)
    Order.push_back(F.Name);
  Order.push_back(ManifestName);
  for (size_t I = 0; Error.empty() && I < Order.size(); ++I) {
    Error = makeParents(Dir, Order[I]);
    if (Error.empty() &&
        std::rename(join(Stage, Order[I]).c_str(), join(Dir, Order[I]).c_str()) != 0)
      Error = "cannot move '" + Order[I] + "' into '" + Dir + "': " + errnoMessage();
  }
  fs::remove_directories(Stage);
  if (!Error.empty())
    return Error;
  for (const auto &Old : E.Previous.Files)
    if (!New.Files.count(Old.first) && !path::is_absolute(Old.first) &&
        !fs::is_directory(join(Dir, Old.first)))
      fs::remove(join(Dir, Old.first));
  return "";
}

/// Writes Text to Path through a temporary file renamed into place.
std::string replaceFile(const std::string &Path, llvm::StringRef Text) {
  std::string Temporary = Path + ".wash-" + std::to_string(::getpid());
  fs::remove(Temporary);
  if (std::string Error = writeFile(Temporary, Text); !Error.empty())
    return Error;
  if (std::rename(Temporary.c_str(), Path.c_str()) != 0) {
    std::string Error = "cannot write depfile '" + Path + "': " + errnoMessage();
    fs::remove(Temporary);
    return Error;
  }
  return "";
}

} // namespace

std::string depfileText(const std::string &Target, const std::vector<std::string> &Inputs) {
  std::string Text = depfileName(Target) + ":";
  for (const std::string &Input : Inputs)
    Text += " \\\n  " + depfileName(Input);
  return Text + "\n";
}

std::string writeOutputs(const ProjectOutput &Out) {
  std::string Error;
  std::string Dir = followLink(Out.Dir, "output folder", Error);
  std::string DepFile = Out.DepFile.empty() ? "" : followLink(Out.DepFile, "depfile", Error);
  if (!Error.empty())
    return Error;
  Existing E;
  llvm::StringSet<> Replaced;
  if (std::string Error = inspect(Dir, E); !Error.empty())
    return Error;
  if (std::string Error = checkInputs(Out, Dir, E, DepFile); !Error.empty())
    return Error;
  if (std::string Error = checkOwnership(Out, Dir, E, Replaced); !Error.empty())
    return Error;
  if (std::string Error = checkDepfile(Out, Dir, E, DepFile); !Error.empty())
    return Error;

  Manifest New;
  for (const GeneratedFile &F : Out.Files)
    New.Files[F.Name] = contentHash(F.Text);
  std::string DepText = depfileText(Out.DepTarget, Out.Inputs);
  if (!DepFile.empty())
    New.Files[absolute(DepFile)] = contentHash(DepText);
  // What --force replaces is not carried over.
  std::vector<std::string> Kept;
  for (const std::string &Name : E.Theirs)
    if (!Replaced.contains(Name))
      Kept.push_back(Name);
  if (!writeBeside(Dir, Out.Files, New, E, Kept, Error))
    Error = writeInPlace(Dir, Out.Files, New, E);
  // The depfile last: a build that sees it sees the project it describes.
  if (Error.empty() && !DepFile.empty())
    Error = replaceFile(DepFile, DepText);
  return Error;
}

} // namespace wash::tr
