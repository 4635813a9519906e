// Runs a property of the zdg check registry (convergence/check/property.hpp) inside a GoogleTest
// test, so that the tests and `zdg check` exercise the same properties:
//
//   TYPED_TEST(FloorSum, RegisteredOracleHolds) {
//     zdg::test::expect_registered_property("floor_sum.oracle", zdg::int_kind<TypeParam>(), 300);
//   }
//
// The seed is fixed (reproducible CI); ZDG_CHECK_SEED=S overrides it for a local hunt. A failure
// reports the shrunk counterexample and the `zdg check --replay` command that reproduces it.
#pragma once

#include <zdg/convergence/check/property.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <string>

namespace zdg::test {

inline void expect_registered_property(const std::string& name, IntKind type, std::int64_t runs) {
  const check::Property& p = check::find_property(name);
  check::Params params;
  params.type = type;
  params.bits = check::default_bits(type);
  params.max_size = p.default_max_size;
  check::Options opt;
  opt.seed = 20;
  if (const char* s = std::getenv("ZDG_CHECK_SEED")) opt.seed = std::strtoull(s, nullptr, 10);
  opt.runs = runs;
  const check::Report r = check::run_check(p, params, opt);
  EXPECT_EQ(r.runs, runs) << name;
  if (r.failure) {
    ADD_FAILURE() << name << " on " << to_string(type) << ": " << r.failure->verdict.why
                  << "\n  case: " << check::to_json(r.failure->shrunk) << "\n  replay: zdg check "
                  << name << " --replay " << r.failure->token;
  }
}

} // namespace zdg::test
