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

// Every pair of Bullet's shape types, each cell its rule: the step asks for
// a manifold's rule in every part, and this answers without a search.
constexpr int kTypes = MAX_BROADPHASE_COLLISION_TYPES;
struct RuleGrid {
  PairRule cell[kTypes][kTypes];
};

constexpr PairRule unlisted(int a, int b) { return {a, b, F::kBullet, O::kNone, U::kKept, true}; }

constexpr RuleGrid makeGrid() {
  RuleGrid g{};
  for (int a = 0; a < kTypes; ++a) {
    for (int b = 0; b < kTypes; ++b) g.cell[a][b] = unlisted(a, b);
  }
  for (const PairRule& rule : kRules) {
    g.cell[rule.a][rule.b] = rule;
    g.cell[rule.b][rule.a] = rule;
  }
  return g;
}

constexpr RuleGrid kGrid = makeGrid();

}  // namespace

const PairRule* pairRulesBegin() { return std::begin(kRules); }
const PairRule* pairRulesEnd() { return std::end(kRules); }

PairRule pairRule(int typeA, int typeB) {
  if (typeA < 0 || typeB < 0 || typeA >= kTypes || typeB >= kTypes) return unlisted(typeA, typeB);
  return kGrid.cell[typeA][typeB];
}

}  // namespace tabletop
