//===- WashApiHeaderTest.cpp - WashApi.def against wash/wash.hpp ----------===//
//
// Parses runtime/include/wash/wash.hpp with the translator's own parser and
// checks the table against it in both directions: every entry is declared
// with the shape the passes rely on, and every public wash::Particle member
// and every free function of wash.hpp and settings.hpp is an entry. A name
// the table lacks would be silently ignored by every pass.
//
// WASH_API_TEST_PREFIX=<dir> parses <dir>/include/wash/wash.hpp instead (to
// see the test fail on an edited copy of the header).
//
//===----------------------------------------------------------------------===//
#include "wash/translator/Frontend/Parse.h"
#include "wash/translator/Frontend/WashApi.h"
#include "wash/translator/WashApiTable.h"

#include "clang/AST/DeclCXX.h"
#include "clang/AST/DeclTemplate.h"
#include "clang/Basic/SourceManager.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/raw_ostream.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <set>

using namespace clang;
using namespace wash::tr;

namespace {

/// A declaration's shape, in the few words the checks need: a type is
/// "void", "double", "bool", "size_t", "vec" (wash::ParticleVec), "string", or
/// "kernel:<return>(<parameter count>)" for a kernel pointer; else clang's
/// spelling.
struct Signature {
  std::string Return;
  std::vector<std::string> Params;
  unsigned Required = 0; ///< Parameters without a default.
  bool Const = false;
};

/// What the header declares, by name; a name declared twice (an overload)
/// has two signatures.
struct HeaderApi {
  std::map<std::string, std::vector<Signature>> Methods, Functions;
};

std::string shape(QualType T, ASTContext &Ctx) {
  T = T.getNonReferenceType().getUnqualifiedType();
  if (T->isVoidType())
    return "void";
  if (Ctx.hasSameType(T, Ctx.DoubleTy))
    return "double";
  if (T->isBooleanType())
    return "bool";
  if (Ctx.hasSameType(T, Ctx.getSizeType()))
    return "size_t";
  if (vecDimension(T))
    return "vec";
  if (const auto *RD = T->getAsCXXRecordDecl(); RD && RD->getName() == "basic_string")
    return "string";
  if (const auto *F =
          T->isPointerType() ? T->getPointeeType()->getAs<FunctionProtoType>() : nullptr)
    return "kernel:" + shape(F->getReturnType(), Ctx) + "(" + std::to_string(F->getNumParams()) +
           ")";
  return T.getAsString();
}

Signature signature(const FunctionDecl *FD, ASTContext &Ctx) {
  Signature S;
  S.Return = shape(FD->getReturnType(), Ctx);
  for (const ParmVarDecl *P : FD->parameters())
    S.Params.push_back(shape(P->getType(), Ctx));
  S.Required = FD->getMinRequiredArguments();
  if (const auto *MD = dyn_cast<CXXMethodDecl>(FD))
    S.Const = MD->isConst();
  return S;
}

/// Free functions of these headers are the API; math.hpp and vec.hpp are
/// plain maths that kernels call like any library, with no meaning to wash,
/// and so is random.hpp to the translator: generated code calls the same
/// wash::random, which reads the step from the run (wash/detail/random.hpp).
bool inApiHeader(const SourceManager &SM, SourceLocation L) {
  StringRef File = SM.getFilename(SM.getExpansionLoc(L));
  return File.ends_with("wash/wash.hpp") || File.ends_with("wash/settings.hpp");
}

/// A function or a function template's pattern: templates are API too.
const FunctionDecl *function(const Decl *D) {
  if (const auto *T = dyn_cast<FunctionTemplateDecl>(D))
    return T->getTemplatedDecl();
  return dyn_cast<FunctionDecl>(D);
}

HeaderApi parseHeader() {
  llvm::SmallString<128> Source;
  int FD;
  if (llvm::sys::fs::createTemporaryFile("wash-api", "cpp", FD, Source))
    return {};
  {
    llvm::raw_fd_ostream OS(FD, /*shouldClose=*/true);
    OS << "#include <wash/wash.hpp>\nint main() {}\n";
  }
  Options Opts;
  Opts.Source = std::string(Source);
  if (const char *Prefix = std::getenv("WASH_API_TEST_PREFIX"))
    Opts.ExecutablePath = std::string(Prefix) + "/bin/wash";
  HeaderApi Api;
  bool Parsed =
      parseSimulation(Opts, [&](ASTContext &Ctx, Diagnoser &, unsigned, const IncludeDirectives &) {
        const SourceManager &SM = Ctx.getSourceManager();
        for (const Decl *D : Ctx.getTranslationUnitDecl()->decls()) {
          const auto *NS = dyn_cast<NamespaceDecl>(D);
          if (!NS || NS->getName() != "wash")
            continue;
          for (const Decl *Member : NS->decls()) {
            const auto *F = function(Member);
            if (F && F->isFirstDecl() && isWashFunction(F) && inApiHeader(SM, F->getLocation()))
              Api.Functions[F->getName().str()].push_back(signature(F, Ctx));
            const auto *RD = dyn_cast<CXXRecordDecl>(Member);
            if (!RD || RD->getName() != "Particle" || !RD->isThisDeclarationADefinition())
              continue;
            for (const Decl *M : RD->decls()) {
              const auto *MD = dyn_cast_or_null<CXXMethodDecl>(function(M));
              if (MD && MD->isFirstDecl() && !MD->isImplicit() && MD->getAccess() == AS_public)
                Api.Methods[MD->getNameAsString()].push_back(signature(MD, Ctx));
            }
          }
        }
      });
  llvm::sys::fs::remove(Source);
  EXPECT_TRUE(Parsed) << "wash/wash.hpp did not compile";
  return Api;
}

const HeaderApi &header() {
  static const HeaderApi Api = parseHeader();
  return Api;
}

/// The one declaration of Name, or null (the failure says why).
const Signature *declared(const std::map<std::string, std::vector<Signature>> &Decls,
                          const std::string &Name) {
  auto It = Decls.find(Name);
  if (It == Decls.end()) {
    ADD_FAILURE() << "'" << Name << "' is in WashApi.def but not declared in wash/wash.hpp";
    return nullptr;
  }
  if (It->second.size() != 1) {
    ADD_FAILURE() << "'" << Name << "' is overloaded in wash/wash.hpp; WashApi.def has one shape";
    return nullptr;
  }
  return &It->second[0];
}

std::string valueShape(ForceKind K) { return K == ForceKind::Vector ? "vec" : "double"; }

std::string kernelShape(KernelKind K) {
  switch (K) {
  case KernelKind::Init:
  case KernelKind::Void:
    return "kernel:void(0)";
  case KernelKind::Update:
    return "kernel:void(1)";
  case KernelKind::Force:
    return "kernel:void(2)";
  case KernelKind::Reduction:
    return "kernel:double(1)";
  }
  return "?";
}

// Public members of wash::Particle that are not accessors.
const std::set<std::string> NotAccessors = {
    "Particle", // The runtime's handle constructor; kernels receive handles, never make them.
};

TEST(WashApiHeader, EveryAccessorIsDeclaredWithItsShape) {
  for (const ParticleAccessor &A : particleAccessors()) {
    SCOPED_TRACE(A.Method);
    const Signature *S = declared(header().Methods, A.Method);
    if (!S)
      continue;
    // A force accessor takes the force's name first; a setter takes the value.
    // A type accessor takes the type's name only: is_type returns a bool.
    std::vector<std::string> Params;
    if (A.IsType) {
      EXPECT_EQ(S->Return, A.How == Mode::Read ? "bool" : "void");
      EXPECT_EQ(S->Required, 1u);
      EXPECT_EQ(S->Params.at(0), "string");
      EXPECT_EQ(S->Const, A.How == Mode::Read) << "is_type is const, set_type not";
      continue;
    }
    if (A.isForce())
      Params.push_back("string");
    if (A.How == Mode::Write)
      Params.push_back(valueShape(A.Kind));
    std::string Return = A.How == Mode::Write                        ? "void"
                         : A.Field && A.Field->Kind == FieldKind::Id ? "size_t"
                                                                     : valueShape(A.Kind);
    EXPECT_EQ(S->Return, Return);
    EXPECT_EQ(S->Required, Params.size());
    EXPECT_EQ(std::vector<std::string>(S->Params.begin(), S->Params.begin() + S->Required), Params);
    EXPECT_EQ(S->Const, A.How == Mode::Read) << "getters are const, setters not";
  }
}

TEST(WashApiHeader, ReadOnlyFieldsHaveNoSetter) {
  for (const BuiltinField &F : builtinFields())
    if (!F.settable())
      EXPECT_FALSE(header().Methods.count("set_" + std::string(F.Name)))
          << "'set_" << F.Name << "' is declared but WashApi.def says " << F.Name
          << " cannot be set";
}

TEST(WashApiHeader, EveryCallIsDeclaredWithItsArguments) {
  for (const ApiCallInfo &C : apiCalls()) {
    SCOPED_TRACE(C.Name);
    const Signature *S = declared(header().Functions, C.Name);
    if (!S)
      continue;
    EXPECT_EQ(S->Required, C.MinArgs) << "arguments without a default";
    if (C.Kernel) {
      ASSERT_FALSE(S->Params.empty());
      EXPECT_EQ(S->Params[0], kernelShape(*C.Kernel));
    }
  }
}

TEST(WashApiHeader, EveryParticleMemberIsInTheTable) {
  ASSERT_FALSE(header().Methods.empty()) << "no wash::Particle in wash/wash.hpp";
  for (const auto &[Name, Decls] : header().Methods)
    EXPECT_TRUE(decodeAccessor(Name) || NotAccessors.count(Name))
        << "wash::Particle::" << Name << " is declared in wash/wash.hpp but not in WashApi.def";
}

TEST(WashApiHeader, EveryFreeFunctionIsInTheTable) {
  ASSERT_FALSE(header().Functions.empty()) << "no wash:: functions in wash/wash.hpp";
  for (const auto &[Name, Decls] : header().Functions)
    EXPECT_TRUE(apiCall(Name)) << "wash::" << Name
                               << " is declared in wash/wash.hpp but not in WashApi.def";
}

} // namespace
