// Scenario files: a good one loads with its defaults; each bad one is
// refused with the place and what was expected.

#include "scenario/ScenarioLoader.h"

#include <gtest/gtest.h>

#include "scenario/ScenarioError.h"

namespace tabletop {
namespace {

const char* const kGood = R"({
  // comments are allowed
  "version": 1,
  "name": "good",
  "table": { "size": [1.0, 0.6], "height": 0.7 },
  "settings": { "timestep": 0.005, "duration": 3 },
  "entities": [
    { "name": "A", "shape": "cube", "size": 0.1, "position": [0.1, -0.1], "mass": 0.5,
      "yaw": 15, "colour": [1, 2, 3], "material": { "friction": 0.3 } },
    { "name": "B", "shape": "sphere", "size": 0.02, "position": [0.1, -0.1], "on": "A", "mass": 0.1,
      "material": { "rolling_friction": 0.001 } },
    { "name": "C", "shape": "box", "size": [0.1, 0.2, 0.3], "position": [0.3, 0.5, 0.2], "mass": 1 }
  ],
  "script": [
    { "t": 0.5, "push": { "entity": "A", "direction": "Front", "step": 0.1 } },
    { "wait": "rest", "timeout": 2 },
    { "push": { "entity": "B", "angle": 30, "impulse": 0.01 } },
    { "wait": 0.25 },
    { "t": 2.0, "rotate": { "entity": "C", "angle": -45 } }
  ]
})";

// max_substeps: 64 unless given; 1 turns the substeps off.
TEST(ScenarioLoader, ReadsTheSubstepLimit) {
  const char* text = R"({"version": 1, "name": "t", "settings": {"max_substeps": 1},
                         "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})";
  EXPECT_EQ(ScenarioLoader::loadText(text, "one.json").settings.maxSubsteps, 1);
  EXPECT_EQ(Settings{}.maxSubsteps, 64);
}

TEST(ScenarioLoader, ReadsEveryField) {
  const Scenario s = ScenarioLoader::loadText(kGood, "good.json");
  EXPECT_EQ(s.name, "good");
  EXPECT_DOUBLE_EQ(s.table.width, 1.0);
  EXPECT_DOUBLE_EQ(s.table.height, 0.7);
  EXPECT_DOUBLE_EQ(s.table.thickness, TableSpec{}.thickness);
  EXPECT_DOUBLE_EQ(s.settings.timestep, 0.005);
  EXPECT_EQ(s.settings.iterations, Settings{}.iterations);
  ASSERT_EQ(s.entities.size(), 3u);
  EXPECT_EQ(s.entities[0].on, Support::table());  // [x, z] means on the table
  EXPECT_DOUBLE_EQ(s.entities[0].position.z, -0.1);
  EXPECT_DOUBLE_EQ(s.entities[0].material.friction, 0.3);
  EXPECT_EQ(s.entities[0].colour.b, 3);
  EXPECT_EQ(s.entities[1].on, Support::entity("A"));
  EXPECT_DOUBLE_EQ(s.entities[1].material.spinningFriction, 0.001);  // follows rolling friction
  EXPECT_TRUE(s.entities[2].on.isNone());
  EXPECT_DOUBLE_EQ(s.entities[2].position.y, 0.5);
  ASSERT_EQ(s.script.size(), 5u);
  EXPECT_EQ(s.script[0].arrow.face, DirectionDef::Front);
  EXPECT_EQ(s.script[0].magnitude.kind, PushMagnitude::Kind::Step);
  EXPECT_EQ(s.script[1].type, Action::Type::WaitRest);
  EXPECT_DOUBLE_EQ(s.script[1].seconds, 2.0);
  EXPECT_FALSE(s.script[2].arrow.face.has_value());
  EXPECT_DOUBLE_EQ(s.script[2].arrow.angleDegrees, 30.0);
  EXPECT_EQ(s.script[3].type, Action::Type::WaitTime);
  EXPECT_EQ(s.script[4].type, Action::Type::Rotate);
  EXPECT_DOUBLE_EQ(s.script[4].degrees, -45.0);
}

// One bad input: the text, the JSON pointer expected in the first problem,
// and a piece of its message.
struct BadInput {
  const char* name;
  std::string text;
  std::string path;
  std::string message;
};

