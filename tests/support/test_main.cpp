// The one main of every zdg test program (GoogleTest; RapidCheck properties run inside
// GoogleTest tests through rapidcheck/gtest.h).
#include <gtest/gtest.h>

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
