// The names of the value-parameterised tests (TestName.h): numbers written
// with letters for '.', '-' and '+', other characters folded into one '_',
// so that every name GoogleTest is given is a valid one and reads back as
// the parameters it came from.

#include <gtest/gtest.h>

#include "support/TestName.h"

namespace tabletop::test {
namespace {

TEST(TestName, WritesNumbersWithoutDotsOrSigns) {
  EXPECT_EQ(number(0.5), "0p5");
  EXPECT_EQ(number(-1), "m1");
  EXPECT_EQ(number(-0.001), "m0p001");
  EXPECT_EQ(number(1000), "1000");
  EXPECT_EQ(number(10000), "10000");
  EXPECT_EQ(number(1e-6), "1em06");
  EXPECT_EQ(number(1e6), "1e06");
  EXPECT_EQ(number(0.0355), "0p0355");
  EXPECT_EQ(number(1.0 / 3.0), "0p333333");
}

TEST(TestName, FoldsOtherCharactersIntoOneUnderscore) {
  EXPECT_EQ(namePart("[0.08, 0.03, 0.06]"), "0p08_0p03_0p06");
  EXPECT_EQ(namePart("\"shape\": \"cube\""), "shape_cube");
  EXPECT_EQ(namePart("example1_single_cube.json"), "example1_single_cube_json");
  EXPECT_EQ(namePart("a - b"), "a_b");
  EXPECT_EQ(namePart("..."), "");
  EXPECT_EQ(numbers({0, 0, -10}), "0_0_m10");
}

TEST(TestName, JoinsItsPartsLeavingOutEmptyOnes) {
  EXPECT_EQ(testName({"sphere", "0.05", "table", "e" + number(0.5), number(60) + "Hz"}), "sphere_0p05_table_e0p5_60Hz");
  EXPECT_EQ(testName({"cube", "", "[]", "Left"}), "cube_Left");
}

// Every name it makes is one GoogleTest takes: letters, digits and '_',
// over every printable character and the numbers the sweeps use.
TEST(TestName, MakesOnlyLettersDigitsAndUnderscores) {
  std::string printable;
  for (char c = ' '; c <= '~'; ++c) printable += c;
  const std::string name = testName({printable, number(-2.5e-7), numbers({1e300, -0.0, 12345678.9})});
  ASSERT_FALSE(name.empty());
  for (const char c : name) {
    EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_') << "'" << c << "' in " << name;
  }
  EXPECT_NE(name.front(), '_');
  EXPECT_NE(name.back(), '_');
}

}  // namespace
}  // namespace tabletop::test
