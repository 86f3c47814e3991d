//===- TypeNameTest.cpp ---------------------------------------------------===//
#include "AstSnippet.h"

#include "wash/translator/Frontend/TypeName.h"

#include <gtest/gtest.h>

using namespace clang;
using namespace wash::tr;
using namespace wash::tr::test;

namespace {

TEST(TypeName, ATypeIsAnIdentifierAddedBeforeUse) {
  withAst(R"(#include <wash/wash.hpp>
void use(const char *) {}
int main() { use("fluid"); use("wall 2"); use("solid"); }
)",
          [](ASTContext &Ctx, Diagnoser &D) {
            EXPECT_EQ(particleTypeName(argument(Ctx, "use", 0, 0), Ctx, D), "fluid");
            EXPECT_FALSE(D.hasErrors());
            std::vector<ParticleType> Types = {{"fluid", {}}};
            EXPECT_EQ(knownParticleType(argument(Ctx, "use", 0, 0), Ctx, D, Types), "fluid");
            EXPECT_EQ(knownParticleType(argument(Ctx, "use", 2, 0), Ctx, D, Types), std::nullopt);
            EXPECT_EQ(particleTypeName(argument(Ctx, "use", 1, 0), Ctx, D), std::nullopt);
            EXPECT_TRUE(D.hasErrors());
          });
}

} // namespace
