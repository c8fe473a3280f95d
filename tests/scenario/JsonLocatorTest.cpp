#include "scenario/JsonLocator.h"

#include <gtest/gtest.h>

namespace tabletop {
namespace {

TEST(JsonLocator, FindsEachValueAfterComments) {
  const JsonLocator l("// a comment\n{\"a\": [1, /* two */ 2],\n \"b\": {\"c/d\": true}}");
  EXPECT_EQ(l.find("/a/1").line, 2);
  EXPECT_EQ(l.find("/a/1").column, 21);
  EXPECT_EQ(l.find("/b/c~1d").line, 3);
  EXPECT_EQ(l.find("/b/c~1d").column, 15);
  // An unknown pointer falls back to its nearest located parent.
  EXPECT_EQ(l.find("/b/zz").line, 3);
  EXPECT_EQ(l.find("/b/zz").column, 7);
}

// The scan is only given texts that parsed, but one it misreads (the
// fuzzer found one, through a NUL byte) must end rather than loop: here an
// array holds a '}', where the scan once stood still for ever.
TEST(JsonLocator, EndsOnATextItMisreads) {
  const JsonLocator l("[1, } 2]");
  EXPECT_EQ(l.find("/0").column, 2);
}

}  // namespace
}  // namespace tabletop
