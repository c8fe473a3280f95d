// --camera's forms, and the cameras they give, against the pinhole
// projection: what is asked to be in view is in the image.

#include <filesystem>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "draw/CameraChoice.h"
#include "draw/SceneDrawing.h"
#include "scenario/ScenarioLoader.h"

namespace tabletop {
namespace {

constexpr int kWidth = 960, kHeight = 720;

CameraChoice parsed(const std::string& text) {
  const auto c = CameraChoice::parse(text);
  EXPECT_TRUE(std::holds_alternative<CameraChoice>(c)) << text << ": " << std::get<std::string>(c);
  return std::get<CameraChoice>(c);
}

std::string refused(const std::string& text) {
  const auto c = CameraChoice::parse(text);
  EXPECT_TRUE(std::holds_alternative<std::string>(c)) << text;
  return std::holds_alternative<std::string>(c) ? std::get<std::string>(c) : "";
}

// The entities where the scene puts them at the start.
std::vector<EntityState> startStates(const Scenario& s) {
  std::vector<EntityState> states;
  for (const EntitySpec& e : s.entities) {
    EntityState state;
    state.name = e.name;
    state.position = e.position;
    states.push_back(state);
  }
  return states;
}

// Whether the ball is wholly inside the image (its centre and the points
// a radius away across and up the view), to `slack` pixels.
bool inView(const Camera& c, const Camera::Bound& b, double slack = 1e-6) {
  const Mat4 v = c.view();
  const Vec3 right{v.at(0, 0), v.at(0, 1), v.at(0, 2)}, up{v.at(1, 0), v.at(1, 1), v.at(1, 2)};
  for (const Vec3& p : {b.centre, b.centre + right * b.radius, b.centre - right * b.radius, b.centre + up * b.radius,
                        b.centre - up * b.radius}) {
    const auto px = c.project(p, kWidth, kHeight);
    if (!px || px->column < -slack || px->column > kWidth + slack || px->row < -slack || px->row > kHeight + slack) {
      return false;
    }
  }
  return true;
}

TEST(CameraChoice, ReadsEveryForm) {
  EXPECT_EQ(parsed("fit").kind, CameraChoice::Kind::Fit);
  for (const std::string& name : Camera::names()) {
    const CameraChoice c = parsed(name);
    EXPECT_EQ(c.kind, CameraChoice::Kind::Preset);
    EXPECT_EQ(c.name, name);
  }
  const CameraChoice f = parsed("follow:Big ball");
  EXPECT_EQ(f.kind, CameraChoice::Kind::Follow);
  EXPECT_EQ(f.name, "Big ball");
  const CameraChoice e = parsed("2,1.5,-3:0,0.75,1e-1");
  EXPECT_EQ(e.kind, CameraChoice::Kind::EyeTarget);
  EXPECT_EQ(e.eye, (Vec3{2, 1.5, -3}));
  EXPECT_EQ(e.target, (Vec3{0, 0.75, 0.1}));
}

TEST(CameraChoice, RefusesAnythingElseInOneLine) {
  for (const std::string& text : std::vector<std::string>{"", "Fit", "ceiling", "follow:", "1,2:3,4,5", "1,2,3:4,5,6,7", "1,2,3:4,5,x",
                                                      "nan,0,0:0,0,0", "inf,0,0:0,0,0", "1e5,0,0:0,0,0", "1,2,3:1,2,3", "1,2,3 :0,0,0",
                                                      "1,2,3:0,0,0\n"}) {
    const std::string why = refused(text);
    EXPECT_FALSE(why.empty()) << text;
    EXPECT_EQ(why.find('\n'), std::string::npos) << why;
  }
  EXPECT_NE(refused("1,2,3:1,2,3").find("same point"), std::string::npos);
}

// An eye and a target give a camera at that eye looking at that target:
// the target projects to the image's centre.
TEST(CameraChoice, EyeAndTargetPlaceTheCamera) {
  const Scenario scene = ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/example1_single_cube.json");
  for (const std::string text : {"2,1.5,3:0,0.75,0", "-1,0.2,-4:0.5,0.8,0.1", "0.3,5,0.2:0,0.75,0"}) {
    const CameraChoice choice = parsed(text);
    const Camera c = cameraFor(choice, scene, startStates(scene), SceneExtent{}, double(kWidth) / kHeight);
    EXPECT_LT((c.eye() - choice.eye).length(), 1e-9) << text;
    const auto centre = c.project(choice.target, kWidth, kHeight);
    ASSERT_TRUE(centre) << text;
    EXPECT_NEAR(centre->column, kWidth / 2.0, 1e-6) << text;
    EXPECT_NEAR(centre->row, kHeight / 2.0, 1e-6) << text;
  }
}

// Fit, the default, keeps the table and every entity of every shipped
// scene (the hard ones included: a 5 m cube, a 20-cube tower) in view;
// follow centres the entity with room around it.
TEST(CameraChoice, FitFramesEveryShippedSceneAndFollowCentresItsEntity) {
  int scenes = 0;
  for (const auto& f : std::filesystem::recursive_directory_iterator(std::string(TABLETOP_SOURCE_DIR) + "/scenarios")) {
    if (f.path().extension() != ".json") continue;
    const Scenario scene = ScenarioLoader::loadFile(f.path().string());
    const std::vector<EntityState> states = startStates(scene);
    const SceneExtent extent = SceneExtent::of(scene, states);
    const Camera fitted = cameraFor(parsed("fit"), scene, states, extent, double(kWidth) / kHeight);
    for (const Camera::Bound& b : sceneBounds(scene, states)) EXPECT_TRUE(inView(fitted, b)) << f.path();
    for (std::size_t i = 0; i < states.size(); ++i) {
      const Camera c = cameraFor(parsed("follow:" + scene.entities[i].name), scene, states, extent, 4.0 / 3.0);
      const auto centre = c.project(states[i].position, kWidth, kHeight);
      ASSERT_TRUE(centre);
      EXPECT_NEAR(centre->column, kWidth / 2.0, 1e-6);
      EXPECT_NEAR(centre->row, kHeight / 2.0, 1e-6);
      EXPECT_TRUE(inView(c, {states[i].position, scene.entities[i].geometry.boundingRadius()}));
    }
    ++scenes;
  }
  EXPECT_GE(scenes, 26);
}

TEST(CameraChoice, FollowMustNameAnEntityOfTheScene) {
  const Scenario scene = ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/example2_two_cubes.json");
  EXPECT_EQ(parsed("follow:A").problemWith(scene), "");
  EXPECT_NE(parsed("follow:C").problemWith(scene).find("no entity is named 'C'"), std::string::npos);
  EXPECT_EQ(parsed("fit").problemWith(scene), "");
  // forScene does both: the form, then the scene.
  EXPECT_TRUE(std::holds_alternative<CameraChoice>(CameraChoice::forScene("follow:A", scene)));
  const auto unknown = CameraChoice::forScene("follow:C", scene);
  ASSERT_TRUE(std::holds_alternative<std::string>(unknown));
  EXPECT_NE(std::get<std::string>(unknown).find("no entity is named 'C'"), std::string::npos);
  const auto malformed = CameraChoice::forScene("sideways", scene);
  ASSERT_TRUE(std::holds_alternative<std::string>(malformed));
  EXPECT_EQ(std::get<std::string>(malformed), std::get<std::string>(CameraChoice::parse("sideways")));
}

}  // namespace
}  // namespace tabletop
