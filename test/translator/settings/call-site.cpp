// wash::CallSite, the defaulted last parameter of the API's calls, names the
// caller's file, line and column under both compilers: g++ fills it from
// std::source_location, clang (which the translator parses with) from the
// __builtin_FILE/LINE/COLUMN builtins.
// RUN: %cxx -std=c++20 -I%wash_src/runtime/include %s -o %t.gcc && %t.gcc | FileCheck %s
// RUN: clang++ -std=c++20 -I%wash_src/runtime/include %s -o %t.clang && %t.clang | FileCheck %s
#include <wash/call_site.hpp>

#include <cstdio>

void Report(int Value, wash::CallSite Site = wash::CallSite::current()) {
  std::printf("%s:%u:%u %d\n", Site.file_name(), Site.line(), Site.column(), Value);
}

int main() {
#line 40 "scene.cpp"
  Report(1);
  // CHECK: scene.cpp:40:{{3|9}} 1
      Report(2);
  // CHECK-NEXT: scene.cpp:42:{{7|13}} 2
}
