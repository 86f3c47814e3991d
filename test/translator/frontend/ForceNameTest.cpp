//===- ForceNameTest.cpp --------------------------------------------------===//
#include "AstSnippet.h"

#include "wash/translator/Frontend/ForceName.h"

#include <gtest/gtest.h>

using namespace clang;
using namespace wash::tr;
using namespace wash::tr::test;

namespace {

TEST(ForceName, AForceNameIsAnIdentifierThatIsNoKeywordOrMacro) {
  withAst(R"(#include <wash/wash.hpp>
#define heat 1
void use(const char *) {}
int main() { use("pressure"); use("class"); use("heat"); use("2d"); use("mass"); }
)",
          [](ASTContext &Ctx, Diagnoser &D) {
            EXPECT_EQ(forceName(argument(Ctx, "use", 0, 0), Ctx, D), "pressure");
            EXPECT_FALSE(D.hasErrors());
            EXPECT_EQ(forceName(argument(Ctx, "use", 1, 0), Ctx, D), std::nullopt);
            EXPECT_EQ(forceName(argument(Ctx, "use", 2, 0), Ctx, D), std::nullopt);
            EXPECT_EQ(forceName(argument(Ctx, "use", 3, 0), Ctx, D), std::nullopt);
            EXPECT_EQ(forceName(argument(Ctx, "use", 4, 0), Ctx, D), std::nullopt); // builtin
            EXPECT_TRUE(D.hasErrors());
          });
}

} // namespace
