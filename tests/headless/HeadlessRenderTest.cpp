// Headless frames of the report's examples (OSMesa, no display): the
// picture shows each entity in its colour where projecting its simulated
// position says it should be, a dropped entity below the table top, the
// arrow on the pushed side, and has the size asked for.

#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "draw/Camera.h"
#include "draw/SceneDrawing.h"
#include "headless/OsMesaContext.h"
#include "render/GlRenderer.h"
#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptPlayer.h"
#include "support/ColourProbe.h"
#include "support/TestName.h"

namespace tabletop {
namespace {

using test::Blob;
using test::findColour;

constexpr int kWidth = 640, kHeight = 480;
constexpr double kPi = 3.14159265358979323846;

const char* const kExamples[] = {"example1_single_cube", "example2_two_cubes", "example3_stacked_cubes",
                                 "example4_two_spheres"};

// One scenario played in bullet mode, rendered on demand.
class Scene {
 public:
  explicit Scene(const std::string& name)
      : scenario_(ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/" + name + ".json")),
        simulation_(buildSimulation(scenario_, scenario_.settings, SimulationMode::Bullet)),
        player_(scenario_, scenario_.settings, *simulation_) {
    player_.runDue();
  }

  void runTo(double t) {
    while (simulation_->time() < t - 1e-9 && !player_.finished()) player_.step();
  }
  void runToEnd() { player_.runToEnd(); }
  double time() const { return simulation_->time(); }

  Image render(const Camera& camera, bool arrow = true, int width = kWidth, int height = kHeight) {
    OsMesaContext context(width, height);
    GlRenderer renderer(context.gl());
    DrawOptions options;
    options.arrow = arrow;
    renderer.draw(makeDrawList(scenario_, simulation_->snapshot(), player_.arrow(), {}, options), camera, width,
                  height);
    return renderer.readPixels(width, height);
  }

  const Scenario& scenario() const { return scenario_; }
  std::vector<EntityState> states() const { return simulation_->snapshot(); }
  Camera front() const { return *Camera::named("front", scenario_.table); }
  // The report's direction, fitted to the table and every entity now.
  Camera fitted() const {
    Camera c = front();
    c.fit(sceneBounds(scenario_, states()), double(kWidth) / kHeight);
    return c;
  }

 private:
  Scenario scenario_;
  std::unique_ptr<Simulation> simulation_;
  ScriptPlayer player_;
};

// Half the entity's size, metres: a cube's half side, a sphere's radius.
double halfSize(const EntitySpec& e) { return e.geometry.halfExtents().x; }

// The same length in pixels at `depth` metres from the eye.
double pixels(double metres, double depth, const Camera& camera, int height = kHeight) {
  return metres * (0.5 * height / std::tan(0.5 * camera.fovyDegrees * kPi / 180.0)) / depth;
}

// Each entity's colour is found around its projected centre: enough pixels
// to be the entity (a tenth of its silhouette's bounding square) and
// centred on it within half its size.
void expectEntitiesWhereSimulated(Scene& scene, const std::string& when) {
  const Camera camera = scene.fitted();
  const Image image = scene.render(camera);
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    colours.insert(image.rgb[i] << 16 | image.rgb[i + 1] << 8 | image.rgb[i + 2]);
  }
  EXPECT_GT(colours.size(), 200u) << when << ": the image is (nearly) blank";

