#include "physics/collision/PairTable.h"

#include <iterator>

namespace tabletop {
namespace {

constexpr int kBox = BOX_SHAPE_PROXYTYPE;
constexpr int kCylinder = CYLINDER_SHAPE_PROXYTYPE;
constexpr int kHull = CONVEX_HULL_SHAPE_PROXYTYPE;  // a cone or truncated cone
constexpr int kSphere = SPHERE_SHAPE_PROXYTYPE;
constexpr int kPlane = STATIC_PLANE_PROXYTYPE;      // the floor
constexpr int kCompound = COMPOUND_SHAPE_PROXYTYPE; // the table: a box top and cylinder legs

using F = PointFinder;
using O = FaceFallback;
using U = PointUpkeep;

// Why each row is so: docs/bullet-corrections.md, under the algorithm's name.
// Solids on solids: a face's corners while one rests on the other's face;
// otherwise boxes are clipped (and then found afresh), cylinders get a whole
// face by perturbation. Solids on the floor: its nearest corners, found
// afresh. The table's children are dispatched through this table again, by
// Bullet's compound algorithm. A ball touches anything at one point.
constexpr PairRule kRules[] = {
    {kBox, kBox, F::kSolidOnFace, O::kConvexConvex, U::kFoundAfresh, true},
    {kBox, kCylinder, F::kSolidOnFace, O::kMultipointGjk, U::kKept, true},
    {kBox, kHull, F::kSolidOnFace, O::kConvexConvex, U::kKept, true},
    {kCylinder, kCylinder, F::kSolidOnFace, O::kMultipointGjk, U::kKept, true},
    {kCylinder, kHull, F::kSolidOnFace, O::kConvexConvex, U::kKept, true},
    {kHull, kHull, F::kSolidOnFace, O::kConvexConvex, U::kKept, true},
    {kBox, kPlane, F::kSolidOnPlane, O::kNone, U::kFoundAfresh, true},
    {kCylinder, kPlane, F::kSolidOnPlane, O::kNone, U::kFoundAfresh, true},
    {kHull, kPlane, F::kSolidOnPlane, O::kNone, U::kFoundAfresh, true},
    {kBox, kCompound, F::kBullet, O::kNone, U::kFoundAfresh, true},
    {kCylinder, kCompound, F::kBullet, O::kNone, U::kKept, true},
    {kHull, kCompound, F::kBullet, O::kNone, U::kKept, true},
    {kSphere, kSphere, F::kBullet, O::kNone, U::kDeepestOnly, false},
    {kSphere, kBox, F::kBullet, O::kNone, U::kDeepestOnly, true},
    {kSphere, kCylinder, F::kBullet, O::kNone, U::kDeepestOnly, true},
    {kSphere, kHull, F::kBullet, O::kNone, U::kDeepestOnly, true},
    {kSphere, kPlane, F::kBullet, O::kNone, U::kDeepestOnly, true},
    {kSphere, kCompound, F::kBullet, O::kNone, U::kDeepestOnly, true},
};

}  // namespace

const PairRule* pairRulesBegin() { return std::begin(kRules); }
const PairRule* pairRulesEnd() { return std::end(kRules); }

PairRule pairRule(int typeA, int typeB) {
  for (const PairRule& rule : kRules) {
    if ((rule.a == typeA && rule.b == typeB) || (rule.a == typeB && rule.b == typeA)) return rule;
  }
  return {typeA, typeB, F::kBullet, O::kNone, U::kKept, true};
}

}  // namespace tabletop
