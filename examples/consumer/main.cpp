// A scene built in code, no scenario file: a 0.1 m cube on the table is
// pushed with an impulse of 1 N s along +X, stepped until it rests, and
// its state printed. With the cube's friction 0.5 (the table's is neutral,
// 1, under Bullet's product) it should slide d = v0^2 / (2 mu g) = 1^2 / (2 * 0.5 * 9.81) = 0.1019 m.
#include <cstdio>

#include <tabletop/core/Arrow.h>
#include <tabletop/scenario/Scenario.h>
#include <tabletop/sim/SceneBuilder.h>

int main() {
  using namespace tabletop;
  Scenario scene;
  scene.name = "slide";

  EntitySpec cube;
  cube.name = "A";
  cube.geometry = ShapeGeometry::cube(0.1);
  cube.position = {-0.2, 0.0, 0.0};  // y comes from what it rests on
  cube.on = Support::table();
  cube.mass = 1.0;
  cube.material.friction = 0.5;
  scene.entities.push_back(cube);

  std::unique_ptr<Simulation> sim = buildSimulation(scene, scene.settings, SimulationMode::Bullet);
  Arrow arrow;
  arrow.entity = "A";
  arrow.angleDegrees = 0.0;
  sim->push(arrow, PushMagnitude{PushMagnitude::Kind::Impulse, 1.0});
  do sim->step();
  while (!sim->allAtRest() && sim->time() < 5.0);

  const EntityState a = sim->snapshot().front();
  std::printf("after %.3f s (%ld steps) A is at x = %.4f m, y = %.4f m: slid %.4f m (closed form 0.1019 m)\n",
              sim->time(), sim->steps(), a.position.x, a.position.y, a.position.x + 0.2);
  return 0;
}