void PrintTo(const BadInput& c, std::ostream* os) { *os << c.name; }

// A scenario with one entity A; `extra` adds fields to it.
std::string entity(const std::string& extra, const std::string& shape = "\"cube\"",
                   const std::string& size = "0.1", const std::string& mass = "1") {
  return R"({"version": 1, "name": "t", "entities": [{"name": "A", "shape": )" + shape +
         ", \"size\": " + size + ", \"position\": [0, 0], \"mass\": " + mass + extra + "}]}";
}

std::string withScript(const std::string& actions) {
  return R"({"version": 1, "name": "t", "settings": {"duration": 5},
    "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}],
    "script": [)" + actions + "]}";
}

class BadScenario : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadScenario, IsRefusedWithPlaceAndReason) {
  const BadInput& c = GetParam();
  try {
    ScenarioLoader::loadText(c.text, "bad.json");
    FAIL() << "accepted: " << c.text;
  } catch (const ScenarioError& e) {
    ASSERT_FALSE(e.problems().empty());
    const Problem& p = e.problems().front();
    EXPECT_EQ(p.path, c.path) << e.what();
    EXPECT_NE(p.message.find(c.message), std::string::npos) << e.what();
    EXPECT_GT(p.line, 0) << e.what();
    // One line each, starting with the file and its position.
    for (const std::string& line : e.lines()) {
      EXPECT_EQ(line.find('\n'), std::string::npos);
      EXPECT_EQ(line.rfind("bad.json:", 0), 0u) << line;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, BadScenario,
    ::testing::Values(
        BadInput{"NotJson", "{\"version\": 1,\n  \"name\": }", "", "not valid JSON"},
        BadInput{"NotAnObject", "[1, 2]", "", "expected an object"},
        // Found by the fuzzer: nlohmann stops at a NUL as at the end, and
        // the text before it ("|") parsed.
        BadInput{"NulByte", std::string("// x\n\"|\"\0 {\"version\": 1}", 24), "", "got a NUL byte"},
        BadInput{"WrongVersion", R"({"version": 2, "name": "t", "entities": []})", "/version", "expected 1"},
        BadInput{"NoEntities", R"({"version": 1, "name": "t", "entities": []})", "/entities", "non-empty array"},
        BadInput{"UnknownShape", entity("", "\"pyramid\""), "/entities/0/shape",
                 "expected one of cube, sphere, box, cylinder"},
        BadInput{"ShapeNotAString", entity("", "3"), "/entities/0/shape", "expected a non-empty string"},
        BadInput{"ZeroSize", entity("", "\"cube\"", "0"), "/entities/0/size",
                 "expected a positive number, got 0"},
        BadInput{"NegativeSize", entity("", "\"cube\"", "-0.1"), "/entities/0/size",
                 "expected a positive number, got -0.1"},
        BadInput{"InfiniteSize", entity("", "\"cube\"", "1e999"), "", "number overflow parsing '1e999'"},
        BadInput{"ZeroMass", entity("", "\"cube\"", "0.1", "0"), "/entities/0/mass",
                 "expected a positive number, got 0"},
        BadInput{"MisspeltKey", entity(R"(, "material": {"fricton": 0.3})"), "/entities/0/material/fricton",
                 "unknown key 'fricton'"},
        BadInput{"BadColour", entity(R"(, "colour": [0, 300, 0])"), "/entities/0/colour/1",
                 "integer from 0 to 255"},
        BadInput{"RestitutionAboveOne", entity(R"(, "material": {"restitution": 1.5})"),
                 "/entities/0/material/restitution", "from 0 to 1"},
        BadInput{"UnknownSupport", entity(R"(, "on": "shelf")"), "/entities/0/on", "entity listed before"},
        BadInput{"BoxSizeNotTriple", entity("", "\"box\"", "[0.1, 0.2]"), "/entities/0/size",
                 "an array of 3 numbers"},
        BadInput{"MissingMass", R"({"version": 1, "name": "t", "entities": [{"name": "A", "shape": "cube",
                   "size": 0.1, "position": [0, 0]}]})", "/entities/0", "missing required key 'mass'"},
        BadInput{"PushUnknownEntity", withScript(R"({"push": {"entity": "Z", "direction": "Left", "step": 0.1}})"),
                 "/script/0/push/entity", "expected the name of an entity, got \"Z\""},
        BadInput{"PushBadDirection", withScript(R"({"push": {"entity": "A", "direction": "Up", "step": 0.1}})"),
                 "/script/0/push/direction", "one of Left, Right, Front, Back"},
        BadInput{"PushNegativeStep", withScript(R"({"push": {"entity": "A", "direction": "Left", "step": -1}})"),
                 "/script/0/push/step", "positive number"},
        BadInput{"PushStepAndImpulse",
                 withScript(R"({"push": {"entity": "A", "direction": "Left", "step": 1, "impulse": 1}})"),
                 "/script/0/push", "exactly one of 'step', 'impulse'"},
        BadInput{"NegativeTime", withScript(R"({"t": -1, "wait": 1})"), "/script/0/t", "expected a number from 0 to 3600, got -1"},
        BadInput{"TimesOutOfOrder", withScript(R"({"t": 2, "wait": 1}, {"t": 1, "wait": 1})"), "/script/1/t",
                 "not before the previous action's"},
        BadInput{"TimeAfterDuration", withScript(R"({"t": 9, "wait": 1})"), "/script/0/t", "within the duration"},
        BadInput{"TwoActionsInOne", withScript(R"({"wait": 1, "rotate": {"entity": "A", "angle": 5}})"),
                 "/script/0", "exactly one of 'push', 'rotate', 'wait'"},
        BadInput{"ZeroTimestep", R"({"version": 1, "name": "t", "settings": {"timestep": 0},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/timestep", "expected a positive number, got 0"},
        BadInput{"UnknownTopLevelKey", R"({"version": 1, "name": "t", "entitys": [],
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/entitys", "unknown key 'entitys'"},
        BadInput{"TableTopThickerThanHeight", R"({"version": 1, "name": "t", "table": {"height": 0.5, "thickness": 0.6},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/table/thickness", "less than the table height"},
        BadInput{"FractionalIterations", R"({"version": 1, "name": "t", "settings": {"iterations": 2.5},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/iterations", "an integer from 1 to 10000"},
        BadInput{"NoSubsteps", R"({"version": 1, "name": "t", "settings": {"max_substeps": 0},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/max_substeps", "expected an integer from 1 to 1000, got 0"},
        BadInput{"UnknownIntegrator", R"({"version": 1, "name": "t", "settings": {"integrator": "rk4"},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/integrator", "expected \"euler\" or \"trapezoid\", got \"rk4\""},
        BadInput{"UnknownBroadphase", R"({"version": 1, "name": "t", "settings": {"broadphase": "octree"},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/broadphase", "expected \"dbvt\", \"sap\" or \"simple\", got \"octree\""},
        BadInput{"UnknownSolver", R"({"version": 1, "name": "t", "settings": {"solver": "lemke"},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/solver", "expected \"sequential_impulse\", \"dantzig\" or \"auto\", got \"lemke\""},
        BadInput{"UnknownGyroscopic", R"({"version": 1, "name": "t", "settings": {"gyroscopic": "rk4"},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/gyroscopic",
                 "expected \"none\", \"explicit\", \"implicit_world\" or \"implicit_body\", got \"rk4\""},
        BadInput{"LegsSwitchNotABoolean", R"({"version": 1, "name": "t", "settings": {"legs_when_reachable": 1},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/legs_when_reachable", "expected true or false"},
        BadInput{"WarmStartAboveOne", R"({"version": 1, "name": "t", "settings": {"warm_start": 1.5},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/warm_start", "expected a number from 0 to 1, got 1.5"},
        BadInput{"VelocityOfTwoNumbers", entity(R"(, "velocity": [1, 0])"), "/entities/0/velocity",
                 "an array of 3 numbers"},
        BadInput{"ReservedName", entity("").replace(entity("").find("\"A\""), 3, "\"table\""), "/entities/0/name",
                 "'table' is reserved"},
        BadInput{"HeightAndOn", entity(R"(, "on": "ground")").replace(entity("").find("[0, 0]"), 6, "[0, 1, 0]"),
                 "/entities/0/on", "no 'on' when the position gives a height"},
        BadInput{"RotateWithoutAngle", withScript(R"({"rotate": {"entity": "A"}})"), "/script/0/rotate",
                 "missing required key 'angle'"},
        BadInput{"WaitForWhat", withScript(R"({"wait": "forever"})"), "/script/0/wait",
                 "expected \"rest\" or a positive number of seconds"},
        BadInput{"DuplicateName", R"({"version": 1, "name": "t", "entities": [
                   {"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1},
                   {"name": "A", "shape": "cube", "size": 0.1, "position": [0.3, 0], "mass": 1}]})",
                 "/entities/1/name", "unique name"},
        // Ranges that keep a run meaningful and finite in time.
        BadInput{"TimestepTooLarge", R"({"version": 1, "name": "t", "settings": {"timestep": 0.5},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/timestep", "expected a number from 1e-05 to 0.1, got 0.5"},
        BadInput{"TooManySteps", R"({"version": 1, "name": "t", "settings": {"timestep": 1e-5, "duration": 1000},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/duration", "expected at most 1e+07 steps (duration / timestep), got 1e+08"},
        BadInput{"DurationBeyondAnHour", R"({"version": 1, "name": "t", "settings": {"duration": 1e5},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/duration", "expected a positive number up to 3600, got 100000.0"},
        BadInput{"GravityTooStrong", R"({"version": 1, "name": "t", "settings": {"gravity": 1000},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/gravity", "expected a number from 0 to 100, got 1000"},
        BadInput{"SizeBelowAMillimetre", entity("", "\"cube\"", "1e-6"), "/entities/0/size",
                 "expected a number from 0.001 to 1000, got 1e-06"},
        BadInput{"MassTooLarge", entity("", "\"cube\"", "0.1", "1e9"), "/entities/0/mass",
                 "expected a number from 0.0001 to 100000, got 1000000000.0"},
        BadInput{"FrictionTooLarge", entity(R"(, "material": {"friction": 50})"), "/entities/0/material/friction",
                 "expected a number from 0 to 10, got 50"},
        BadInput{"PositionFarAway", entity("").replace(entity("").find("[0, 0]"), 6, "[0, 1e6, 0]"),
                 "/entities/0/position/1", "expected a number from -10000 to 10000, got 1000000.0"},
        BadInput{"OffTheTable", entity("").replace(entity("").find("[0, 0]"), 6, "[0.7, 0]"),
                 "/entities/0/position", "expected a centre over the table top (x from -0.6 to 0.6"},
        BadInput{"ImpulseTooLarge", withScript(R"({"push": {"entity": "A", "angle": 0, "impulse": 1e9}})"),
                 "/script/0/push/impulse", "expected a positive number up to 1e+06, got 1000000000.0"},
        BadInput{"PushWithoutDirection", withScript(R"({"push": {"entity": "A", "step": 0.1}})"),
                 "/script/0/push", "expected exactly one of 'direction', 'angle'"},
        BadInput{"PushNotAnObject", withScript(R"({"push": "A"})"), "/script/0/push", "expected an object"},
        BadInput{"ScriptNotAnArray", R"({"version": 1, "name": "t", "script": {},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/script", "expected an array of actions"},
        BadInput{"SupportListedLater", R"({"version": 1, "name": "t", "entities": [
                   {"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "on": "B", "mass": 1},
                   {"name": "B", "shape": "cube", "size": 0.1, "position": [0.3, 0], "mass": 1}]})",
                 "/entities/0/on", "an entity listed before this one"},
        BadInput{"NameMissing", R"({"version": 1, "entities": [{"name": "A", "shape": "cube", "size": 0.1,
                   "position": [0, 0], "mass": 1}]})", "", "missing required key 'name'"},
        // Hostile input: names that would carry a command into a gnuplot
        // script, colour a terminal, or reverse what it shows.
        BadInput{"NameWithNewline", entity("").replace(entity("").find("\"A\""), 3, R"x("A\nsystem('touch x')")x"),
                 "/entities/0/name", "expected printable text, got a control character (U+000A)"},
        BadInput{"NameWithAnsiEscape", entity("").replace(entity("").find("\"A\""), 3, R"("\u001b[31mA")"),
                 "/entities/0/name", "a control character (U+001B)"},
        BadInput{"NameWithBidiOverride", entity("").replace(entity("").find("\"A\""), 3, R"("A\u202eB")"),
                 "/entities/0/name", "a format character (invisible, or a direction mark) (U+202E)"},
        // Look-alike names: marks that show as nothing, chosen by Unicode
        // category (Cf, Zl, Zp), so "A" and "A" + U+200B cannot both be.
        BadInput{"NameWithZeroWidthSpace", entity("").replace(entity("").find("\"A\""), 3, R"("A\u200b")"),
                 "/entities/0/name", "a format character (invisible, or a direction mark) (U+200B)"},
        BadInput{"NameWithLeftToRightMark", entity("").replace(entity("").find("\"A\""), 3, R"("A\u200e")"),
                 "/entities/0/name", "(U+200E) at byte 1"},
        BadInput{"NameWithArabicLetterMark", entity("").replace(entity("").find("\"A\""), 3, R"("\u061cA")"),
                 "/entities/0/name", "(U+061C) at byte 0"},
        BadInput{"NameWithIsolate", entity("").replace(entity("").find("\"A\""), 3, R"("A\u2066")"),
                 "/entities/0/name", "(U+2066)"},
        BadInput{"NameWithByteOrderMark", entity("").replace(entity("").find("\"A\""), 3, R"("A\ufeff")"),
                 "/entities/0/name", "(U+FEFF)"},
        BadInput{"NameWithLineSeparator", entity("").replace(entity("").find("\"A\""), 3, R"("A\u2028")"),
                 "/entities/0/name", "a line separator (U+2028)"},
        BadInput{"NameWithParagraphSeparator", entity("").replace(entity("").find("\"A\""), 3, R"("A\u2029")"),
                 "/entities/0/name", "a paragraph separator (U+2029)"},
        BadInput{"NameUnassigned", entity("").replace(entity("").find("\"A\""), 3, R"("A\u0378")"),
                 "/entities/0/name", "an unassigned code point (U+0378)"},
        // U+00E9 and e + U+0301 are one name in NFC.
        BadInput{"NamesEqualInNfc", R"({"version": 1, "name": "t", "entities": [
                   {"name": "caf\u00e9", "shape": "cube", "size": 0.1, "position": [-0.3, 0], "mass": 1},
                   {"name": "cafe\u0301", "shape": "cube", "size": 0.1, "position": [0.3, 0], "mass": 1}]})",
                 "/entities/1/name", "is the same name as 'caf\u00e9' (/entities/0) in Unicode normalization form C (NFC)"},
        BadInput{"NameTooLong", entity("").replace(entity("").find("\"A\""), 3, "\"" + std::string(65, 'n') + "\""),
                 "/entities/0/name", "expected at most 64 bytes, got 65"},
        BadInput{"ScenarioNameWithCarriageReturn", R"({"version": 1, "name": "t\r", "entities": [{"name": "A",
                   "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})", "/name",
                 "a control character (U+000D)"},
        BadInput{"DuplicateKey", R"({"version": 1, "name": "t", "entities": [{"name": "A", "shape": "cube",
                   "size": 0.1, "position": [0, 0], "mass": 1, "mass": 2}]})", "/entities/0/mass",
                 "expected each key once in an object, but it was given already at line 2, column 61"},
        BadInput{"DeepNesting", std::string(100000, '['), "", "expected arrays and objects nested at most 64 deep"},
        BadInput{"RiderBesideItsBase", R"({"version": 1, "name": "t", "entities": [
                   {"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1},
                   {"name": "B", "shape": "cube", "size": 0.1, "position": [0.3, 0], "on": "A", "mass": 1}]})",
                 "/entities/1/position", "expected a centre over the top of 'A' (within 0.05 m of [0, 0])"},
        BadInput{"DaysOfWork", R"({"version": 1, "name": "t", "settings": {"timestep": 1e-5, "duration": 100,
                   "iterations": 10000, "max_substeps": 1000},
                   "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})",
                 "/settings/duration", "expected at most 1e+11 solver work"}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return p.param.name; });

