#include "physics/collision/ContactDispatcher.h"

#include "physics/shapes/ShapeKinds.h"

namespace tabletop {

ContactDispatcher::ContactDispatcher(btCollisionConfiguration* configuration)
    : btCollisionDispatcher(configuration) {
  setDispatcherFlags(getDispatcherFlags() & ~CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD);
  setNearCallback(&ContactDispatcher::nearCallback);
  // Bullet's default configuration makes every convex pair with one
  // create function; it is copied and given Bullet's multipoint defaults.
  const auto* convex = static_cast<const btConvexConvexAlgorithm::CreateFunc*>(
      configuration->getCollisionAlgorithmCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE));
  multipoint_ = std::make_unique<btConvexConvexAlgorithm::CreateFunc>(*convex);
  multipoint_->m_numPerturbationIterations = 3;
  multipoint_->m_minimumPointsPerturbationThreshold = 3;
  for (const int other : {BOX_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE}) {
    registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, other, multipoint_.get());
    registerCollisionCreateFunc(other, CYLINDER_SHAPE_PROXYTYPE, multipoint_.get());
  }
  // Cylinders and hulls on a box's face: as on the floor while they rest
  // on it, else the pair's algorithm above (for a hull, clipping).
  hullOnBox_ = std::make_unique<SolidOnFaceAlgorithm::CreateFunc>(
      configuration->getCollisionAlgorithmCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE));
  cylinderOnBox_ = std::make_unique<SolidOnFaceAlgorithm::CreateFunc>(multipoint_.get());
  registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, cylinderOnBox_.get());
  registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE, cylinderOnBox_.get());
  registerCollisionCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, hullOnBox_.get());
  registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE, hullOnBox_.get());
  // The same on a cylinder's and a cone's ends: a cylinder, a cone or a box
  // resting on a standing cylinder slid 1.2 mm long at 60 Hz and turned 0.9
  // degrees on Bullet's points, a stack of equal cylinders leaned at its
  // start, and a cube on a cone's top stood 0.4 mm aside.
  cylinderOnCylinder_ = std::make_unique<SolidOnFaceAlgorithm::CreateFunc>(multipoint_.get());
  registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE, cylinderOnCylinder_.get());
  hullOnCylinder_ = std::make_unique<SolidOnFaceAlgorithm::CreateFunc>(
      configuration->getCollisionAlgorithmCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE));
  registerCollisionCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE, hullOnCylinder_.get());
  registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE, hullOnCylinder_.get());
  hullOnHull_ = std::make_unique<SolidOnFaceAlgorithm::CreateFunc>(
      configuration->getCollisionAlgorithmCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE));
  registerCollisionCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE, hullOnHull_.get());
  // Two boxes likewise, else by polyhedral clipping. Bullet's box-box
  // detector reports only penetrating corners: a tilt of 1e-10 rad dropped
  // a corner and jolted a sliding cube (0.15-0.5 rad/s), 3-5 mm off its
  // slide; clipping (with SAT axes, Pipeline) reports nothing while the
  // faces are a hair apart, and a box sliding on a box on the floor, lifted
  // 0.4 nm by the solve, fell freely for a step.
  boxOnBox_ = std::make_unique<SolidOnFaceAlgorithm::CreateFunc>(
      configuration->getCollisionAlgorithmCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE));
  registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, boxOnBox_.get());
  // Boxes and hulls on the floor: every vertex near it, every step.
  for (const int solid : {BOX_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE}) {
    registerCollisionCreateFunc(solid, STATIC_PLANE_PROXYTYPE, &planeVertices_);
    registerCollisionCreateFunc(STATIC_PLANE_PROXYTYPE, solid, &planeVertices_);
  }
}

void ContactDispatcher::nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher,
                                     const btDispatcherInfo& info) {
  const auto* object0 = static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
  const auto* object1 = static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
  if (!dispatcher.needsCollision(object0, object1)) return;
  const btCollisionObjectWrapper wrap0(nullptr, object0->getCollisionShape(), object0, object0->getWorldTransform(),
                                       -1, -1);
  const btCollisionObjectWrapper wrap1(nullptr, object1->getCollisionShape(), object1, object1->getWorldTransform(),
                                       -1, -1);
  // The pair keeps its algorithm from step to step.
  if (pair.m_algorithm == nullptr) {
    pair.m_algorithm = dispatcher.findAlgorithm(&wrap0, &wrap1, nullptr, BT_CONTACT_POINT_ALGORITHMS);
  }
  if (pair.m_algorithm == nullptr) return;
  // Only a ContactDispatcher sets this callback.
  ContactResult result(&wrap0, &wrap1, static_cast<ContactDispatcher&>(dispatcher).found_);
  // Two spheres: Bullet's algorithm reports them only once they overlap,
  // unless asked for points this far apart. Every other pair is found up
  // to the breaking threshold ahead of touching, and an impact between
  // spheres is placed at its own time like any other (DynamicsWorld).
  if (isBall(*object0) && isBall(*object1)) {
    result.m_closestPointDistanceThreshold = gContactBreakingThreshold;
  }
  if (info.m_dispatchFunc == btDispatcherInfo::DISPATCH_DISCRETE) {
    pair.m_algorithm->processCollision(&wrap0, &wrap1, info, &result);
  } else {
    const btScalar impact = pair.m_algorithm->calculateTimeOfImpact(const_cast<btCollisionObject*>(object0),
                                                                    const_cast<btCollisionObject*>(object1), info,
                                                                    &result);
    if (impact < info.m_timeOfImpact) info.m_timeOfImpact = impact;
  }
}

}  // namespace tabletop