  const std::vector<EntityState> states = scene.states();
  for (std::size_t i = 0; i < states.size(); ++i) {
    const EntitySpec& spec = scene.scenario().entities[i];
    const auto p = camera.project(states[i].position, kWidth, kHeight);
    ASSERT_TRUE(p) << spec.name << " is behind the eye " << when;
    const double r = pixels(halfSize(spec), p->depth, camera);
    const int reach = static_cast<int>(1.6 * r) + 3;
    const Blob b = findColour(image, spec.colour, int(p->column) - reach, int(p->row) - reach,
                              int(p->column) + reach, int(p->row) + reach);
    EXPECT_GE(b.count, 0.4 * r * r) << spec.name << " " << when << ": too few pixels of its colour near ("
                                    << p->column << ", " << p->row << "), expected about " << 4 * r * r;
    EXPECT_LT(std::hypot(b.column - p->column, b.row - p->row), 0.5 * r + 3.0)
        << spec.name << " " << when << ": its colour's centre (" << b.column << ", " << b.row
        << ") is away from the projection (" << p->column << ", " << p->row << ")";
  }
}

class ReportExampleFrames : public ::testing::TestWithParam<const char*> {};

TEST_P(ReportExampleFrames, ShowEachEntityWhereItsSimulatedPositionProjects) {
  Scene scene(GetParam());
  expectEntitiesWhereSimulated(scene, "at t = 0");
  Scene ended(GetParam());
  ended.runToEnd();
  const double end = ended.time();
  scene.runTo(0.5 * end);
  expectEntitiesWhereSimulated(scene, "half way, at t = " + std::to_string(scene.time()));
  expectEntitiesWhereSimulated(ended, "at the end, t = " + std::to_string(end));
}

// Every pixel of a dropped entity lies below the line of the table top's
// front edge (projected, and extended beyond the table).
TEST_P(ReportExampleFrames, ShowDroppedEntitiesBelowTheTableTopLine) {
  Scene scene(GetParam());
  scene.runToEnd();
  const Camera camera = scene.fitted();
  const Image image = scene.render(camera);
  const TableSpec& t = scene.scenario().table;
  const auto a = camera.project({t.centreX - 0.5 * t.width, t.height, t.centreZ + 0.5 * t.depth}, kWidth, kHeight);
  const auto b = camera.project({t.centreX + 0.5 * t.width, t.height, t.centreZ + 0.5 * t.depth}, kWidth, kHeight);
  ASSERT_TRUE(a && b);
  const auto edgeRow = [&](double column) {
    return a->row + (b->row - a->row) * (column - a->column) / (b->column - a->column);
  };
  int dropped = 0;
  const std::vector<EntityState> states = scene.states();
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (states[i].status != EntityPositionStatus::FinishDropSimulation) continue;
    ++dropped;
    const EntitySpec& spec = scene.scenario().entities[i];
    const Blob all = findColour(image, spec.colour);
    const Blob above = findColour(image, spec.colour, 0, 0, kWidth, kHeight,
                                  [&](int column, int row) { return row <= edgeRow(column); });
    EXPECT_GT(all.count, 50) << spec.name << " is not in the picture";
    EXPECT_EQ(above.count, 0) << spec.name << " has " << above.count << " pixels above the table top's line";
  }
  EXPECT_GT(dropped, 0) << "every report example drops an entity";
}

INSTANTIATE_TEST_SUITE_P(HeadlessRender, ReportExampleFrames, ::testing::ValuesIn(kExamples),
                         [](const ::testing::TestParamInfo<const char*>& p) { return test::testName({p.param}); });

// The arrow (Push Direction On) is on the side of the face it pushes: for a
// push on the Left face, left of the entity, at its height; Off, it is gone.
TEST(HeadlessRender, ArrowIsOnThePushedSideAndGoneWhenOff) {
  for (const char* name : {"example2_two_cubes", "example4_two_spheres"}) {
    Scene scene(name);
    const Camera camera = scene.front();
    const EntityState pushed = scene.states().front();  // both examples push their first entity
    const EntitySpec& spec = scene.scenario().entities.front();
    const auto p = camera.project(pushed.position, kWidth, kHeight);
    ASSERT_TRUE(p);
    const double r = pixels(halfSize(spec), p->depth, camera);
    const Colour cyan = DrawArrow{}.colour;

    const Blob on = findColour(scene.render(camera, true), cyan);
    EXPECT_GT(on.count, 20) << name;
    EXPECT_LT(on.right, p->column - 0.5 * r) << name << ": the arrow reaches past the pushed (left) face";
    EXPECT_GT(on.left, p->column - 6.0 * r) << name << ": the arrow is far from its entity";
    EXPECT_NEAR(on.row, p->row, 0.5 * r + 2.0) << name << ": the arrow is not at the entity's height";

    EXPECT_EQ(findColour(scene.render(camera, false), cyan).count, 0) << name;
  }
}

TEST(HeadlessRender, ImageHasTheSizeAskedFor) {
  Scene scene("example1_single_cube");
  const Image image = scene.render(scene.front(), true, 321, 123);
  EXPECT_EQ(image.width, 321);
  EXPECT_EQ(image.height, 123);
  EXPECT_EQ(image.rgb.size(), 321u * 123u * 3u);
  EXPECT_THROW(OsMesaContext(0, 10), std::runtime_error);
}

// OpenGL's rows start at the bottom: the sky must come out at the top.
TEST(HeadlessRender, RowsAreFlippedSoTheSkyIsOnTop) {
  Scene scene("example1_single_cube");
  const Image image = scene.render(scene.front());
  const Colour top = image.at(kWidth / 2, 2), bottom = image.at(kWidth / 2, kHeight - 3);
  EXPECT_GT(top.b, top.r) << "the top row is not the pale blue sky";
  EXPECT_FALSE(top.r == bottom.r && top.g == bottom.g && top.b == bottom.b);
}

}  // namespace
}  // namespace tabletop
