// Where the user wrote an API call, for error messages in file:line:col form.
#pragma once

#include <source_location>

namespace wash {

/// The file, line and column of a call: the API's functions take one as a
/// defaulted last parameter. Like std::source_location, but under Clang it is
/// filled by __builtin_FILE/LINE/COLUMN: std::source_location::current() is
/// consteval, and re-evaluating it at every call made the translator (which
/// parses with Clang) three times slower on long kernels. One layout for every
/// compiler, so programs and the runtime library may be built by different ones.
class CallSite {
public:
#if defined(__clang__)
  static constexpr CallSite current(const char *file = __builtin_FILE(),
                                    unsigned line = __builtin_LINE(),
                                    unsigned column = __builtin_COLUMN()) noexcept {
    return CallSite(file, line, column);
  }
#else // GCC 12 has no __builtin_COLUMN.
  static constexpr CallSite
  current(std::source_location site = std::source_location::current()) noexcept {
    return CallSite(site.file_name(), site.line(), site.column());
  }
#endif

  /// What current() would give at a call written in the user's source with
  /// its expression starting at (startLine, startColumn) and its opening
  /// parenthesis at (parenLine, parenColumn): generated code passes it, as
  /// its rewrite moves the call.
  static constexpr CallSite written(const char *file, unsigned startLine, unsigned startColumn,
                                    unsigned parenLine, unsigned parenColumn) noexcept {
#if defined(__clang__)
    (void)parenLine, (void)parenColumn;
    return CallSite(file, startLine, startColumn);
#else
    (void)startLine, (void)startColumn;
    return CallSite(file, parenLine, parenColumn);
#endif
  }

  constexpr CallSite(const char *file, unsigned line, unsigned column) noexcept
      : file_(file), line_(line), column_(column) {}

  constexpr const char *file_name() const noexcept { return file_; }
  constexpr unsigned line() const noexcept { return line_; }
  constexpr unsigned column() const noexcept { return column_; }

private:
  const char *file_;
  unsigned line_;
  unsigned column_;
};

} // namespace wash
