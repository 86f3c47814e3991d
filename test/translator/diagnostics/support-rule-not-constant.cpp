// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main(int argc, char **) {
  const wash::Support rule = argc > 1 ? wash::Support::Symmetric : wash::Support::Gather;
  // CHECK: support-rule-not-constant.cpp:[[@LINE+1]]:43: error: the support rule must be the constant wash::Support::Gather or wash::Support::Symmetric
  wash::set_smoothing_length_support(2.0, rule);
  wash::start();
}