// Every problem is reported, not only the first, each with its own line.
TEST(ScenarioLoader, ReportsAllProblemsWithTheirLines) {
  const std::string text = "{\"version\": 1, \"name\": \"t\",\n\"entities\": [\n"
                           "  {\"name\": \"A\", \"shape\": \"cube\", \"size\": -1, \"position\": [0, 0], \"mass\": 1},\n"
                           "  {\"name\": \"B\", \"shape\": \"cube\", \"size\": 0.1, \"position\": [0, 0], \"mass\": -2}\n]}";
  try {
    ScenarioLoader::loadText(text, "two.json");
    FAIL();
  } catch (const ScenarioError& e) {
    ASSERT_EQ(e.problems().size(), 2u);
    EXPECT_EQ(e.problems()[0].line, 3);
    EXPECT_EQ(e.problems()[1].line, 4);
    EXPECT_EQ(e.lines()[0].rfind("two.json:3:", 0), 0u) << e.lines()[0];
  }
}

// Counts are bounded, and a refusal names the bound.
TEST(ScenarioLoader, RefusesMoreEntitiesThanTheLimit) {
  std::string text = R"({"version": 1, "name": "t", "table": {"size": [1000, 1000]}, "entities": [)";
  for (std::size_t i = 0; i <= ScenarioLoader::kMaxEntities; ++i) {
    text += std::string(i ? "," : "") + R"({"name": "e)" + std::to_string(i) +
            R"(", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1})";
  }
  try {
    ScenarioLoader::loadText(text + "]}", "many.json");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.problems().front().path, "/entities");
    EXPECT_NE(e.problems().front().message.find("at most 10000 entities, got 10001"), std::string::npos);
  }
}

