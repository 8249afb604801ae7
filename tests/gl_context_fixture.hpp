// A test suite that shares one headless OpenGL context (EGL; llvmpipe in CI), made current when
// the suite starts and destroyed when it ends.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "gl/headless_context.hpp"

namespace clothlab::testing {

class GlContextTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<vis::HeadlessContext>(); }
  static void TearDownTestSuite() { context_.reset(); }
  static const vis::HeadlessContext& context() { return *context_; }

 private:
  static inline std::unique_ptr<vis::HeadlessContext> context_;
};

}  // namespace clothlab::testing
