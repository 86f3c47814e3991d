// The lookups over WashApi.def (WashApiHeaderTest checks the table itself
// against the header).
#include "wash/translator/WashApiTable.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace wash::tr;

TEST(WashApiTable, BuiltinFieldsInDumpOrder) {
  // The dump, the storage and the output columns follow this order.
  EXPECT_EQ(builtinFieldNames(), (std::vector<std::string>{"id", "pos", "vel", "acc", "density",
                                                           "mass", "smoothing_length"}));
  ASSERT_NE(builtinField("id"), nullptr);
  EXPECT_FALSE(builtinField("id")->settable());
  EXPECT_EQ(builtinField("acc")->storage(), ForceKind::Vector);
  EXPECT_FALSE(builtinField("acc")->AlwaysOutput);
  EXPECT_EQ(builtinField("force_scalar"), nullptr);
}

TEST(WashApiTable, DecodesBuiltinAccessors) {
  auto Get = decodeAccessor("get_smoothing_length");
  ASSERT_TRUE(Get);
  EXPECT_FALSE(Get->isForce());
  EXPECT_STREQ(Get->Field->Name, "smoothing_length");
  EXPECT_EQ(Get->How, Mode::Read);
  EXPECT_TRUE(Get->reads("smoothing_length"));
  auto Set = decodeAccessor("set_pos");
  ASSERT_TRUE(Set);
  EXPECT_EQ(Set->How, Mode::Write);
  EXPECT_EQ(Set->Kind, ForceKind::Vector);
  EXPECT_FALSE(Set->reads("pos"));
  EXPECT_FALSE(decodeAccessor("set_id"));
  EXPECT_FALSE(decodeAccessor("get_"));
  EXPECT_FALSE(decodeAccessor("Particle"));
}

TEST(WashApiTable, DecodesForceAccessors) {
  auto A = decodeAccessor("set_force_vector");
  ASSERT_TRUE(A);
  EXPECT_TRUE(A->isForce());
  EXPECT_EQ(A->How, Mode::Write);
  EXPECT_EQ(A->Kind, ForceKind::Vector);
  EXPECT_FALSE(A->reads("force_vector"));
  EXPECT_EQ(decodeAccessor("get_force_scalar")->Kind, ForceKind::Scalar);
}

TEST(WashApiTable, Calls) {
  const ApiCallInfo *C = apiCall("add_reduction_kernel");
  ASSERT_NE(C, nullptr);
  EXPECT_EQ(C->Kernel, KernelKind::Reduction);
  EXPECT_EQ(C->Lowering, CallLowering::Drop);
  EXPECT_EQ(C->Use, CallUse::MainOnce);
  EXPECT_FALSE(apiCall("add_force")->Kernel);
  EXPECT_TRUE(apiCall("set_bounding_box")->readFromMain());
  EXPECT_FALSE(apiCall("get_variable")->readFromMain());
  EXPECT_EQ(apiCall("start")->Lowering, CallLowering::Generated);
  EXPECT_EQ(apiCall("TIME_DELTA"), nullptr);
  for (const ApiCallInfo &Call : apiCalls())
    EXPECT_EQ(&apiCall(Call.Id), &Call);
}

TEST(WashApiTable, NamesAreUnique) {
  std::set<std::string> Methods, Calls;
  for (const ParticleAccessor &A : particleAccessors())
    EXPECT_TRUE(Methods.insert(A.Method).second) << A.Method;
  for (const ApiCallInfo &C : apiCalls())
    EXPECT_TRUE(Calls.insert(C.Name).second) << C.Name;
}
