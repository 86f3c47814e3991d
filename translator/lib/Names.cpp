//===- Names.cpp ----------------------------------------------------------===//
#include "wash/translator/Names.h"
#include "wash/translator/WashApiTable.h"

#include <algorithm>
#include <cstdio>

namespace wash::tr {

static bool identifierStart(char C) {
  return (C >= 'a' && C <= 'z') || (C >= 'A' && C <= 'Z') || C == '_';
}
static bool identifierChar(char C) { return identifierStart(C) || (C >= '0' && C <= '9'); }

std::optional<std::string> forceNameProblem(std::string_view Name) {
  if (Name.empty())
    return "is empty";
  if (!identifierStart(Name[0]) || !std::all_of(Name.begin(), Name.end(), identifierChar))
    return "is not an identifier";
  if (builtinField(Name))
    return "is a builtin particle property";
  return std::nullopt;
}

std::string escapedName(std::string_view Name) {
  std::string Out;
  for (char C : Name) {
    if (C == '\'' || C == '\\') {
      Out += '\\';
      Out += C;
    } else if (C >= 0x20 && C < 0x7f) {
      Out += C;
    } else {
      char Buf[8];
      std::snprintf(Buf, sizeof(Buf), "\\x%02x", static_cast<unsigned char>(C));
      Out += Buf;
    }
  }
  return Out;
}

/// Levenshtein distance, two rows.
static unsigned editDistance(std::string_view A, std::string_view B) {
  std::vector<unsigned> Prev(B.size() + 1), Cur(B.size() + 1);
  for (unsigned J = 0; J <= B.size(); ++J)
    Prev[J] = J;
  for (unsigned I = 1; I <= A.size(); ++I) {
    Cur[0] = I;
    for (unsigned J = 1; J <= B.size(); ++J)
      Cur[J] = std::min({Prev[J] + 1, Cur[J - 1] + 1, Prev[J - 1] + (A[I - 1] != B[J - 1])});
    std::swap(Prev, Cur);
  }
  return Prev[B.size()];
}

std::optional<std::string> closestName(std::string_view Name,
                                       const std::vector<std::string> &Candidates) {
  unsigned Limit = std::max<unsigned>(1, Name.size() / 3);
  std::optional<std::string> Best;
  unsigned BestDistance = Limit + 1;
  for (const std::string &C : Candidates) {
    if (C == Name)
      continue;
    unsigned D = editDistance(Name, C);
    if (D < BestDistance) {
      BestDistance = D;
      Best = C;
    }
  }
  return Best;
}

} // namespace wash::tr