// The first problem's line and column, as the error prints them.
std::string placeOf(const std::string& text) {
  try {
    ScenarioLoader::loadText(text, "f.json");
  } catch (const ScenarioError& e) {
    const Problem& p = e.problems().front();
    return std::to_string(p.line) + ":" + std::to_string(p.column);
  }
  return "accepted";
}

// Places the scan once got wrong: after a byte order mark, a number too
// large that a comment before it also spells, a key written with escapes.
TEST(ScenarioLoader, LocatesThroughBomCommentsAndEscapedKeys) {
  const std::string one = R"({"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": -1})";
  EXPECT_EQ(placeOf("\xEF\xBB\xBF{\"version\": 1, \"name\": \"t\",\n\"entities\": [" + one + "]}"), "2:86");
  EXPECT_EQ(placeOf("// 1e400\n{\"version\": 1, \"name\": \"t\", \"gravity\": 1e400}"), "2:40");
  EXPECT_EQ(placeOf("{\"version\": 1, \"name\": \"t\",\n\"entities\": [{\"name\": \"A\", \"shape\": \"cube\",\n"
                    "\"size\": 0.1, \"position\": [0, 0],\n\"m\\u0061ss\": -1}]}"),
            "4:14");
}

// A value or key of any size is shown cut, on one line.
TEST(ScenarioLoader, ShowsLongValuesCut) {
  const std::string key(1 << 20, 'k');
  try {
    ScenarioLoader::loadText(entity(", \"" + key + "\": 1"), "long.json");
    FAIL();
  } catch (const ScenarioError& e) {
    for (const std::string& line : e.lines()) EXPECT_LT(line.size(), 1200u) << line.substr(0, 200);
  }
}

// Only a regular file is read: a directory or a device that never ends
// is refused before anything is read from it.
TEST(ScenarioLoader, ReadsOnlyRegularFiles) {
  for (const char* path : {"/", "/dev/zero"}) {
    try {
      ScenarioLoader::loadFile(path);
      FAIL() << path;
    } catch (const ScenarioError& e) {
      EXPECT_NE(e.problems().front().message.find("expected a regular file"), std::string::npos) << e.what();
    }
  }
}

TEST(ScenarioLoader, MissingFileIsAScenarioError) {
  EXPECT_THROW(ScenarioLoader::loadFile("no/such/file.json"), ScenarioError);
}

}  // namespace
}  // namespace tabletop
